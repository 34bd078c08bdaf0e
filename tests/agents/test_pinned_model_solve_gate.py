"""The solver's certain-completion fixpoint on a hand-made model, and when it reads memory.

The model (four states, one action each) is drawn by hand: state 0 completes; state 1
goes to 0 or to 2 with probability 1/2 each; state 2 loops on itself for ever; state 3
goes to 1. Only state 0 completes with probability 1: 1 may fall into 2, and 3 leads to
1, which the fixpoint finds in its second and third rounds (not its first).
"""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest
from scipy import sparse

from hg_marl.agents.models.builder import Dynamics, Model
from hg_marl.agents.models.solve import certain_states, solve, without_self_loops
from hg_marl.core import World
from tests.agents.test_models import array_model


def test_only_states_that_complete_for_sure_are_certain() -> None:
    model = SimpleNamespace(n=4, pair_state=lambda: np.arange(4), pair_terminal=np.array([True, False, False, False]))
    #                      pair 1 -> 0, 2       pair 2 -> 2   pair 3 -> 1
    rows, cols, probs = [1, 1, 2, 3], [0, 2, 2, 1], [0.5, 0.5, 1.0, 1.0]
    transitions = sparse.csr_matrix((probs, (rows, cols)), shape=(4, 4))
    alive, ok = certain_states(model, transitions)  # type: ignore[arg-type]
    assert alive.tolist() == [True, False, False, False]
    assert ok.tolist() == [True, False, False, False]


class Recorder:
    """A budget that never refuses and records each reading's sweep count and memory flag."""

    def __init__(self) -> None:
        self.readings: list[tuple[int, bool]] = []

    def check(self, phase: str, done: int, total: Any = None, unit: str = "", *, memory: bool = True, **_: Any) -> None:
        assert phase == "solve" and unit == "sweeps"
        self.readings.append((done, memory))


def test_the_solver_reads_memory_first_and_every_4096_sweeps() -> None:
    model, _ = array_model(World("paper2015"), "random")
    budget = Recorder()
    solution = solve(model, tolerance=0.0, max_iterations=4096, budget=budget)  # type: ignore[arg-type]
    assert solution.iterations == 4096 and not solution.converged
    # the first reading before any sweep (memory read), then one every 64 sweeps
    assert [d for d, _ in budget.readings] == [0, *range(64, 4097, 64)]
    assert [d for d, memory in budget.readings if memory] == [0, 4096]


def _model(t_start: list[int], t_next: list[int], t_prob: list[float], t_tau: list[float], pairs: int) -> Model:
    """Two states (10 and 11), ``pairs`` pairs at state 0 and the rest at state 1, the last
    pair the completing wait; the re-drawn table is state 0 (probability 1, the first pair's
    re-draw seconds: 2 s)."""
    dynamics = Dynamics(
        t_start=np.array(t_start),
        t_next=np.array(t_next),
        t_prob=np.array(t_prob),
        t_tau=np.array(t_tau),
        regen_next=np.array([0]),
        regen_prob=np.array([1.0]),
        regen_tau=np.array([2.0]),
    )
    n_pairs = len(t_start) - 1
    return Model(
        packer=None,  # type: ignore[arg-type]
        keys=np.array([10, 11]),
        pair_start=np.array([0, pairs, n_pairs]),
        pair_action=np.arange(n_pairs) + 2,
        pair_terminal=np.arange(n_pairs) == n_pairs - 1,
        dynamics=[dynamics],
        n_layouts=1,
    )


def _looping_model(p_back: float) -> Model:
    """State 0 has one pair: 5 s, then back to 0 with ``p_back``, else to 1. State 1 has a
    pair that only returns to 1 (3 s) and the completing wait."""
    return _model([0, 2, 3, 3], [0, 1, 1], [p_back, 1.0 - p_back, 1.0], [5.0, 5.0, 3.0], pairs=1)


def test_a_self_loop_is_solved_in_closed_form_in_two_sweeps() -> None:
    # By hand: V(1) = 0 (the completing wait); V(0) = 5 + 0.8 V(0)  =>  V(0) = 5 / 0.2 = 25 s.
    # Plain sweeps from 0 reach it one factor 0.8 at a time: 25 (1 - 0.8^k) is within 1e-9
    # of 25 only after k = 108 sweeps; solved in closed form the first sweep gives 25 and
    # the second sees no change.
    solution = solve(_looping_model(0.8), tolerance=1e-9)
    assert solution.iterations == 2 and solution.converged
    assert solution.values.tolist() == pytest.approx([25.0, 0.0], abs=1e-12)  # 1 / (1 - 0.8) is not 5 in floats
    # q is the plain operator's: the looping pair at state 1 costs 3 s and returns to V(1) = 0.
    assert solution.q.tolist() == pytest.approx([25.0, 3.0, 0.0], abs=1e-12)
    assert solution.best_pair.tolist() == [0, 2]
    assert solution.seconds_per_task == pytest.approx(27.0, abs=1e-12)  # 2 s for the re-draw, then 25


def test_the_closed_form_divides_by_the_leaving_probability_summed_not_one_minus_the_loop() -> None:
    model = _looping_model(0.8)
    cost = np.array([5.0, 3.0, 0.0])
    matrix, scaled, looping = without_self_loops(
        model.pair_state(), model.t_start, model.t_next, model.t_prob, cost, model.n
    )
    # pair 0 leaves with 1 - 0.8 (as a float: 0.19999999999999996), the only transition it keeps
    leave = 1.0 - 0.8
    assert matrix.toarray().tolist() == [[0.0, leave / leave], [0.0, 0.0], [0.0, 0.0]]
    assert scaled.tolist() == [5.0 * (1.0 / leave), 3.0, 0.0]
    assert looping.tolist() == [False, True, False]


@pytest.mark.parametrize(("extra", "chosen"), [(1e-9, 0), (5e-7, 0), (2e-6, 1)])
def test_pairs_within_a_microsecond_of_the_best_are_tied_and_the_first_wins(extra: float, chosen: int) -> None:
    # State 0: pair 0 takes 4 s + extra to state 1, pair 1 takes 4 s to state 1; state 1 completes.
    # Within 1e-6 s the two are tied and the first in option order is chosen; beyond it, the faster.
    model = _model([0, 1, 2, 2], [1, 1], [1.0, 1.0], [4.0 + extra, 4.0], pairs=2)
    solution = solve(model)
    assert solution.best_pair.tolist() == [chosen, 2]
    assert solution.values[0] == 4.0  # the value is the minimum, whichever pair is chosen


def test_a_model_where_nothing_completes_takes_no_sweep() -> None:
    # State 0's only pair returns to 0 for ever; state 1 completes but is never reached from
    # the re-drawn table (state 0): no state of the re-draw completes, so the time is infinite.
    # State 1 is certain (its wait completes), so the sweeps run; with it unreachable too
    # (below), nothing is certain and no sweep is made.
    solution = solve(_model([0, 1, 1], [0], [1.0], [5.0], pairs=1))
    assert solution.seconds_per_task == np.inf and solution.best_pair.tolist() == [0, 1]
    nothing = _model([0, 1, 2], [0, 1], [1.0, 1.0], [5.0, 5.0], pairs=1)
    nothing.pair_terminal[:] = False  # state 1's pair now loops too: nothing completes anywhere
    solution = solve(nothing)
    assert solution.iterations == 0 and not solution.converged
    assert solution.values.tolist() == [np.inf, np.inf]
