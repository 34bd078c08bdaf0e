"""A copy of the project's sources that the content keys read instead of the real ones.

``copy_sources`` copies ``hg_marl/``, ``agents/`` and ``training/`` into a temporary folder
and points :func:`hg_marl.agents.content.source_file` at the copies, so a test can edit one
file of the copy at a time and see which keys change, without touching the checkout.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from hg_marl.agents import content

REPO = Path(__file__).resolve().parents[1]
TREES = ("hg_marl", "agents", "training")


def copy_sources(root: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Copy the three source trees under ``root`` and make the content keys read them there."""
    for tree in TREES:
        shutil.copytree(REPO / tree, root / tree, ignore=shutil.ignore_patterns("__pycache__"))

    def copied(name: str) -> tuple[Path, bool] | None:
        """The copy's file of a project module, found by its name as the installed layout maps it."""
        parts = name.split(".")
        if parts[0] != "hg_marl":
            return None
        if parts[1:2] in (["agents"], ["training"]):  # installed from agents/ and training/
            folder = root.joinpath(parts[1], *parts[2:])
        else:
            folder = root.joinpath(*parts)
        if (folder / "__init__.py").is_file():
            return folder / "__init__.py", True
        module = folder.with_suffix(".py")
        return (module, False) if module.is_file() else None

    monkeypatch.setattr(content, "source_file", copied)
    return root


def write(path: Path, text: str) -> None:
    """Write a source of the copy; the code digests computed so far are forgotten."""
    path.write_text(text)
    content.forget_code()


def edit_code(path: Path) -> None:
    """A change to what the module does (a new module-level name), not to its documentation."""
    write(path, path.read_text() + "\n_EDITED_FOR_A_TEST = 1\n")


def edit_docs(path: Path) -> None:
    """A change to comments only: no key may change."""
    write(path, path.read_text() + "\n# a comment added by a test\n")
