"""The README's "Using it" blocks, the quick rows of its command table and ``docs/using.md`` run as written.

The other pages test their own examples (``tests/env/test_readme_libraries.py``,
``tests/play/test_readme_play.py``, the quick-look study in
``tests/training/test_evaluate.py``, ...; ``tests/docs_sections.py`` finds them); the long
commands of the table (``reproduce``, ``train``, ``compare``) are run by the slow and sb3 tests.
"""

from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from tests.docs_sections import blocks, section

QUICK = ("hg-marl run ", "hg-marl plan ", "hg-marl oracle ")
"""Command-table rows that finish in seconds; the test runs each as written (options in brackets dropped)."""


def quick_commands() -> list[str]:
    rows = re.findall(r"^\| `(hg-marl [^`]*)` \|", section("README.md", "Commands"), flags=re.M)
    return [re.sub(r"\s*\[[^\]]*\]", "", row) for row in rows if row.startswith(QUICK) and "..." not in row]


README_BLOCKS = blocks(section("README.md", "Using it"), "python")
PAGE_BLOCKS = blocks(section("using.md"), "python")
BLOCKS = README_BLOCKS + PAGE_BLOCKS


def test_the_section_has_its_examples() -> None:
    assert len(README_BLOCKS) == 2 and len(PAGE_BLOCKS) == 1
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
