"""SB3 model-file pieces checked against values worked by hand (``agents/model_sb3.py``).

A Dict space round-trips through its JSON; a space type that is not one of the four is
refused by name. Saved state may nest at most 20 levels: a scalar wrapped in 20 lists is
read back, in 21 it is refused. A replay buffer is restored only from arrays of the
buffer's own dtype, and its position is any of ``0 .. buffer_size - 1``.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest
from gymnasium import spaces

from hg_marl.agents.model_sb3 import (
    _unflatten,
    load_replay_buffer,
    save_replay_buffer,
    space_from_json,
    space_to_json,
)
from hg_marl.core.errors import ModelFileError


def test_a_dict_space_round_trips() -> None:
    space = spaces.Dict({"a": spaces.Discrete(3), "b": spaces.MultiBinary(2)})
    back = space_from_json(space_to_json(space), "h")
    assert isinstance(back, spaces.Dict)
    assert back == space


@pytest.mark.parametrize("space", [spaces.MultiBinary([2, 3]), spaces.MultiBinary(4), spaces.Box(0.0, 1.0, ())])
def test_multi_dimensional_and_scalar_spaces_round_trip(space: Any) -> None:
    """A ``MultiBinary`` of shape (2, 3) is written as ``"n": [2, 3]``: it must read back too
    (it was saved and then refused on load); a scalar ``Box`` has the empty shape."""
    assert space_from_json(space_to_json(space), "h.json") == space


@pytest.mark.parametrize(
    ("data", "field"),
    [
        ({"type": "MultiBinary", "n": True}, "MultiBinary n"),  # JSON's true is not the integer 1
        ({"type": "MultiBinary", "n": []}, "MultiBinary n"),
        ({"type": "MultiBinary", "n": [1000, 1001]}, "MultiBinary n"),  # 1,001,000 elements: over the limit
        ({"type": "MultiBinary", "n": [2, 0]}, "MultiBinary n"),
        ({"type": "Discrete", "n": 0}, "Discrete n"),  # no actions
        ({"type": "Discrete", "n": 3, "start": False}, "Discrete start"),
        ({"type": "Box", "shape": [True], "low": 0, "high": 1, "dtype": "float32"}, "Box shape"),
        # 2**64 elements: numpy's product of the shape wraps to 0, Python's integers do not
        (
            {"type": "Box", "shape": [2**32, 2**32], "low": 0, "high": 1, "dtype": "float32"},
            "Box of 18446744073709551616",
        ),
    ],
)
def test_malformed_sizes_are_refused_naming_the_field(data: dict[str, Any], field: str) -> None:
    with pytest.raises(ModelFileError, match=rf"^h\.json: {field}"):
        space_from_json(data, "h.json")


def test_an_unknown_space_type_is_refused_by_name() -> None:
    with pytest.raises(ModelFileError, match="unknown space type 'Tuple'"):
        space_from_json({"type": "Tuple", "spaces": [{"type": "Discrete", "n": 2}]}, "h")


def _nested(levels: int) -> Any:
    tree: Any = 7
    for _ in range(levels):
        tree = [tree]
    return tree


def test_state_nested_in_twenty_lists_is_read_back() -> None:
    assert _unflatten(_nested(20), {}, "h") == _nested(20)


def test_state_nested_in_twenty_one_lists_is_refused() -> None:
    with pytest.raises(ModelFileError, match="nested too deeply"):
        _unflatten(_nested(21), {}, "h")


def _buffer(dtype: Any, pos: int = 0) -> SimpleNamespace:
    size = 4
    return SimpleNamespace(
        observations=np.arange(size * 2, dtype=dtype).reshape(size, 2) * (pos + 1),
        actions=np.full((size, 1), pos, dtype=np.int64),
        buffer_size=size,
        pos=pos,
        full=False,
    )


def test_a_buffer_is_restored_with_its_position(tmp_path: Path) -> None:
    source = _buffer(np.float64, pos=3)
    entry = save_replay_buffer(source, tmp_path / "buffer.npz")
    target = _buffer(np.float64)
    load_replay_buffer(target, tmp_path / "model.json", entry)
    assert (target.pos, target.full) == (3, False)
    assert target.observations.tolist() == [[0, 4], [8, 12], [16, 20], [24, 28]]
    assert target.actions.tolist() == [[3], [3], [3], [3]]


@pytest.mark.parametrize("pos", [-1, 4])
def test_a_position_outside_the_buffer_is_refused(tmp_path: Path, pos: int) -> None:
    entry = save_replay_buffer(_buffer(np.float64), tmp_path / "buffer.npz")
    with pytest.raises(ModelFileError, match="out of range"):
        load_replay_buffer(_buffer(np.float64), tmp_path / "model.json", {**entry, "pos": pos})


@pytest.mark.parametrize(("saved", "needed"), [(np.float32, np.float64), (np.float64, np.float32)])
def test_arrays_of_another_dtype_are_refused(tmp_path: Path, saved: Any, needed: Any) -> None:
    entry = save_replay_buffer(_buffer(saved, pos=1), tmp_path / "buffer.npz")
    target = _buffer(needed)
    with pytest.raises(ModelFileError, match="the buffer needs"):
        load_replay_buffer(target, tmp_path / "model.json", entry)
    assert target.pos == 0 and target.observations.tolist() == [[0, 1], [2, 3], [4, 5], [6, 7]]


def test_a_header_sb3_cannot_build_from_is_refused_in_one_line(tmp_path: Path) -> None:
    """SB3 asserts an algorithm's supported spaces (DQN: a Discrete action space): a header
    whose action space is a Box makes the constructor raise ``AssertionError``, which must
    come back as the file's one-line refusal, not a traceback."""
    import json

    pytest.importorskip("stable_baselines3")
    from stable_baselines3 import DQN

    from hg_marl.agents.model_file import save_sb3, world_fields
    from hg_marl.agents.model_format import load_model_file
    from hg_marl.agents.model_sb3 import build_sb3
    from hg_marl.agents.views import RobotView
    from hg_marl.core import Agent, World

    world = World("paper2015")
    model = DQN("MlpPolicy", RobotView("paper2015"), buffer_size=16, learning_starts=0, seed=0, device="cpu")
    path = save_sb3(model, tmp_path / "model.json", world_fields(world, Agent.ROBOT), observation="facts")
    header = json.loads(path.read_text())
    header["action_space"] = space_to_json(spaces.Box(0.0, 1.0, (2,)))
    path.write_text(json.dumps(header))
    with pytest.raises(ModelFileError, match=r"model\.json: cannot rebuild the DQN model \(.*Discrete") as info:
        build_sb3(load_model_file(path))
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("which", ["observation", "action"])
def test_an_environment_differing_in_either_space_is_refused(tmp_path: Path, which: str) -> None:
    """Resuming on an environment whose observation space, or whose action space alone,
    differs from the header's is refused (paper2015's robot: 24 facts, 18 actions)."""
    pytest.importorskip("stable_baselines3")
    from stable_baselines3 import DQN

    from hg_marl.agents.model_file import save_sb3, world_fields
    from hg_marl.agents.model_format import load_model_file
    from hg_marl.agents.model_sb3 import _SpacesOnly, build_sb3
    from hg_marl.agents.views import RobotView
    from hg_marl.core import Agent, World

    model = DQN("MlpPolicy", RobotView("paper2015"), buffer_size=16, learning_starts=0, seed=0, device="cpu")
    path = save_sb3(model, tmp_path / "model.json", world_fields(World("paper2015"), Agent.ROBOT), observation="facts")
    obs = spaces.Box(0, 1, (25 if which == "observation" else 24,), np.int8)
    env = _SpacesOnly(obs, spaces.Discrete(19 if which == "action" else 18))
    with pytest.raises(ModelFileError, match=r"model\.json: its spaces differ from the environment's$"):
        build_sb3(load_model_file(path), env=env)
