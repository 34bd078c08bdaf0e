"""The README's "Using it" section runs as written: its Python blocks and the quick rows of its command table.

The other sections test their own examples (``tests/env/test_readme_libraries.py``,
``tests/play/test_readme_play.py``, the quick-look study in
``tests/training/test_evaluate.py``); the long commands of the table (``reproduce``,
``train``, ``compare``) are run by the slow and sb3 tests.
"""

from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
QUICK = ("hg-marl run ", "hg-marl plan ", "hg-marl oracle ")
"""Command-table rows that finish in seconds; the test runs each as written (options in brackets dropped)."""


def section(title: str) -> str:
    text = README.read_text()
    start = text.index(f"## {title}\n")
    return text[start : text.index("\n## ", start + 1)]


def quick_commands() -> list[str]:
    rows = re.findall(r"^\| `(hg-marl [^`]*)` \|", section("Using it"), flags=re.M)
    return [re.sub(r"\s*\[[^\]]*\]", "", row) for row in rows if row.startswith(QUICK) and "..." not in row]


BLOCKS = re.findall(r"```python\n(.*?)```", section("Using it"), flags=re.S)


def test_the_section_has_its_examples() -> None:
    assert len(BLOCKS) == 2
    assert [c.split()[1] for c in quick_commands()] == ["run", "plan", "oracle"]


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_python_block_runs(index: int, tmp_path: Path) -> None:
    out = subprocess.run(
        [sys.executable, "-c", BLOCKS[index]], capture_output=True, text=True, timeout=600, cwd=tmp_path, check=False
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip(), "each block prints what it shows"


@pytest.mark.parametrize("command", quick_commands())
def test_readme_command_runs(command: str, tmp_path: Path) -> None:
    hg_marl = Path(sys.executable).with_name("hg-marl")
    argv = [str(hg_marl) if hg_marl.exists() else "hg-marl", *shlex.split(command)[1:]]
    out = subprocess.run(argv, capture_output=True, text=True, timeout=600, cwd=tmp_path, check=False)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip()
