"""The certain-completion fixpoint of ``agents/models/chains.py`` on three-state chains worked by hand.

State 0 has the completing pair; state 1's only pair goes to state 0 or, half the time,
to state 2, a trap whose only pair loops on itself. From state 1 no policy completes with
certainty, so only state 0 is certain. Given a second pair that goes straight to state 0,
state 1 becomes certain through that pair alone.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.models.builder import Dynamics
from hg_marl.agents.models.chains import certain_states


def _chain(rows: list[list[tuple[int, float]]]) -> Dynamics:
    """One transition row per pair: ``(next state, probability)`` each, seconds 1."""
    t_next = [s for row in rows for s, _ in row]
    t_prob = [p for row in rows for _, p in row]
    t_start = np.concatenate([[0], np.cumsum([len(r) for r in rows])])
    empty = np.zeros(0)
    return Dynamics(
        t_start=t_start.astype(np.int64),
        t_next=np.array(t_next, dtype=np.int64),
        t_prob=np.array(t_prob),
        t_tau=np.ones(len(t_next)),
        regen_next=empty.astype(np.int64),
        regen_prob=empty,
        regen_tau=empty,
    )


def test_a_state_that_may_fall_into_a_trap_is_not_certain() -> None:
    # pairs: 0 completes at state 0; 1 (state 1) -> 0 or 2 at 1/2 each; 2 (state 2) -> 2
    pair_state = np.array([0, 1, 2])
    terminal = np.array([True, False, False])
    chain = _chain([[(0, 1.0)], [(0, 0.5), (2, 0.5)], [(2, 1.0)]])
    alive, ok = certain_states(3, pair_state, terminal, chain)
    assert alive.tolist() == [True, False, False]
    assert ok.tolist() == [True, False, False]


def test_a_safe_pair_makes_its_state_certain_and_the_risky_one_stays_out() -> None:
    # as above, and pair 3 at state 1 goes to state 0 for sure
    pair_state = np.array([0, 1, 1, 2])
    terminal = np.array([True, False, False, False])
    chain = _chain([[(0, 1.0)], [(0, 0.5), (2, 0.5)], [(0, 1.0)], [(2, 1.0)]])
    alive, ok = certain_states(3, pair_state, terminal, chain)
    assert alive.tolist() == [True, True, False]
    assert ok.tolist() == [True, False, True, False]
