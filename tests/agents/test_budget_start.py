"""Under the ``hg-marl`` script, time budgets count from the process's start, and a refusal leaves at once.

A person who typed ``--max-seconds 5`` waits from the moment the command started: the
interpreter's start-up and imports are part of it, and so is what the process does after
the refusal. Nothing here reads the wall clock against a bound that a slow machine could
miss: the start is moved by a known amount, or a sleep gives a lower bound.
"""

from __future__ import annotations

import re
import subprocess
import sys
import time
from pathlib import Path

import pytest

import hg_marl_start
from hg_marl.agents.models import budget as budget_module
from hg_marl.training.commands import common
from tests.cli_helpers import HANG_GUARD, error_lines, run_main


def test_the_process_start_lies_before_what_the_process_did() -> None:
    # A fresh interpreter that sleeps 0.3 s before asking: at least 0.3 s lie between.
    code = (
        "import time; time.sleep(0.3); from hg_marl.agents.models.budget import process_start; "
        "print(time.perf_counter() - process_start())"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=HANG_GUARD, check=True)
    assert float(out.stdout) >= 0.3


def test_the_process_start_lies_between_the_launch_and_now() -> None:
    # On the wall clock: not before the parent launched the process (two clock ticks of
    # rounding each way and the clocks' own resolution allowed), not after the moment it asks.
    code = (
        "import time; from hg_marl.agents.models.budget import process_start; "
        "start = process_start(); age = time.perf_counter() - start; now = time.time(); print(now - age, now)"
    )
    launched = time.time()
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=HANG_GUARD, check=True)
    start, now = (float(x) for x in out.stdout.split())
    assert launched - 0.05 <= start <= now


def test_the_process_start_is_not_after_now() -> None:
    assert budget_module.process_start() <= time.perf_counter()


@pytest.mark.parametrize(
    "args",
    [
        ["oracle", "--scenario", "paper2015", "--max-seconds", "50"],
        ["headroom", "--scenario", "paper2015", "--humans", "lazy", "--max-seconds", "50"],
    ],
)
def test_a_command_counts_its_budget_from_the_scripts_start(
    args: list[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    # The script "started" 100 s ago: a 50 s budget is spent before the work begins.
    monkeypatch.setitem(common.SCRIPT, "started", time.perf_counter() - 100.0)
    if args[0] == "headroom":
        args = [*args, "--out", str(tmp_path / "out")]
    code, _, err = run_main(args)
    (line,) = error_lines(err)
    assert code == 2
    assert "over its budget of 50 s of wall time (after 10" in line  # 100.x s
    assert "--max-seconds" in line
    assert not (tmp_path / "out").exists()


def test_called_in_process_a_command_counts_from_its_call() -> None:
    # A test process has run for a while: a command called in it starts its budget now.
    assert common.SCRIPT["started"] is None
    code, out, _ = run_main(["oracle", "--scenario", "paper2015", "--human", "no_handover", "--max-seconds", "600"])
    assert code == 0 and "optimal rate" in out


def _script(args: list[str], before: str = "pass") -> subprocess.CompletedProcess[str]:
    """``hg-marl ARGS`` through the console script, with an exit hook that prints ``teardown``."""
    code = (
        f"import atexit, sys, time; {before}; atexit.register(lambda: print('teardown')); "
        "from hg_marl.training.cli import script; sys.argv = ['hg-marl', *sys.argv[1:]]; script()"
    )
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, timeout=HANG_GUARD)


def test_the_script_counts_the_time_before_the_command() -> None:
    # 3 s pass in the process before the script runs: a 2 s budget is spent while it starts
    # up, and the start-up's timer refuses it in one line, without the exit hooks.
    proc = _script(["oracle", "--scenario", "paper2015", "--max-seconds", "2"], before="time.sleep(3)")
    assert proc.returncode == 2
    (line,) = error_lines(proc.stderr)
    assert line.startswith("error: --max-seconds 2: over the budget of wall time while still starting up")
    spent = float(re.search(r"\(after ([0-9.]+) s", line).group(1))  # type: ignore[union-attr]
    assert spent >= 3.0
    assert "teardown" not in proc.stdout


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["oracle", "--max-seconds", "5"], 5.0),
        (["oracle", "--max-seconds=0.5"], 0.5),
        (["headroom", "--max-seconds", "nan"], None),
        (["oracle", "--max-seconds", "-1"], None),
        (["oracle", "--max-seconds", "five"], None),
        (["oracle", "--max-seconds"], None),
        (["oracle", "--max-states", "5"], None),
        (["oracle", "--max-seconds", "10000000"], 1e7),
        (["oracle", "--max-seconds", "10000001"], None),
        (["oracle", "--max-seconds", "1e23"], None),
    ],
)
def test_the_startup_timer_reads_only_a_positive_finite_max_seconds(argv: list[str], expected: float | None) -> None:
    assert hg_marl_start.given_max_seconds(["hg-marl", *argv]) == expected


@pytest.mark.parametrize("command", ["oracle", "headroom"])
def test_a_budget_past_the_longest_timer_is_refused_in_one_line(
    command: str, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """1e23 s was past what ``setitimer`` holds: an ``OverflowError`` traceback. The longest
    budget is 1e7 s (about 16 weeks); past it, one line naming the option and the limit, exit 2."""
    from hg_marl.training.cli import main

    monkeypatch.setattr("sys.argv", ["hg-marl", command, "--max-seconds", "1e23"])
    with pytest.raises(SystemExit) as exit_info:
        main()
    assert exit_info.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["error: --max-seconds: expected a number <= 1e+07, got 1e+23"]


def test_a_library_budget_past_the_longest_timer_is_refused() -> None:
    from hg_marl.agents.models.budget import Budget
    from hg_marl.core.errors import ConfigError

    assert Budget(seconds=1e7).seconds == 1e7
    for seconds in (1e7 + 1, 1e23, float("inf"), float("nan"), 0.0, -1.0):
        with pytest.raises(ConfigError, match="--max-seconds"):
            Budget(seconds=seconds)


def test_the_startup_timer_is_armed_under_the_script_and_stopped_when_the_budget_takes_over(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import signal

    monkeypatch.setattr(signal, "signal", lambda *args: None)  # keep this process's own SIGALRM handler
    monkeypatch.setitem(common.SCRIPT, "started", None)
    hg_marl_start.arm_startup_budget(["hg-marl", "oracle", "--max-seconds", "600"])
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)  # in-process: nothing armed
    monkeypatch.setitem(common.SCRIPT, "started", time.perf_counter())
    hg_marl_start.arm_startup_budget(["hg-marl", "oracle", "--max-seconds", "600"])
    try:
        assert 0.0 < signal.getitimer(signal.ITIMER_REAL)[0] <= 600.0
        assert common.SCRIPT["startup_timer"] is True
        common.command_start()  # the command's budget reads the clock from here
        assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
        assert common.SCRIPT["startup_timer"] is False
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        common.SCRIPT["startup_timer"] = False


def test_the_script_leaves_without_teardown_after_a_budget_refusal() -> None:
    proc = _script(["oracle", "--scenario", "paper2015", "--max-states", "10"])
    assert proc.returncode == 2
    (line,) = error_lines(proc.stderr)
    assert "over its budget of max_states=10" in line
    assert "teardown" not in proc.stdout


def test_the_script_tears_down_as_usual_after_other_errors_and_success() -> None:
    bad = _script(["oracle", "--scenario", "paper2015", "--human", "switching"])
    assert bad.returncode == 2 and "teardown" in bad.stdout
    ok = _script(["oracle", "--scenario", "paper2015", "--human", "no_handover", "--max-states", "200000"])
    assert ok.returncode == 0 and "teardown" in ok.stdout and "optimal rate" in ok.stdout


def test_the_console_script_enters_through_the_module_that_imports_nothing_first() -> None:
    import tomllib

    pyproject = tomllib.loads((Path(__file__).parents[2] / "pyproject.toml").read_text())
    assert pyproject["project"]["scripts"]["hg-marl"] == "hg_marl_start:script"
    # a fresh interpreter importing the module loads no module outside the standard library
    code = (
        "import sys; before = set(sys.modules); import hg_marl_start; "
        "print(' '.join(sorted(set(sys.modules) - before)))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=HANG_GUARD, check=True)
    loaded = {name.split(".")[0] for name in out.stdout.split()} - {"hg_marl_start"}
    assert loaded <= set(sys.stdlib_module_names), loaded - set(sys.stdlib_module_names)


def test_the_budget_is_armed_before_the_package_is_imported() -> None:
    # The package's import made to take 30 s (a finder that sleeps when ``hg_marl`` is first
    # imported, then prints): a 2 s budget is refused during that import, so the sleep never
    # ends. Armed after the package's import, the refusal would come after the 30 s.
    finder = (
        "import sys, time\n"
        "class Slow:\n"
        "    def find_spec(self, name, path, target=None):\n"
        "        if name == 'hg_marl':\n"
        "            sys.meta_path.remove(self); time.sleep(30); print('slept', flush=True)\n"
        "sys.meta_path.insert(0, Slow())\n"
        "import hg_marl_start\n"
        "sys.argv = ['hg-marl', 'oracle', '--scenario', 'paper2015', '--max-seconds', '2']\n"
        "hg_marl_start.script()\n"
    )
    proc = subprocess.run([sys.executable, "-c", finder], capture_output=True, text=True, timeout=HANG_GUARD)
    assert proc.returncode == 2
    (line,) = error_lines(proc.stderr)
    assert line.startswith("error: --max-seconds 2: over the budget of wall time while still starting up")
    assert "slept" not in proc.stdout
