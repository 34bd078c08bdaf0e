"""No docstring quotes a measurement of one machine: those go stale, and live in the docs.

A docstring says why; timings, rates, speed-ups and memory measured on one machine go in
benchmark output and the docs' pages (``docs/benchmarks.md``, ``docs/batched.md``,
``docs/inputs.md``, ...) next to the command that measures them. This scans every
docstring (module, class, function and attribute strings) of ``hg_marl/``, ``agents/``
and ``training/`` with ``ast`` for the forms such figures take. Simulated seconds are not
machine measurements, so a bare ``s`` is not flagged; limits are written in binary units
(``MiB``, ``GiB``), measurements in decimal ones (``MB``, ``GB``). There is no allowed
exception: a figure a docstring needs is written as the constant it comes from.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("hg_marl", "agents", "training")

MEASUREMENT = re.compile(
    r"""
      \d[\d,.]*\s?(?:ms|µs|us)\b                                  # milli- and microseconds
    | \d[\d,.]*\s?[kM]?\s+(?:[\w-]+\s+)?(?:steps|states|turns|cycles|keys|frames|runs|decisions)/s\b  # rates
    | \d[\d,.]*\s?(?:KB|MB|GB|TB)\b                               # memory, decimal units
    | \d[\d,.]*\s?x\s+(?:faster|slower|the\b[^.]{0,40}?(?:speed|steps|throughput|rate))  # speed-ups
    | \bspeed-?up\s+of\s+\d
    | \d[\d,.]*\s?s\s+(?:to\s+(?:build|compile|enumerate|solve|load|plan)|of\s+(?:wall|CPU))\b  # wall timings
    | \b(?:took|takes)\s+\d[\d,.]*\s?(?:s|seconds|minutes)\b\s+(?:of\s+)?(?:wall|CPU)
    | \bload\s+(?:average\s+)?(?:of\s+)?\d                        # the machine's load at the time
    """,
    re.VERBOSE,
)
"""The forms a machine's measurement takes in prose."""


def docstrings(path: Path) -> Iterator[tuple[int, str]]:
    """Every bare string statement in a body (module, class, function and attribute docstrings)."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if not isinstance(body, list):
            continue
        for stmt in body:
            if (
                isinstance(stmt, ast.Expr)
                and isinstance(stmt.value, ast.Constant)
                and isinstance(stmt.value.value, str)
            ):
                yield stmt.lineno, stmt.value.value


def findings(path: Path, root: Path = ROOT) -> list[str]:
    """``path:line: the match`` for each measurement in the docstrings of ``path``."""
    rel = path.relative_to(root).as_posix()
    out = []
    for line, text in docstrings(path):
        for match in MEASUREMENT.finditer(text):
            at = line + text[: match.start()].count("\n")
            out.append(f"{rel}:{at}: {match.group(0)!r}")
    return out


def test_no_docstring_quotes_a_measurement() -> None:
    files = [p for package in PACKAGES for p in sorted((ROOT / package).rglob("*.py"))]
    assert len(files) > 100  # the scan reads the packages, not an empty folder
    found = [finding for path in files for finding in findings(path)]
    assert not found, "measurements belong in docs/ next to their command:\n" + "\n".join(found)


@pytest.mark.parametrize(
    "text",
    [
        "Built in 3.3-3.7 s to build on a laptop.",
        "then about 100x the live robots' steps/s",
        "each worker holds ~100 MB",
        "a cold plan takes 3-7 ms",
        "12x faster than before",
        "measured at a load of 8",
        "1,807,830 turns/s with 4,096 tables",
        "took 17.4 s of wall time",
    ],
)
def test_the_scan_finds_each_form(text: str) -> None:
    assert MEASUREMENT.search(text), text


@pytest.mark.parametrize(
    "text",
    [
        "A run of 1800 s of simulated time, switching at 20-180 s.",
        "A trace file may be at most 64 MiB.",
        "Speed is reported as env steps/s beside learner steps/s.",
        "Several trainings may share a 2-core machine, so one thread (default 1) each.",
        "The habit's constant charge (``CostModel.habit``).",
        "Percentile interval (2 x k) of the statistic.",
        "The longest run of unchanged robot turns is 10 turns.",
    ],
)
def test_the_scan_leaves_reasons_and_limits_alone(text: str) -> None:
    assert not MEASUREMENT.search(text), text


def test_a_planted_measurement_is_reported_with_its_line(tmp_path: Path) -> None:
    module = tmp_path / "planted.py"
    module.write_text('"""Fast.\n\nIt takes 2.5 s to build."""\n\n\ndef f():\n    """Why only."""\n', encoding="utf-8")
    assert findings(module, tmp_path) == ["planted.py:3: '2.5 s to build'"]
