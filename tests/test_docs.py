"""The README stays a one-hour read, the docs site lists every page, and every Python block runs.

``make docs`` (a CI stage) builds the site with ``mkdocs build --strict``; these checks need
no MkDocs, so ``make test`` catches a page left out of the nav or a README grown long.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from tests.docs_sections import DOCS, ROOT, blocks, section

README_MAX_LINES = 300
"""Issue 27: a README of at most 300 lines."""

SETUP_COMMANDS = ("make reproduce", "make test")
"""The two set-up commands, which must sit in the README's first 20 lines."""

DEDICATED = {
    "using.md": "tests/test_readme_using.py",
    "libraries.md": "tests/env/test_readme_libraries.py",
    "batched.md": "tests/env/test_readme_batched.py",
    "play.md": "tests/play/test_readme_play.py",
    "populations.md": "tests/training/test_readme_population.py",
    "hard-layouts.md": "tests/training/test_readme_headroom.py",
}
"""Pages whose blocks a test of their own runs (with the checks of what they print); every
other page's Python blocks run here, each in a fresh interpreter."""


def test_readme_is_short_and_opens_with_the_two_commands() -> None:
    lines = section("README.md").splitlines()
    assert len(lines) <= README_MAX_LINES, f"README.md has {len(lines)} lines (at most {README_MAX_LINES})"
    head = "\n".join(lines[:20])
    (setup,) = blocks(head + "\n", "bash")  # the commands are a block a reader can copy
    assert [line.split("#")[0].strip() for line in setup.strip().splitlines()] == list(SETUP_COMMANDS)


def test_the_two_commands_are_make_targets() -> None:
    makefile = (ROOT / "Makefile").read_text()
    for command in SETUP_COMMANDS:
        target = command.split()[1]
        assert re.search(rf"^{target}:", makefile, flags=re.M), target


def _nav_pages(entries: list[object]) -> list[str]:
    pages: list[str] = []
    for entry in entries:
        value = next(iter(entry.values())) if isinstance(entry, dict) else entry
        pages += _nav_pages(value) if isinstance(value, list) else [str(value)]
    return pages


def test_mkdocs_is_strict_and_its_nav_lists_every_page_once() -> None:
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text())
    assert config["strict"] is True and config["docs_dir"] == "docs"
    nav = _nav_pages(config["nav"])
    assert len(nav) == len(set(nav)), nav
    assert sorted(nav) == sorted(p.name for p in DOCS.glob("*.md"))
    assert "task.md" in nav and nav[0] == "index.md"


def test_readme_links_every_page_that_exists() -> None:
    readme = section("README.md")
    for target in re.findall(r"\]\((docs/[^)#]+)", readme):
        assert (ROOT / target).is_file(), target
    linked = set(re.findall(r"\]\(docs/([^)#]+)", readme))
    assert linked == {p.name for p in DOCS.glob("*.md")} - {"index.md"}, "the README's map of the docs"


def test_dedicated_tests_exist() -> None:
    for page, test in DEDICATED.items():
        assert (DOCS / page).is_file() and (ROOT / test).is_file(), (page, test)
        assert f'"{page}"' in (ROOT / test).read_text(), f"{test} does not read {page}"


OTHER_BLOCKS = [
    pytest.param(code, id=f"{page.name}-{i}")
    for page in sorted(DOCS.glob("*.md"))
    if page.name not in DEDICATED
    for i, code in enumerate(blocks(page.read_text(), "python"))
]


@pytest.mark.parametrize("code", OTHER_BLOCKS)
def test_every_other_python_block_runs(code: str, tmp_path: Path) -> None:
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=tmp_path, check=False
    )
    assert out.returncode == 0, out.stderr[-2000:]
