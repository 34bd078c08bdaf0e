"""Plant the hand-written bugs that once went unnoticed, one at a time, and see which tests catch them.

Each bug is a small, plausible edit of one source file (a swapped filter term, VPI with
the wrong action's uncertainty, decision time charged from the wrong field or regardless
of the flag, the tasks column read before the step, results of a resumed sweep returned out of
job order; what counts as a finished job is the results store's, tested with it). For each one this script makes a
scratch copy (as ``mutation/run.py`` does), applies the edit, runs the tests that guard
that file and reports caught or missed, with the failing tests.

Usage::

    python mutation/planted.py                 # the tests of this checkout
    python mutation/planted.py --tests-from REV   # the tests of an older commit (before/after)
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run import _env, scratch_copy, tests_from


@dataclass(frozen=True)
class Bug:
    """One planted bug: replace ``old`` by ``new`` in ``path``, then run ``tests``."""

    name: str
    path: str
    old: str
    new: str
    tests: tuple[str, ...]


META_TESTS = ("tests/agents/test_meta.py", "tests/agents/test_meta_exact.py", "tests/agents/test_robots.py")
RUN_TESTS = ("tests/training/test_runner.py", "tests/training/test_run_clock.py", "tests/training/test_sweep_resume.py")

BUGS = (
    Bug(
        "entropy filter: weights swapped",
        "agents/meta/entropy.py",
        "(1.0 - self.rate) * p + self.rate * p_new",
        "self.rate * p + (1.0 - self.rate) * p_new",
        META_TESTS,
    ),
    Bug(
        "VPI: best action priced with the second best's sd",
        "agents/meta/vpi.py",
        "out[a1] = expected_gain(float(q[a2]) - q1, float(sd[a1]))",
        "out[a1] = expected_gain(float(q[a2]) - q1, float(sd[a2]))",
        META_TESTS,
    ),
    Bug(
        "clock charged with the measured planning time, not the decision time",
        "training/runner.py",
        "raw.charge_time(record.decision_time)",
        "raw.charge_time(record.planning_time)",
        RUN_TESTS,
    ),
    Bug(
        "charge_decision_time flag ignored",
        "training/runner.py",
        "if config.charge_decision_time and record.decision_time > 0:",
        "if record.decision_time > 0:",
        RUN_TESTS,
    ),
    Bug(
        "tasks column read before the step",
        "training/runner.py",
        '"tasks_solved": raw.tasks_solved,',
        '"tasks_solved": raw.tasks_solved - int(raw.rewards["robot"]),',
        RUN_TESTS,
    ),
    Bug(
        "results of a resumed sweep in completion order",
        "training/sweep.py",
        "return [found[key] for key in keys], stats",
        "return list(found.values()), stats",
        RUN_TESTS,
    ),
)


def check(bug: Bug, work: Path, tests_rev: str | None) -> tuple[bool, list[str]]:
    """Plant ``bug`` in a fresh copy; return (caught, failing tests)."""
    scratch = scratch_copy(work / bug.name.split(":")[0].replace(" ", "_")[:40])
    if tests_rev:
        tests_from(tests_rev, scratch)
    source = scratch / bug.path
    text = source.read_text()
    if text.count(bug.old) != 1:
        raise SystemExit(f"{bug.name}: the code to change is not found once in {bug.path} (update mutation/planted.py)")
    source.write_text(text.replace(bug.old, bug.new))
    tests = [t for t in bug.tests if (scratch / t).exists()]
    cmd = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-m", "not slow", "-rf", *tests]
    proc = subprocess.run(cmd, cwd=scratch, env=_env(scratch), capture_output=True, text=True)
    failed = [ln.split(" ")[1] for ln in proc.stdout.splitlines() if ln.startswith(("FAILED ", "ERROR "))]
    return proc.returncode != 0, failed


def main(argv: list[str] | None = None) -> int:
    """Plant every bug; exit 1 if any is missed."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tests-from", metavar="REV", help="use the tests of this commit")
    args = parser.parse_args(argv)
    missed = 0
    with tempfile.TemporaryDirectory(prefix="hg-marl-planted-") as tmp:
        for bug in BUGS:
            caught, failed = check(bug, Path(tmp), args.tests_from)
            missed += not caught
            print(f"{'caught' if caught else 'MISSED'}  {bug.name}  ({bug.path})")
            for name in failed:
                print(f"        {name}")
    print(f"\n{len(BUGS) - missed}/{len(BUGS)} planted bugs caught")
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())
