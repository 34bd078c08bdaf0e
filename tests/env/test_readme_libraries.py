"""The "With MARL libraries" page's examples (``docs/libraries.md``) run as written, each in a fresh interpreter."""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.docs_sections import blocks, section

BLOCKS = blocks(section("libraries.md"), "python")


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
