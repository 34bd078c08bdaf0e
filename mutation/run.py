"""Mutation testing of the modules whose mistakes change results (cosmic-ray underneath).

For each module of ``mutation/modules.toml`` this script

1. copies the sources and tests into a scratch folder laid out as the installed package
   (``agents/`` and ``training/`` appear as ``hg_marl/agents`` and ``hg_marl/training``),
   so the mutated file is the one the tests import and the worktree is never touched;
2. runs the module's tests once unmutated (they must pass; their time sets the timeout), or,
   with ``--baseline-from``, reads both from the report of a test run of the same files
   (CI's test stage: ``pytest --report-log``, with the key ``--write-key`` wrote beside it);
3. lets cosmic-ray enumerate every mutant of the module, sets aside those that
   ``equivalent.toml`` justifies by their source line alone, draws a seeded sample among
   the rest (or keeps them all with ``--full``), marks the others skipped and executes
   the sample;
4. prints the mutation score per module (killed / (run - justified equivalents)) and
   every survivor with its diff, flagging those not in ``mutation/equivalent.toml``.

Exit status: 0 when every module's score is at least its ``fail_under``; 1 otherwise;
2 for a bad config or option (one line naming it).

Usage::

    python mutation/run.py                      # all modules, seeded sample (the CI stage)
    python mutation/run.py --full               # every mutant (long: see mutation/README.md)
    python mutation/run.py --changed main       # only modules whose file or tests differ from main
    python mutation/run.py --modules vpi,runner --sample 40
    python mutation/run.py --write-key artifacts/test-report.key      # then, after
    pytest --report-log artifacts/test-report.jsonl ...                  # the same files,
    python mutation/run.py --baseline-from artifacts/test-report.jsonl   # no baselines run
"""

from __future__ import annotations

import argparse
import contextlib
import difflib
import fnmatch
import functools
import hashlib
import itertools
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tarfile
import tempfile
import threading
import time
import tomllib
import traceback
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field
from io import BytesIO
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
CONFIG = ROOT / "mutation" / "modules.toml"
EQUIVALENT = ROOT / "mutation" / "equivalent.toml"
COPIED = (
    "hg_marl",
    "hg_marl_start.py",
    "agents",
    "training",
    "tests",
    "pyproject.toml",
    "populations",
    "studies",
    "docs",
    "README.md",
    "benchmarks",
    "examples",
    "mkdocs.yml",
    "mutation",
    ".ci",
    "Makefile",
    "noxfile.py",
)
"""What a scratch copy holds (sources, tests, pytest's configuration, and the data, pages and
scripts tests read: a test running a benchmark or an example fails in a copy without them)."""
IGNORED = ("__pycache__", "*.pyc", ".hypothesis", ".pytest_cache")
"""What a scratch copy leaves out (caches): patterns of file and folder names."""
PACKAGE_DIRS = {"agents": "hg_marl/agents", "training": "hg_marl/training"}
"""pyproject's package-dir: these folders install under hg_marl."""


class ConfigError(Exception):
    """Bad config or option: reported in one line, exit code 2."""


@dataclass(frozen=True)
class Module:
    """One entry of modules.toml."""

    key: str
    path: str
    tests: tuple[str, ...]
    sample: int
    fail_under: float


@dataclass(frozen=True)
class Equivalent:
    """A survivor judged equivalent: same behaviour, so no test can kill it.

    ``module`` is a key of modules.toml or ``*``; ``operator`` (a trailing ``*`` matches
    any suffix), ``removed`` and ``added`` (the changed line before and after, stripped)
    and ``pattern`` (a regular expression searched in the removed line) narrow the match.
    """

    module: str
    why: str
    operator: str = ""
    removed: str = ""
    added: str = ""
    pattern: str = ""

    def matches(self, module: str, operator: str, removed: str, added: str) -> bool:
        """Whether a survivor is this equivalent mutant."""
        op = self.operator
        return (
            self.module in ("*", module)
            and (not op or op == operator or (op.endswith("*") and operator.startswith(op[:-1])))
            and self.removed in ("", removed)
            and self.added in ("", added)
            and (not self.pattern or re.search(self.pattern, removed) is not None)
        )

    def judges_line(self, module: str, operator: str, line: str) -> bool:
        """Whether every mutant by ``operator`` of the source ``line`` is this equivalent.

        Only entries that do not depend on the mutated text (no ``added``) can say so
        before the mutant runs; the sample is drawn among the other mutants.
        """
        return not self.added and self.matches(module, operator, line.strip(), "")


@dataclass
class Outcome:
    """A module's result."""

    key: str
    path: str
    total: int = 0
    run: int = 0
    killed: int = 0
    timeouts: int = 0
    incompetent: int = 0
    equivalent: int = 0
    prejudged: int = 0
    """Mutants left out of the sample because ``equivalent.toml`` justifies them by their line alone."""
    survivors: list[dict[str, str | int]] = field(default_factory=list)
    timed_out: list[dict[str, str | int]] = field(default_factory=list)
    """Mutants whose tests ran out of time (counted as killed, as cosmic-ray does): each one costs
    the whole timeout, so a test that fails fast on it shortens the stage."""
    baseline_s: float = 0.0
    baseline_reported: bool = False
    """``baseline_s`` read from ``--baseline-from``'s report (the unmutated tests not run again)."""
    wall_s: float = 0.0
    error: str = ""

    @property
    def score(self) -> float:
        """Killed over the non-equivalent mutants run (1.0 when there were none)."""
        denominator = self.run - self.equivalent
        return self.killed / denominator if denominator > 0 else 1.0


def load_modules(path: Path = CONFIG) -> tuple[dict[str, Module], dict[str, float | int]]:
    """Read modules.toml, naming any bad field."""
    data = tomllib.loads(path.read_text())
    defaults = data.get("defaults", {})
    for name in ("sample", "seed", "fail_under", "target"):
        if name not in defaults:
            raise ConfigError(f"{path}: field 'defaults.{name}' is missing")
    modules: dict[str, Module] = {}
    for key, entry in data.get("modules", {}).items():
        where = f"{path}: field 'modules.{key}"
        if not isinstance(entry.get("path"), str):
            raise ConfigError(f"{where}.path': expected a file path")
        if not (ROOT / entry["path"]).is_file():
            raise ConfigError(f"{where}.path': no file {entry['path']!r} (renamed? update this entry)")
        tests = entry.get("tests")
        if not isinstance(tests, list) or not tests:
            raise ConfigError(f"{where}.tests': expected a non-empty list of test files")
        present = tuple(t for t in tests if (ROOT / t.split("::")[0]).exists())  # files or pytest node ids
        if not present:
            raise ConfigError(f"{where}.tests': none of {tests} exists (renamed? update this entry)")
        for missing in sorted(set(tests) - set(present)):
            print(f"warning: {where}.tests': {missing!r} does not exist, ignored", file=sys.stderr)
        modules[key] = Module(
            key,
            entry["path"],
            present,
            int(entry.get("sample", defaults["sample"])),
            float(entry.get("fail_under", defaults["fail_under"])),
        )
    return modules, defaults


def load_equivalents(path: Path = EQUIVALENT) -> list[Equivalent]:
    """The justified equivalent mutants (matched by module and changed line, not line number)."""
    data = tomllib.loads(path.read_text()) if path.exists() else {}
    out = []
    fields = ("module", "why", "operator", "removed", "added", "pattern")
    for i, entry in enumerate(data.get("equivalent", [])):
        for name in fields:
            if not isinstance(entry.get(name, ""), str) or (name in ("module", "why") and not entry.get(name)):
                raise ConfigError(f"{path}: field 'equivalent[{i}].{name}': expected a non-empty string")
        unknown = set(entry) - set(fields)
        if unknown:
            raise ConfigError(f"{path}: field 'equivalent[{i}].{sorted(unknown)[0]}': unknown (known: {fields})")
        out.append(Equivalent(**{k: str(entry.get(k, "")).strip() for k in fields}))
    return out


def changed_files(base: str) -> set[str]:
    """Files that differ from ``base`` (committed on this branch or not yet committed)."""
    cmd = ["git", "diff", "--name-only", f"{base}...HEAD"]
    committed = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=False)
    if committed.returncode != 0:
        raise ConfigError(f"--changed {base}: git diff failed: {committed.stderr.strip()}")
    cmd = ["git", "diff", "--name-only", "HEAD"]
    local = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=False)
    return set(committed.stdout.split()) | set(local.stdout.split())


def scratch_copy(dest: Path) -> Path:
    """Sources and tests laid out as installed, so ``import hg_marl.agents`` finds the copy."""
    ignore = shutil.ignore_patterns(*IGNORED)
    for name in COPIED:
        src = ROOT / name
        if not src.exists():  # an optional folder or page this checkout does not have
            continue
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=ignore, symlinks=True)
        else:
            shutil.copy2(src, dest / name)
    for folder, installed in PACKAGE_DIRS.items():
        if not (dest / installed).is_symlink():  # a copy made from a copy has its links already
            (dest / installed).symlink_to(Path("..") / folder)
    return dest


def _env(scratch: Path | None) -> dict[str, str]:
    """The tests' environment: imports from ``scratch`` (the warm server's children set their own)."""
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    if scratch is None:
        env.pop("PYTHONPATH", None)
    else:
        env["PYTHONPATH"] = str(scratch)
    env.setdefault("CI", "1")  # hypothesis replays the same examples (conftest's "ci" profile)
    return env


def _pytest_args(tests: tuple[str, ...]) -> list[str]:
    """pytest's arguments for a module's tests (the warm runner's request; the cold command's tail)."""
    return ["-x", "-q", "-p", "no:cacheprovider", "-m", "not slow", *tests]


def _test_command(tests: tuple[str, ...]) -> list[str]:
    return [sys.executable, "-m", "pytest", *_pytest_args(tests)]


def _check_layout(scratch: Path, modules: list[Module]) -> dict[str, str]:
    """The modules that the tests would not import from the scratch copy (else every mutant
    survives): ``{key: why}``, empty when each is found there.

    One interpreter imports them all: every scratch copy has the same layout, so the stage
    checks one copy once instead of starting an interpreter per module.
    """
    names: dict[str, str] = {}
    for m in modules:
        dotted = m.path.removesuffix(".py").replace("/", ".")
        for folder, installed in PACKAGE_DIRS.items():
            if dotted.startswith(folder + "."):
                dotted = installed.replace("/", ".") + dotted[len(folder) :]
        names[m.key] = dotted
    # import_module, not ``import a.b as m``: a package may re-export a function under its
    # module's name (agents/models/__init__.py: ``from .solve import solve``)
    code = (
        "import importlib, json, pathlib, sys\n"
        "found = {}\n"
        "for key, name in json.loads(sys.argv[1]).items():\n"
        "    try:\n"
        "        found[key] = str(pathlib.Path(importlib.import_module(name).__file__).resolve())\n"
        "    except Exception as exc:\n"
        "        found[key] = f'nowhere ({type(exc).__name__}: {exc})'\n"
        "print(json.dumps(found))\n"
    )
    cmd = [sys.executable, "-c", code, json.dumps(names)]
    proc = subprocess.run(cmd, cwd=scratch, env=_env(scratch), capture_output=True, text=True)
    lines = proc.stdout.strip().splitlines()
    found = json.loads(lines[-1]) if proc.returncode == 0 and lines else {}
    wrong = {}
    for key, dotted in names.items():
        where = str(found.get(key, f"nowhere: {proc.stderr[-300:]}"))
        if where.startswith("nowhere") or not Path(where).is_relative_to(scratch.resolve()):
            wrong[key] = f"{key}: {dotted} imports from {where}, not the scratch copy"
    return wrong


def _diff_lines(diff: str) -> tuple[str, str]:
    lines = [ln for ln in diff.splitlines() if ln[1:].strip()]  # changed blank lines carry no meaning
    removed = [ln[1:].strip() for ln in lines if ln.startswith("-") and not ln.startswith("---")]
    added = [ln[1:].strip() for ln in lines if ln.startswith("+") and not ln.startswith("+++")]
    return " / ".join(removed), " / ".join(added)


def tests_from(rev: str, dest: Path) -> None:
    """Replace a scratch copy's tests by those of commit ``rev`` (to score an older suite)."""
    archive = subprocess.run(["git", "archive", rev, "tests"], cwd=ROOT, capture_output=True, check=True).stdout
    shutil.rmtree(dest / "tests")
    with tarfile.open(fileobj=BytesIO(archive)) as tar:
        tar.extractall(dest, filter="data")


def content_key(root: Path = ROOT) -> str:
    """A hash of everything a scratch copy holds (paths and bytes): what a test run's report stands for."""
    digest = hashlib.sha256()
    for name in COPIED:
        src = root / name
        files = sorted(p for p in src.rglob("*") if p.is_file()) if src.is_dir() else [src] if src.exists() else []
        for f in files:
            rel = f.relative_to(root)
            if any(fnmatch.fnmatch(part, pattern) for part in rel.parts for pattern in IGNORED):
                continue
            data = f.read_bytes()
            digest.update(f"{rel.as_posix()}\0{len(data)}\0".encode())
            digest.update(data)
    return digest.hexdigest()


@dataclass(frozen=True)
class Baselines:
    """A test run's outcome and seconds per test (setup, call and teardown), from ``pytest --report-log``.

    The run must have tested the same files: its key (``--write-key``, written before it)
    must equal the files' key now, or the report is refused.
    """

    passed: dict[str, bool]
    seconds: dict[str, float]

    @classmethod
    def load(cls, report: Path) -> Baselines | None:
        """Read ``report`` if the key beside it (``report`` with the suffix ``.key``) is the files' key now.

        None, with a warning, where the files changed since (every module runs its baseline).
        """
        key_file = report.with_suffix(".key")
        if not report.is_file() or not key_file.is_file():
            raise ConfigError(f"--baseline-from: no report {report} with its key {key_file} (--write-key)")
        if key_file.read_text().strip() != content_key():
            print(f"warning: --baseline-from: {report} tested other files (its key differs)", file=sys.stderr)
            return None
        passed: dict[str, bool] = {}
        seconds: dict[str, float] = {}
        for number, line in enumerate(report.read_text().splitlines(), 1):
            try:
                entry = json.loads(line)
            except json.JSONDecodeError as exc:
                raise ConfigError(f"--baseline-from: {report}:{number}: not JSON ({exc.msg})") from exc
            if not isinstance(entry, dict) or entry.get("$report_type") != "TestReport":
                continue
            node, outcome, duration = entry.get("nodeid"), entry.get("outcome"), entry.get("duration")
            if not isinstance(node, str) or not isinstance(duration, int | float) or not math.isfinite(duration):
                raise ConfigError(f"--baseline-from: {report}:{number}: a test report without its nodeid or duration")
            ok = outcome in ("passed", "skipped")  # a test skipped at setup never reaches its call
            passed[node] = passed.get(node, True) and ok
            seconds[node] = seconds.get(node, 0.0) + float(duration)
        return cls(passed, seconds)

    def seconds_for(self, tests: tuple[str, ...]) -> float | None:
        """The seconds ``tests`` (files, folders or node ids) took if each of them passed, else None.

        None (the module's own baseline runs) where none of them is in the report or one failed.
        """
        chosen = [n for n in self.passed if any(n == t or n.startswith((t + "::", t + "[", t + "/")) for t in tests)]
        if not chosen or not all(self.passed[n] for n in chosen):
            return None
        return sum(self.seconds[n] for n in chosen)


def _prejudged(mutation: Any, lines: list[str], module: str, equivalents: list[Equivalent]) -> bool:
    """Whether a mutant is equivalent by its source line alone (see :meth:`Equivalent.judges_line`)."""
    row = mutation.start_pos[0] - 1
    line = lines[row] if 0 <= row < len(lines) else ""
    return any(e.judges_line(module, mutation.operator_name, line) for e in equivalents)


BASELINE_TIMEOUT = 3600.0
"""The unmutated tests' own limit (a module's mutants get 4x the time they took)."""


class WarmRunner:
    """The driver's side of ``mutation/warm.py``: one warm server, serving any scratch copy.

    The server imports the third-party test stack once and forks a child per test run,
    which works in the scratch copy the request names and imports the package afresh from
    it (so it sees the mutant on disk); :meth:`run` returns pytest's exit status, whether
    the time ran out, and the output. ``--cold`` runs every test in a new interpreter
    instead (``cosmic-ray exec``).
    """

    def __init__(self, env: dict[str, str]) -> None:
        self.proc = subprocess.Popen(
            [sys.executable, str(ROOT / "mutation" / "warm.py"), "hg_marl"],
            env=env,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
        )
        self._answer()  # {"ready": true}, once the test stack is imported

    def _answer(self) -> dict[str, Any]:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:  # a preloaded library may print; the protocol's lines are JSON objects
            try:
                data = json.loads(line)
            except json.JSONDecodeError:
                continue
            if isinstance(data, dict):
                return data
        raise RuntimeError(f"the warm test runner stopped (exit {self.proc.wait()})")

    def run(self, args: list[str], timeout: float, root: Path) -> tuple[int, bool, str]:
        """pytest with ``args`` in a forked child working in ``root``: ``(exit status, timed out, output)``."""
        assert self.proc.stdin is not None
        log = root / "warm-test-output.log"
        request = {"args": args, "timeout": timeout, "log": str(log), "root": str(root)}
        self.proc.stdin.write(json.dumps(request) + "\n")
        self.proc.stdin.flush()
        answer = self._answer()
        output = log.read_text(errors="replace") if log.exists() else ""
        return int(answer["code"]), bool(answer["timeout"]), output

    def __enter__(self) -> WarmRunner:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Stop the server."""
        if self.proc.stdin is not None:
            self.proc.stdin.close()
        try:
            self.proc.wait(timeout=60)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


class WarmPool:
    """One warm server per worker thread, kept for every module that thread mutates.

    Starting a server (importing torch, SB3 and the rest) and stopping it cost a few
    seconds; paid once per worker instead of once per module.
    """

    def __init__(self) -> None:
        self._local = threading.local()
        self._lock = threading.Lock()
        self._started: list[WarmRunner] = []

    def get(self) -> WarmRunner:
        """This thread's server, started on first use (or again if it stopped)."""
        runner: WarmRunner | None = getattr(self._local, "runner", None)
        if runner is None or runner.proc.poll() is not None:
            runner = WarmRunner(_env(None))
            self._local.runner = runner
            with self._lock:
                self._started.append(runner)
        return runner

    def __enter__(self) -> WarmPool:
        return self

    def __exit__(self, *exc: object) -> None:
        for runner in self._started:
            runner.close()


_INIT_LOCK = threading.Lock()


def _init_session(path: Path, session: Path) -> None:
    """``cosmic-ray init`` in this process: every mutant of ``path`` into a new session database.

    The command's own interpreter spent about a second importing cosmic-ray and its
    operators before the enumeration, once per module; the mutants are the same (the same
    operators, none with arguments, as the stage's configuration names none).
    """
    import cosmic_ray.commands
    from cosmic_ray.work_db import use_db

    with _INIT_LOCK, use_db(str(session)) as db:  # one at a time: the operators' plugins load on first use
        cosmic_ray.commands.init([path], db, {})


def _execute_warm(session: Path, scratch: Path, warm: WarmRunner, args: list[str], timeout: float) -> None:
    """``cosmic-ray exec`` with the warm runner: apply each pending mutant, test it, record the result."""
    import cosmic_ray.plugins
    from cosmic_ray.mutating import use_mutation
    from cosmic_ray.work_db import WorkDB, use_db
    from cosmic_ray.work_item import TestOutcome, WorkerOutcome, WorkResult

    with use_db(str(session), WorkDB.Mode.open) as db:
        for item in list(db.pending_work_items):
            (mutation,) = item.mutations  # run.py draws single mutants
            try:
                operator = cosmic_ray.plugins.get_operator(mutation.operator_name)(
                    **(getattr(mutation, "operator_args", None) or {})
                )
                path = scratch / mutation.module_path
                with use_mutation(path, operator, mutation.occurrence) as (original, mutated):
                    if mutated is None:
                        result = WorkResult(worker_outcome=WorkerOutcome.NO_TEST)
                    else:
                        code, timed_out, output = warm.run(args, timeout, scratch)
                        name = str(mutation.module_path)
                        diff = difflib.unified_diff(
                            original.splitlines(), mutated.splitlines(), f"a/{name}", f"b/{name}", lineterm=""
                        )
                        result = WorkResult(
                            output="timeout" if timed_out else output[-4000:],
                            diff="\n".join(diff),
                            test_outcome=TestOutcome.KILLED if code != 0 else TestOutcome.SURVIVED,
                            worker_outcome=WorkerOutcome.NORMAL,
                        )
            except Exception:  # as cosmic-ray: a mutant that cannot be applied is incompetent
                result = WorkResult(
                    output=traceback.format_exc(),
                    test_outcome=TestOutcome.INCOMPETENT,
                    worker_outcome=WorkerOutcome.EXCEPTION,
                )
            db.set_result(item.job_id, result)


@contextlib.contextmanager
def _warm_runner(pool: WarmPool | None, cold: bool) -> Iterator[WarmRunner | None]:
    """The pool's server for this thread (left running), a server of its own, or none (``cold``)."""
    if cold:
        yield None
    elif pool is not None:
        yield pool.get()
    else:
        with WarmRunner(_env(None)) as warm:
            yield warm


def run_module(
    module: Module,
    sample: int | None,
    seed: int,
    equivalents: list[Equivalent],
    work: Path,
    rev: str | None = None,
    cold: bool = False,
    pool: WarmPool | None = None,
    baselines: Baselines | None = None,
) -> Outcome:
    """Baseline, enumerate, sample, execute and score one module (its layout checked by the caller).

    ``cold``: run each mutant's tests in a new interpreter through ``cosmic-ray exec``
    (the reference the warm runner is checked against) instead of :class:`WarmRunner`.
    ``pool``: the warm servers to use (one is started and stopped for this module without it).
    ``baselines``: a report of the unmutated tests (their pass and time); a module whose
    tests are not all in it as passed runs its own baseline.
    """
    from cosmic_ray.work_db import WorkDB, use_db
    from cosmic_ray.work_item import TestOutcome, WorkerOutcome, WorkResult

    out = Outcome(module.key, module.path)
    start = time.perf_counter()
    scratch = scratch_copy(work / module.key)
    if rev:
        tests_from(rev, scratch)
        kept = tuple(t for t in module.tests if (scratch / t.split("::")[0]).exists())
        module = Module(module.key, module.path, kept, 0, 0.0)
    env = _env(scratch)
    command = shlex.join(_test_command(module.tests))  # cosmic-ray runs shlex.split(command)
    args = _pytest_args(module.tests)
    reported = None if baselines is None or rev else baselines.seconds_for(module.tests)
    with _warm_runner(pool, cold) as warm:
        t0 = time.perf_counter()
        if reported is not None:
            code, output = 0, ""
        elif warm is not None:
            code, _, output = warm.run(args, BASELINE_TIMEOUT, scratch)
        else:
            base = subprocess.run(shlex.split(command), cwd=scratch, env=env, capture_output=True, text=True)
            code, output = base.returncode, base.stdout
        out.baseline_s = time.perf_counter() - t0 if reported is None else reported
        out.baseline_reported = reported is not None
        if code != 0:
            out.error = f"tests fail before mutation:\n{output[-2000:]}"
            return out
        timeout = max(30.0, 4.0 * out.baseline_s)
        config = scratch / "cosmic-ray.toml"
        config.write_text(
            "[cosmic-ray]\n"
            f"module-path = {json.dumps(module.path)}\n"
            f"timeout = {timeout:.0f}\n"
            "excluded-modules = []\n"
            f"test-command = {json.dumps(command)}\n"
            '[cosmic-ray.distributor]\nname = "local"\n'
        )
        session = scratch / "session.sqlite"
        cosmic = [sys.executable, "-m", "cosmic_ray.cli"]
        _init_session(scratch / module.path, session)
        with use_db(str(session), WorkDB.Mode.open) as db:
            every = sorted(
                db.work_items, key=lambda w: [(m.start_pos, m.operator_name, m.occurrence) for m in w.mutations]
            )
            out.total = len(every)
            lines = (scratch / module.path).read_text().splitlines()
            items = [w for w in every if not _prejudged(w.mutations[0], lines, module.key, equivalents)]
            out.prejudged = out.total - len(items)
            keep = len(items) if sample is None else min(sample, len(items))
            chosen = {items[i].job_id for i in np.random.default_rng(seed).choice(len(items), size=keep, replace=False)}
            skipped = [w.job_id for w in every if w.job_id not in chosen]
            if skipped:
                skip = WorkResult(output="not in sample", worker_outcome=WorkerOutcome.SKIPPED)
                db.set_multiple_results(skipped, skip)
        if warm is not None:
            _execute_warm(session, scratch, warm, args, timeout)
        else:
            subprocess.run([*cosmic, "exec", str(config), str(session)], cwd=scratch, env=env, check=True)
        with use_db(str(session), WorkDB.Mode.open) as db:
            for item, result in db.completed_work_items:
                if result.worker_outcome == WorkerOutcome.SKIPPED:
                    continue
                out.run += 1
                mutation = item.mutations[0]
                removed, added = _diff_lines(result.diff or "")
                op = mutation.operator_name
                where: dict[str, str | int] = {
                    "line": mutation.start_pos[0],
                    "operator": op,
                    "removed": removed,
                    "added": added,
                }
                if result.output == "timeout":  # cosmic-ray counts a timed-out test run as killed
                    out.timeouts += 1
                    out.timed_out.append(where)
                if result.test_outcome == TestOutcome.INCOMPETENT:  # the mutant cannot even be imported
                    out.incompetent += 1
                if result.worker_outcome != WorkerOutcome.NORMAL or result.is_killed:
                    out.killed += 1
                    continue
                why = next((e.why for e in equivalents if e.matches(module.key, op, removed, added)), "")
                out.equivalent += bool(why)
                out.survivors.append({**where, "equivalent": why})
        out.survivors.sort(key=lambda s: int(s["line"]))
        out.wall_s = time.perf_counter() - start
        return out


def report(outcomes: list[Outcome], target: float) -> None:
    """The score table, then every survivor (justified equivalents marked)."""
    head = (
        f"{'module':<18} {'file':<32} {'mutants':>7} {'pre-eq':>6} {'run':>4} {'killed':>6} {'t/o':>4} {'inc':>4} "
        f"{'equiv':>5}"
    )
    print(f"\n{head} {'score':>6}  time")
    for o in outcomes:
        if o.error:
            print(f"{o.key:<18} {o.path:<32} ERROR: {o.error.splitlines()[0]}")
            continue
        flag = "" if o.score >= target else f"  (< target {target:.0%})"
        print(
            f"{o.key:<18} {o.path:<32} {o.total:>7} {o.prejudged:>6} {o.run:>4} {o.killed:>6} {o.timeouts:>4} "
            f"{o.incompetent:>4} {o.equivalent:>5} "
            f"{o.score:>6.1%}  {o.wall_s:5.0f}s{flag}"
        )
    for o in outcomes:
        listed = [(s, f"equivalent: {s['equivalent']}" if s["equivalent"] else "SURVIVED") for s in o.survivors]
        for s, tag in [*listed, *((s, "killed by the timeout") for s in o.timed_out)]:
            print(f"\n{o.path}:{s['line']} [{s['operator']}] {tag}\n  - {s['removed']}\n  + {s['added']}")
        if o.error:
            print(f"\n{o.key}: {o.error}")


def rescore(path: Path, equivalents: list[Equivalent], target: float) -> int:
    """Report a saved run again with the current list of equivalent mutants."""
    outcomes = []
    for data in json.loads(path.read_text()):
        data.pop("score", None)
        o = Outcome(**data)
        for s in o.survivors:
            s["removed"], s["added"] = (str(s[k]).removesuffix(" / ").strip() for k in ("removed", "added"))
            key = (o.key, str(s["operator"]), str(s["removed"]), str(s["added"]))
            s["equivalent"] = next((e.why for e in equivalents if e.matches(*key)), "")
        o.equivalent = sum(bool(s["equivalent"]) for s in o.survivors)
        outcomes.append(o)
    report(outcomes, target)
    return 0


def _progress(finished: Iterator[int], total: int, module: Module, future: Any) -> None:
    """One line when a module's scoring ends (its score, or that it failed), with the count so far."""
    done = next(finished)
    error = future.exception()
    if error is None:
        o = future.result()
        what = f"ERROR {o.error.splitlines()[0]}" if o.error else f"{o.killed}/{o.run} killed, {o.score:.0%}"
        print(f"[{done}/{total}] {module.key}: {what} in {o.wall_s:.0f}s", flush=True)
    else:
        print(f"[{done}/{total}] {module.key}: ERROR {type(error).__name__}: {error}", flush=True)


def main(argv: list[str] | None = None) -> int:
    """Parse options, run the modules (``--jobs`` at a time) and report."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--modules", help="comma-separated keys of modules.toml (default: all)")
    parser.add_argument("--changed", metavar="BASE", help="only modules whose file or tests differ from BASE")
    parser.add_argument("--sample", type=int, help="mutants per module (default: modules.toml)")
    parser.add_argument("--full", action="store_true", help="every mutant of every selected module")
    parser.add_argument("--seed", type=int, help="seed of the sample (default: modules.toml)")
    parser.add_argument("--jobs", type=int, default=2, help="modules mutated at once (default 2)")
    parser.add_argument("--json", type=Path, help="also write the results here")
    parser.add_argument("--keep", action="store_true", help="keep the scratch copies (printed)")
    parser.add_argument(
        "--cold", action="store_true", help="a new interpreter per test run (cosmic-ray exec), not the warm runner"
    )
    parser.add_argument("--tests-from", metavar="REV", help="score the tests of commit REV (e.g. to compare)")
    parser.add_argument("--list", action="store_true", help="print the selected modules and their tests, run nothing")
    parser.add_argument("--rescore", type=Path, metavar="JSON", help="re-apply equivalent.toml to a --json file")
    parser.add_argument(
        "--baseline-from",
        type=Path,
        metavar="REPORT",
        help="pytest --report-log of the same files (key: REPORT with suffix .key): no unmutated runs",
    )
    parser.add_argument("--write-key", type=Path, metavar="FILE", help="write the files' key for --baseline-from, exit")
    args = parser.parse_args(argv)
    try:
        modules, defaults = load_modules()
        equivalents = load_equivalents()
        selected = list(modules.values())
        if args.modules:
            names = [n.strip() for n in args.modules.split(",") if n.strip()]
            unknown = [n for n in names if n not in modules]
            if unknown:
                raise ConfigError(f"--modules: unknown {unknown} (known: {', '.join(modules)})")
            selected = [modules[n] for n in names]
        if args.changed:
            touched = changed_files(args.changed)
            selected = [m for m in selected if m.path in touched or any(t in touched for t in m.tests)]
        if args.sample is not None and args.sample < 1:
            raise ConfigError(f"--sample: expected a positive number, got {args.sample}")
        if args.jobs < 1:
            raise ConfigError(f"--jobs: expected a positive number, got {args.jobs}")
        if args.write_key:
            if not args.write_key.parent.is_dir():
                raise ConfigError(f"--write-key: no folder {args.write_key.parent}")
            partial = args.write_key.with_name(args.write_key.name + ".partial")
            partial.write_text(content_key() + "\n")
            partial.replace(args.write_key)  # atomic: a reader sees the whole key or none
            return 0
        baselines = Baselines.load(args.baseline_from) if args.baseline_from else None
    except (ConfigError, tomllib.TOMLDecodeError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.rescore:
        return rescore(args.rescore, equivalents, float(defaults["target"]))
    if args.list:
        for m in selected:
            print(f"{m.key:<18} {m.path:<32} sample {m.sample:<3} tests: {' '.join(m.tests)}")
        return 0
    if not selected:
        print("no module selected (nothing to mutate)")
        return 0
    seed = int(args.seed if args.seed is not None else defaults["seed"])
    work = Path(tempfile.mkdtemp(prefix="hg-marl-mutation-"))
    start = time.perf_counter()
    try:
        layout = scratch_copy(work / "_layout")  # every module's copy is laid out alike: one check for all
        wrong = _check_layout(layout, selected)
        shutil.rmtree(layout)
        runnable = [m for m in selected if m.key not in wrong]
        with WarmPool() as servers, ThreadPoolExecutor(max_workers=args.jobs) as pool:
            futures = {
                m.key: pool.submit(
                    run_module,
                    m,
                    None if args.full else (args.sample or m.sample),
                    seed,
                    equivalents,
                    work,
                    args.tests_from,
                    args.cold,
                    servers,
                    baselines,
                )
                for m in runnable
            }
            finished = itertools.count(1)
            for m in runnable:  # a line per module as it ends: long runs show progress
                futures[m.key].add_done_callback(functools.partial(_progress, finished, len(runnable), m))
            outcomes = []
            for m in selected:
                if m.key in wrong:
                    outcomes.append(Outcome(m.key, m.path, error=f"RuntimeError: {wrong[m.key]}"))
                    continue
                try:
                    outcomes.append(futures[m.key].result())
                except Exception as exc:  # one module's failure is reported, not the end of the stage
                    outcomes.append(Outcome(m.key, m.path, error=f"{type(exc).__name__}: {exc}"))
    finally:
        if args.keep:
            print(f"scratch copies kept in {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)
    report(outcomes, float(defaults["target"]))
    print(f"\nwall time {time.perf_counter() - start:.0f}s, seed {seed}, {'all mutants' if args.full else 'sample'}")
    if args.json:
        args.json.write_text(json.dumps([{**asdict(o), "score": o.score} for o in outcomes], indent=1))
    failed = [o for o in outcomes if o.error or o.score < modules[o.key].fail_under]
    for o in failed:
        print(f"FAIL {o.key}: {o.error.splitlines()[0] if o.error else f'score {o.score:.1%} < fail_under'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
