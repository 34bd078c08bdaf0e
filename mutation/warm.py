"""A warm test runner: the test stack imported once, a fresh forked child per test run.

Each mutant's test run used to be a new interpreter that imported pytest, hypothesis,
numpy, scipy, gymnasium and torch again before its first test; for the small pinned test
files that import was most of the run. This server imports those third-party libraries
once, drops anything of the package under test that they pulled in, and forks one child
per request. The child imports the package afresh from the scratch copy (so it sees the
mutant on disk), runs ``pytest.main`` and exits with pytest's status; the server kills
the child's whole process group when the request's time is up.

Protocol (one JSON object per line): the request ``{"args": [...], "timeout": s, "log":
path, "root": folder}`` on stdin, the answer ``{"code": n, "timeout": bool}`` on stdout.
The child's output goes to ``log``. ``root`` (optional) is the scratch copy to test: the
child works in it and imports from it (first on ``sys.path`` and on ``PYTHONPATH``, for
the subprocesses tests start), so one server serves every module a worker mutates, each
in its own copy, and the test stack is imported once per worker instead of once per
module.

Usage (by ``mutation/run.py``)::

    python mutation/warm.py hg_marl     # requests name their scratch folder as ``root``
"""

from __future__ import annotations

import contextlib
import gc
import importlib
import json
import os
import signal
import sys
import time
import traceback

PRELOAD = (
    "numpy",
    "scipy.sparse",
    "pytest",
    "_pytest.python",
    "hypothesis",
    "gymnasium",
    "pettingzoo",
    "torch",
    "stable_baselines3",
    "sb3_contrib",
)
"""Third-party libraries imported once by the server (each optional: a missing one is skipped)."""


def preload(package: str) -> None:
    """Import :data:`PRELOAD`, forget every module of ``package`` they imported, freeze the heap.

    A child must import ``package`` from disk, or it would test the code as it was when
    the server started instead of the mutant.
    """
    for name in PRELOAD:
        with contextlib.suppress(Exception):  # an optional library that is absent or broken is not preloaded
            importlib.import_module(name)
    for name in [m for m in sys.modules if m == package or m.startswith(package + ".")]:
        del sys.modules[name]
    gc.collect()
    # Every object alive now moves to a generation the collector never scans: a child's
    # collections (pytest runs two full ones at exit) then walk only what the child made,
    # not the whole of torch; a full collection over the preloaded heap took 0.14 s, most
    # of a small test file's run. The children also stop touching these objects' pages.
    gc.freeze()


def _child(args: list[str], log: str, root: str | None) -> None:
    """In the forked child: its own process group, in ``root``, output to ``log``, pytest, exit."""
    code = 99
    try:
        os.setsid()
        if root is not None:
            os.chdir(root)
            sys.path.insert(0, root)
            os.environ["PYTHONPATH"] = root
        out = os.open(log, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        os.dup2(out, 1)
        os.dup2(out, 2)
        import pytest

        code = int(pytest.main(args))
    except BaseException:  # whatever happens, the child must not return into the server's loop
        traceback.print_exc()
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)


def run_once(args: list[str], timeout: float, log: str, root: str | None = None) -> tuple[int, bool]:
    """Fork, run pytest with ``args`` in the child (in ``root``); ``(exit code, timed out)``."""
    pid = os.fork()
    if pid == 0:
        _child(args, log, root)
    deadline = time.monotonic() + timeout
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            return os.waitstatus_to_exitcode(status), False
        if time.monotonic() > deadline:
            try:
                os.killpg(pid, signal.SIGKILL)  # the child and anything it started
            except OSError:
                os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            return -signal.SIGKILL, True
        time.sleep(0.01)


def serve(package: str) -> None:
    """Answer requests from stdin until it closes."""
    preload(package)
    print(json.dumps({"ready": True}), flush=True)
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        root = request.get("root")
        code, timed_out = run_once(
            list(request["args"]), float(request["timeout"]), str(request["log"]), None if root is None else str(root)
        )
        print(json.dumps({"code": code, "timeout": timed_out}), flush=True)


if __name__ == "__main__":
    serve(sys.argv[1] if len(sys.argv) > 1 else "hg_marl")
