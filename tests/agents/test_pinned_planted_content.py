"""Pinned against a planted bug: the code walk keys the top-level package of every module it reaches.

Importing ``hg_marl.agents.x`` runs ``hg_marl/__init__.py``, then ``hg_marl/agents/__init__.py``,
then ``x``: every dotted prefix of a reached module is code that ran, so it is keyed (the
module docstring: "a parent package is in with its child"). Worked by hand on a module
with no imports at all: its reach starts with itself, ``hg_marl.agents`` and ``hg_marl``,
and editing the code of ``hg_marl/__init__.py`` changes its digest. On real roots the
property is checked as stated: the found set is closed under taking a dotted prefix.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents import content
from tests.source_copy import copy_sources, edit_code, write

LEAF = "hg_marl.agents.planted_leaf_probe"


@pytest.fixture()
def sources(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    root = copy_sources(tmp_path / "src", monkeypatch)
    write(root / "agents/planted_leaf_probe.py", "VALUE = 1\n")  # imports nothing
    return root


def test_a_module_without_imports_reaches_its_package_and_the_top_level_package(sources: Path) -> None:
    modules, _ = content.code_modules((LEAF,))
    assert {LEAF, "hg_marl.agents", "hg_marl"} <= set(modules)


def test_editing_the_top_level_package_changes_the_digest_of_a_module_without_imports(sources: Path) -> None:
    before = content.code_digest((LEAF,))
    edit_code(sources / "hg_marl/__init__.py")
    assert content.code_digest((LEAF,)) != before


@pytest.mark.parametrize(
    "root", ["hg_marl.core.world", "hg_marl.agents.progress", "hg_marl.agents.models.chains", "hg_marl.agents.content"]
)
def test_every_dotted_prefix_of_a_reached_module_is_reached(root: str) -> None:
    modules, _ = content.code_modules((root,))
    prefixes = {name.rsplit(".", i)[0] for name in modules for i in range(name.count(".") + 1)}
    assert "hg_marl" in prefixes
    assert prefixes - set(modules) == set()
