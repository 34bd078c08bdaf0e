"""The solver's memory: per-transition temporaries a block at a time, one copy of the indices, the heap given back.

A model of tens of millions of transitions (an 8-object table) holds its probabilities,
seconds and next states in arrays of hundreds of megabytes each; a temporary of the same
length per step of the solve would double that. These tests pin what keeps it bounded,
each against a value stated by hand or by a plain reference, and that the answers do not
move by a bit.
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest

from hg_marl.agents.models import budget as budget_module
from hg_marl.agents.models.budget import _malloc_trim, rss, trim_heap
from hg_marl.agents.models.solve import pair_blocks, pair_sums, solve, without_self_loops
from hg_marl.core import World
from tests.agents.test_models import array_model

solve_module = importlib.import_module("hg_marl.agents.models.solve")  # the package's ``solve`` is the function

# five pairs with 3, 0, 2, 5 and 1 transitions
T_START = np.array([0, 3, 3, 5, 10, 11])


def test_blocks_cut_between_pairs_at_the_first_pair_past_each_multiple() -> None:
    # blocks of 4: the first pair starting at or after transition 4 is pair 3 (it starts at 5),
    # after 8 it is pair 4 (starts at 10): pairs 0-2 (5 transitions), pair 3 (5), pair 4 (1)
    assert pair_blocks(T_START, 4) == [(0, 3), (3, 4), (4, 5)]
    # one block holds them all; a block of 1 cuts before every pair that starts a transition
    assert pair_blocks(T_START, 100) == [(0, 5)]
    assert pair_blocks(T_START, 1) == [(0, 1), (1, 3), (3, 4), (4, 5)]
    assert pair_blocks(np.array([0]), 4) == []  # no pairs, no blocks


def test_pair_sums_add_each_pairs_transitions() -> None:
    t_pair = np.repeat(np.arange(5), np.diff(T_START))
    weights = np.arange(1.0, 12.0)  # transition i weighs i + 1
    # by hand: pair 0: 1+2+3, pair 1: none, pair 2: 4+5, pair 3: 6+7+8+9+10, pair 4: 11
    for block in (1, 2, 4, 100):
        assert pair_sums(T_START, t_pair, lambda at: weights[at], block).tolist() == [6.0, 0.0, 9.0, 40.0, 11.0]


def test_a_solve_in_small_blocks_is_the_solve_in_one_to_the_bit(monkeypatch: pytest.MonkeyPatch) -> None:
    model, _ = array_model(World("paper2015"), "random")
    whole = solve(model)
    assert len(pair_blocks(model.t_start, 37)) > 100  # the small blocks really cut the model
    monkeypatch.setattr(solve_module, "BLOCK", 37)
    cut = solve(model)
    assert cut.values.tobytes() == whole.values.tobytes()
    assert cut.q.tobytes() == whole.q.tobytes()
    assert cut.best_pair.tolist() == whole.best_pair.tolist()
    assert (cut.iterations, cut.seconds_per_task) == (whole.iterations, whole.seconds_per_task)


def test_the_pair_of_each_transition_takes_four_bytes() -> None:
    model, _ = array_model(World("paper2015"), "random")
    t_pair = model.t_pair()
    assert t_pair.dtype == np.int32
    assert t_pair.tolist() == [p for p in range(model.n_pairs) for _ in range(model.t_start[p], model.t_start[p + 1])]


def test_the_sweeps_matrix_reads_the_transitions_indices_without_a_copy() -> None:
    # two states, three pairs: pair 0 (state 0) -> 1; pair 1 (state 1) -> 1 w.p. 1/4, 0 w.p. 3/4; pair 2 (state 1)
    t_start, t_next = np.array([0, 1, 3, 3], dtype=np.int32), np.array([1, 1, 0], dtype=np.int32)
    t_prob = np.array([1.0, 0.25, 0.75])
    matrix, cost, looping = without_self_loops(
        np.array([0, 1, 1]), t_start, t_next, t_prob, np.array([2.0, 4.0, 0.0]), 2
    )
    assert np.shares_memory(matrix.indices, t_next) and np.shares_memory(matrix.indptr, t_start)
    # pair 1's loop (1/4) is solved: its move to 0 becomes certain, its cost 4 / (3/4)
    assert matrix.toarray().tolist() == [[0.0, 1.0], [1.0, 0.0], [0.0, 0.0]]
    assert cost.tolist() == pytest.approx([2.0, 16 / 3, 0.0])
    assert looping.tolist() == [False, False, False]


@pytest.mark.skipif(_malloc_trim() is None, reason="the C library has no malloc_trim")
def test_freed_small_arrays_pages_go_back_to_the_system() -> None:
    # 40,000 arrays of 8 KiB (below malloc's own mapping threshold: they live in its heap, one
    # after another), all but the last 100 freed: those 100 hold the heap's top, so glibc keeps
    # the 312 MiB below them until it is asked to trim
    arrays = [np.ones(1024) for _ in range(40_000)]
    del arrays[:-100]
    before = rss()
    trim_heap(312 * 2**20)
    assert before - rss() >= 200 * 2**20
    assert sum(float(a[0]) for a in arrays) == 100.0  # the arrays still alive are untouched


def test_pairs_that_all_loop_are_all_rescaled() -> None:
    # Every pair returns to its own state with some probability, so no scale is 1:
    # pair 0 (state 0) -> 0 w.p. 1/2, -> 1 w.p. 1/2, 3 s; pair 1 (state 1) -> 1 w.p. 1/4, -> 0 w.p. 3/4, 6 s.
    # By hand: each leaves for the other state for certain, at 3 / (1/2) = 6 s and 6 / (3/4) = 8 s.
    t_start, t_next = np.array([0, 2, 4], dtype=np.int32), np.array([0, 1, 1, 0], dtype=np.int32)
    matrix, cost, looping = without_self_loops(
        np.array([0, 1]), t_start, t_next, np.array([0.5, 0.5, 0.25, 0.75]), np.array([3.0, 6.0]), 2
    )
    assert matrix.toarray().tolist() == [[0.0, 1.0], [1.0, 0.0]]
    assert cost.tolist() == [6.0, 8.0]
    assert looping.tolist() == [False, False]


def test_the_heap_is_trimmed_only_after_256_mib_were_freed(monkeypatch: pytest.MonkeyPatch) -> None:
    # giving pages back makes the next build fault them in again: a small build keeps them
    calls: list[int] = []
    monkeypatch.setattr(budget_module, "_malloc_trim", lambda: calls.append)
    trim_heap(256 * 2**20 - 1)
    assert calls == []
    trim_heap(256 * 2**20)
    assert calls == [0]
