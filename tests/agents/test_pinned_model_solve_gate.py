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
from scipy import sparse

from hg_marl.agents.models.solve import certain_states, solve
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
