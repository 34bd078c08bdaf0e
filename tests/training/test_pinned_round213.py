"""Values that round 213's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.habit import QLearner
from hg_marl.agents.models.builder import _Index
from hg_marl.agents.models.keyed import SegmentTable
from hg_marl.training.store import Job
from tests.training.test_pinned_round205 import executed_with_a_stand_in


def test_the_habit_counts_every_td_update_and_keeps_the_count_on_disk(tmp_path: Path) -> None:
    # Three TD updates (two from one state, one from another, one terminal): n_updates is
    # "TD updates applied so far", 3, and a saved learner reads back the same 3.
    habit = QLearner(3, 2)
    a, b = np.array([1, 0, 1], dtype=np.int8), np.array([0, 1, 0], dtype=np.int8)
    habit.update(a, 0, 1.0, b)
    habit.update(b, 1, 0.0, a)
    habit.update(a, 1, 1.0, b, done=True)
    assert habit.n_updates == 3
    assert habit.visits(a) == 2 and habit.visits(b) == 1
    assert QLearner.load(habit.save(tmp_path / "habit.npz")).n_updates == 3


def test_the_state_index_sorts_keys_given_in_descending_order() -> None:
    # Keys are given distinct, in the order their ids are wanted: 5, 3, 1 get ids 0, 1, 2, and
    # each is found again by its id whatever order it is asked in (the index keeps them sorted).
    index = _Index()
    assert index.add(np.array([5, 3, 1])).tolist() == [0, 1, 2]
    assert index.sorted.tolist() == [1, 3, 5]
    assert index.id_of(np.array([1, 3, 5])).tolist() == [2, 1, 0]
    # a second batch: 3 is known (id 1), 6 and 2 are new (ids 3 and 4, in their given order)
    assert index.add(np.array([6, 3, 2])).tolist() == [3, 1, 4]
    assert index.id_of(np.array([2, 6, 5])).tolist() == [4, 3, 0]
    assert index.keys().tolist() == [5, 3, 1, 6, 2]


def test_keys_added_out_of_order_to_a_filled_table_land_in_sorted_place() -> None:
    # The table holds 20 (entry 1); 30 (entries 7, 8) and 10 (entry 9) are added in that order.
    # By hand: the keys are then 10, 20, 30 and each key's entries are the ones given with it.
    table = SegmentTable({"a": np.int64})
    table.add(np.array([20]), np.array([1]), {"a": np.array([1])})
    table.add(np.array([30, 10]), np.array([2, 1]), {"a": np.array([7, 8, 9])})
    assert table.keys.tolist() == [10, 20, 30]
    start, size = table.lookup(np.array([30, 10, 20]))
    got = [table.entries["a"][s : s + k].tolist() for s, k in zip(start, size, strict=True)]
    assert got == [[7, 8], [9], [1]]
    assert table.missing(np.array([10, 15, 30])).tolist() == [15]


def test_a_jobs_human_is_built_with_the_jobs_human_parameters(monkeypatch: pytest.MonkeyPatch) -> None:
    # execute builds the human as make_human(name, **human_params): a stand-in make_human
    # records what it was asked, and a stand-in run hands back the human it was given.
    import hg_marl.agents.humans as humans

    job = Job(robot="random", seed=4, human="noisy", human_params={"epsilon": 0.25})
    built, asked = executed_with_a_stand_in(monkeypatch, humans, "human", job)
    assert built == ("human noisy", 4)
    assert asked == [("noisy", {"epsilon": 0.25})]
