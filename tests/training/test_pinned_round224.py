"""Values that round 224's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.model_format import load_model_file, save_model_file
from hg_marl.agents.model_limits import check_shape, expected_shapes
from hg_marl.agents.models.budget import Budget
from hg_marl.agents.vector_envs import human_vector_env
from hg_marl.core.errors import ModelFileError
from hg_marl.training.outputs import check_output
from hg_marl.training.store import Store


def test_the_default_memory_budget_is_four_gigabytes() -> None:
    # The documented default: 4 GB of resident memory (4 * 2**30 bytes), named so in a refusal.
    budget = Budget()
    assert budget.memory == 4 * 2**30
    assert f"{budget.memory / 2**30:g} GB" == "4 GB"


def test_a_model_of_the_other_seat_is_refused_naming_its_own_seat_first(tmp_path: Path) -> None:
    # A robot's model asked for the human's seat: the refusal says where it was trained (robot),
    # then the seat asked for (the human's).
    header = {"kind": "linear_softmax", "seat": "robot", "fact_names": ["f"], "action_names": ["a", "b"]}
    path = save_model_file(tmp_path / "m.json", header, {"W": np.zeros((2, 1)), "b": np.zeros(2)})
    with pytest.raises(ModelFileError) as info:
        load_model_file(path, seat="human")
    assert str(info.value) == f"{path}: trained in the robot seat, not the human's"


def test_an_unknown_array_is_refused_naming_the_expected_ones_in_sorted_order() -> None:
    # A table's header implies "facts" then "actions"; the refusal lists them sorted: actions, facts.
    shapes = expected_shapes({"kind": "table", "fact_names": ["f"], "action_names": ["a"]})
    assert list(shapes or {}) == ["facts", "actions"]
    assert check_shape("x", (1,), shapes or {}) == "array 'x' is not one of actions, facts"


def test_every_accepted_ending_is_accepted_not_only_the_first(tmp_path: Path) -> None:
    # Two accepted endings: a name ending in the second one is as good as one ending in the first.
    for name in ("clip.mp4", "clip.gif", "CLIP.GIF"):
        assert check_output(tmp_path / name, "--video", suffixes=(".mp4", ".gif")) == tmp_path / name


def test_a_cached_none_is_served_not_computed_again(tmp_path: Path) -> None:
    # None is a value like any other: computed once, then read back from the store.
    store = Store(tmp_path)
    calls: list[int] = []

    def compute() -> None:
        calls.append(1)

    assert store.cached("oracle", {"human": "lazy"}, compute) is None
    assert store.cached("oracle", {"human": "lazy"}, compute) is None
    assert len(calls) == 1


def test_live_robots_play_each_table_of_the_human_seat() -> None:
    # Two tables against live random robots (compiled=False): one actor per table, both reset.
    env = human_vector_env(num_envs=2, robot="random", compiled=False, cache=False)
    obs, _ = env.reset(seed=0)
    assert len(env.partner.actors) == 2
    assert len(obs) == 2
