"""What ``mutation/planted.py`` counts as caught, and what a scratch copy holds.

A planted bug is caught by a test that fails with it and passes without it: a test that
fails in the scratch copy anyway (a script or page the copy lacks) caught nothing. Two
earlier rounds counted such a test (one that runs a benchmark script, when the copies held
no ``benchmarks/``), so both rules are pinned here.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.test_mutation_config import load_planted

ROOT = Path(__file__).resolve().parent.parent


def _done(stdout: str, code: int) -> subprocess.CompletedProcess[str]:
    return subprocess.CompletedProcess([], code, stdout=stdout, stderr="")


@pytest.mark.parametrize(
    ("without_bug", "caught", "tests"),
    [
        (_done("", 0), True, ["tests/a.py::t1", "tests/a.py::t2"]),  # both pass without the bug
        (_done("FAILED tests/a.py::t1 - x\n", 1), True, ["tests/a.py::t2"]),  # t1 fails anyway
        (_done("FAILED tests/a.py::t1 - x\nFAILED tests/a.py::t2 - x\n", 1), False, []),  # both fail anyway
    ],
)
def test_a_test_failing_without_the_bug_too_caught_nothing(
    without_bug: subprocess.CompletedProcess[str],
    caught: bool,
    tests: list[str],
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    planted = load_planted()
    source = tmp_path / "copy" / "pkg.py"

    def copy(dest: Path) -> Path:
        source.parent.mkdir(parents=True, exist_ok=True)
        source.write_text("x = 1\n")
        return source.parent

    runs: list[str] = []

    def pytest_run(scratch: Path, names: list[str]) -> subprocess.CompletedProcess[str]:
        runs.append(source.read_text())
        if len(runs) == 1:  # with the bug planted: both tests fail
            return _done("FAILED tests/a.py::t1 - x\nFAILED tests/a.py::t2 - y\n", 1)
        assert names == ["tests/a.py::t1", "tests/a.py::t2"]  # only the failures run again
        return without_bug

    monkeypatch.setattr(planted, "scratch_copy", copy)
    monkeypatch.setattr(planted, "_pytest", pytest_run)
    bug = planted.Bug("a bug", "pkg.py", "x = 1", "x = 2", ("tests/a.py",))
    assert planted.check(bug, tmp_path, None) == (caught, tests)
    assert runs == ["x = 2\n", "x = 1\n"]  # the second run without the bug


def test_a_scratch_copy_holds_every_tracked_top_level_entry_but_the_git_files() -> None:
    """A test may read any of them (a benchmark, an example, the CI script, the mutation
    configuration); a copy without one fails that test whether or not a bug is planted."""
    sys.path.insert(0, str(ROOT / "mutation"))
    try:
        import run
    finally:
        sys.path.remove(str(ROOT / "mutation"))
    listed = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=False)
    if listed.returncode != 0:
        pytest.skip("not a git checkout")
    top = {line.split("/")[0] for line in listed.stdout.splitlines()} - {".gitignore"}
    assert top <= set(run.COPIED), sorted(top - set(run.COPIED))
