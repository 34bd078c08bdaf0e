"""The array form of the progress guard at its edges, pinned for the mutation gate.

Expected values by hand from the rule (agents/progress.py): a state that differs from the
previous one in anything (here only the offered object) is a change and zeroes the
count; a reset table counts from 0; resetting no table makes room for none.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.progress import ArrayProgressGuard
from hg_marl.core import World
from hg_marl.core.batch import BatchState
from tests.agents.test_oracle import TINY


def _batch(offer_obj: int) -> BatchState:
    one = np.array([1], dtype=np.int64)
    return BatchState(np.zeros((1, 1), dtype=np.int64), one * 0, one * 0, one * offer_obj)


def test_a_change_of_the_offered_object_alone_is_a_change() -> None:
    guard = ArrayProgressGuard(World(TINY))
    proposed = np.array([3], dtype=np.int64)
    guard.apply(_batch(0), proposed)
    guard.apply(_batch(0), proposed)
    assert guard.unchanged.tolist() == [1]  # the same state twice: one unchanged turn
    guard.apply(_batch(1), proposed)  # only offer_obj differs, and it is larger
    assert guard.unchanged.tolist() == [0]
    guard.apply(_batch(0), proposed)  # and smaller
    assert guard.unchanged.tolist() == [0]


def test_a_reset_table_counts_from_zero_and_no_rows_make_no_room() -> None:
    guard = ArrayProgressGuard(World(TINY))
    guard.reset_rows(np.array([], dtype=np.int64))
    assert len(guard.unchanged) == len(guard.moves) == len(guard.fired) == 0
    proposed = np.array([3], dtype=np.int64)
    for _ in range(3):
        guard.apply(_batch(0), proposed)
    assert guard.unchanged.tolist() == [2]
    guard.reset_rows(np.array([0], dtype=np.int64))
    assert guard.unchanged.tolist() == [0]
    assert guard.moves.tolist() == [0] and guard.fired.tolist() == [False]
    assert len(guard.unchanged) == 1
