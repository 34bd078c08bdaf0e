"""The README's "With MARL libraries" examples run as written, each in a fresh interpreter."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "README.md"


def section_blocks(title: str) -> list[str]:
    text = README.read_text()
    start = text.index(f"## {title}\n")
    end = text.find("\n## ", start + 1)
    return re.findall(r"```python\n(.*?)```", text[start : end if end > 0 else None], flags=re.S)


BLOCKS = section_blocks("With MARL libraries")


def test_the_section_has_examples() -> None:
    assert len(BLOCKS) == 2


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_block_runs(index: int) -> None:
    out = subprocess.run(
        [sys.executable, "-c", BLOCKS[index]], capture_output=True, text=True, timeout=600, check=False
    )
    assert out.returncode == 0, out.stderr


def test_printed_shapes_are_the_ones_the_readme_states() -> None:
    out = subprocess.run([sys.executable, "-c", BLOCKS[1]], capture_output=True, text=True, timeout=600, check=True)
    assert out.stdout.strip() == "(26,) (31,)"  # 24 facts + 2 agent-id entries; the human has 31 actions
