"""A population file written for a test: ``train`` members of ``paper2015``, one per ``name=spec``."""

from __future__ import annotations

from pathlib import Path


def train_members(tmp_path: Path, **specs: str) -> str:
    """The path of a ``paper2015`` population file of ``train`` members ``name=spec``, in ``tmp_path``."""
    path = tmp_path / "population.toml"
    text = 'name = "t"\nscenario = "paper2015"\n'
    for name, spec in specs.items():
        text += f'\n[[members]]\nname = "{name}"\nsplit = "train"\nspec = "{spec}"\n'
    path.write_text(text)
    return str(path)
