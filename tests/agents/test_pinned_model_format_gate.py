"""A header's weights file stays in its folder, and a policy loads only into its own world.

Worked by hand: ``./w.npz`` and ``sub/w.npz`` are not plain file names (their last part is
``w.npz``), so they are refused as such, before any path is resolved; a plain name that is a
symlink to another folder resolves outside the header's folder whichever way the two folder
names sort. ``check_world`` accepts exactly the world whose fact and action names the header
lists.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.model_format import ModelFile, check_world, weights_file
from hg_marl.core.errors import ModelFileError


@pytest.mark.parametrize("name", ["./w.npz", "sub/w.npz"])
def test_a_name_with_a_folder_part_is_refused_as_not_a_plain_file_name(tmp_path: Path, name: str) -> None:
    (tmp_path / "sub").mkdir()
    (tmp_path / "w.npz").write_bytes(b"")
    (tmp_path / "sub" / "w.npz").write_bytes(b"")
    with pytest.raises(ModelFileError, match="must name a file in the header's own folder"):
        weights_file(tmp_path / "model.json", {"file": name})


def test_a_plain_name_is_the_file_beside_the_header(tmp_path: Path) -> None:
    assert weights_file(tmp_path / "model.json", {"file": "w.npz"}) == tmp_path / "w.npz"


@pytest.mark.parametrize("elsewhere", ["0_before", "z_after"])
def test_a_symlink_to_another_folder_is_refused(tmp_path: Path, elsewhere: str) -> None:
    home, other = tmp_path / "m_home", tmp_path / elsewhere
    home.mkdir()
    other.mkdir()
    (other / "w.npz").write_bytes(b"")
    try:
        (home / "w.npz").symlink_to(other / "w.npz")
    except OSError:
        pytest.skip("symlinks not available here")
    with pytest.raises(ModelFileError, match="points outside the header's folder"):
        weights_file(home / "model.json", {"file": "w.npz"})


class _Seat:
    label = "robot"


def _world(facts: list[str], actions: list[str]) -> SimpleNamespace:
    seat = _Seat()
    return SimpleNamespace(
        seat=seat,
        fact_names=tuple(facts),
        action_names={seat: tuple(actions)},
        scenario=SimpleNamespace(name="s"),
    )


def _file(facts: list[str], actions: list[str]) -> ModelFile:
    header = {"seat": "robot", "scenario": "s", "fact_names": facts, "action_names": actions}
    return ModelFile(Path("model.json"), header, {"W": np.zeros(1)})


def test_check_world_accepts_the_world_the_policy_was_saved_for() -> None:
    world = _world(["a", "b"], ["x", "y"])
    check_world(_file(["a", "b"], ["x", "y"]), world, world.seat)


@pytest.mark.parametrize(
    ("facts", "actions"),
    [(["a"], ["x", "y"]), (["a", "b", "c"], ["x", "y"]), (["b", "a"], ["x", "y"]), (["a", "b"], ["y", "x"])],
)
def test_check_world_refuses_other_facts_or_actions(facts: list[str], actions: list[str]) -> None:
    world = _world(["a", "b"], ["x", "y"])
    with pytest.raises(ModelFileError, match="its facts or actions differ"):
        check_world(_file(facts, actions), world, world.seat)
