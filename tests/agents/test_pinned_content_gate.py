"""The content keys' texts looked at, relative imports and library versions, worked by hand.

- Nesting: ``fields`` is depth 0 and each table or list entered adds one, so a text
  inside ``k`` lists under one field sits at depth ``k + 1`` and one inside ``k`` nested
  tables at depth ``k``; texts deeper than ``MAX_DEPTH`` (32) are not looked at. A file
  named under 31 lists is keyed and under 32 is not; under 32 tables it is keyed and
  under 33 it is not.
- Relative imports: ``from .builder import X`` in ``hg_marl.agents.models.chains`` (a
  module, so its package is ``hg_marl.agents.models``) names
  ``hg_marl.agents.models.builder``; ``from .. import content`` names the package
  ``hg_marl.agents`` and its submodule ``hg_marl.agents.content``; in a package's
  ``__init__`` the package is the module itself.
- Libraries: a top-level module is keyed by its distribution's version (numpy's is
  ``numpy.__version__``); the standard library is keyed by the Python version alone, and
  a distribution that is listed but not installed is skipped.
"""

from __future__ import annotations

import ast
import importlib.metadata
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents import content
from tests.source_copy import copy_sources, write


def in_lists(value: Any, k: int) -> Any:
    for _ in range(k):
        value = [value]
    return value


def in_tables(value: Any, k: int) -> Any:
    for _ in range(k):
        value = {"inner": value}
    return value


@pytest.fixture()
def named(tmp_path: Path) -> str:
    path = tmp_path / "trace.txt"
    path.write_text("a replay trace\n")
    return str(path)


def test_a_file_under_31_lists_is_keyed_and_under_32_is_not(named: str) -> None:
    assert content.MAX_DEPTH == 32
    assert set(content.named_files({"f": in_lists(named, 31)})) == {named}  # depth 32
    assert content.named_files({"f": in_lists(named, 32)}) == {}  # depth 33


def test_a_file_under_32_tables_is_keyed_and_under_33_is_not(named: str) -> None:
    assert set(content.named_files(in_tables(named, 32))) == {named}  # depth 32
    assert content.named_files(in_tables(named, 33)) == {}  # depth 33


def test_relative_imports_name_the_modules_they_resolve_to() -> None:
    tree = ast.parse("from .builder import Dynamics\nfrom .. import content\nimport numpy.linalg\n")
    assert content._imports(tree, "hg_marl.agents.models.chains", False) == {
        "hg_marl.agents.models.builder",
        "hg_marl.agents.models.builder.Dynamics",
        "hg_marl.agents",
        "hg_marl.agents.content",
        "numpy.linalg",
    }
    package = ast.parse("from .lazy import ranges\n")
    assert content._imports(package, "hg_marl.agents.models", True) == {
        "hg_marl.agents.models.lazy",
        "hg_marl.agents.models.lazy.ranges",
    }


def test_a_module_imported_relatively_is_in_the_code_digest(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    sources = copy_sources(tmp_path / "src", monkeypatch)
    write(sources / "agents/relative_probe.py", "from .models import lazy\n")
    modules, _ = content.code_modules(("hg_marl.agents.relative_probe",))
    assert {"hg_marl.agents.models", "hg_marl.agents.models.lazy"} <= set(modules)


def test_libraries_are_keyed_by_their_distributions_version() -> None:
    versions = content._versions.__wrapped__(frozenset({"numpy", "json", "os"}))
    assert versions == (("numpy", np.__version__),)


def test_a_listed_distribution_that_is_not_installed_is_skipped(monkeypatch: pytest.MonkeyPatch) -> None:
    listed = {"numpy": ["numpy"], "ghost_top": ["hg-marl-no-such-distribution"]}
    monkeypatch.setattr(importlib.metadata, "packages_distributions", lambda: listed)
    versions = content._versions.__wrapped__(frozenset({"numpy", "ghost_top"}))
    assert versions == (("numpy", np.__version__),)


def test_a_modules_digest_ignores_comments_blank_lines_and_docstrings_but_not_code() -> None:
    # the same code moved down two lines by a comment and a blank line, its docstring reworded:
    # one digest; a changed constant: another
    base = b'"""One."""\n\ndef f(x):\n    return x + 1\n'
    moved = b'"""Reworded."""\n# a comment\n\n\ndef f(x):\n    # why\n    return x + 1\n'
    changed = b'"""One."""\n\ndef f(x):\n    return x + 2\n'
    assert content.module_digest(base) == content.module_digest(moved)
    assert content.module_digest(base) != content.module_digest(changed)
