"""A policy's rate is read from the states it reaches: nothing else is asked, and a rate of 0 solves nothing.

Hand-made chains; each expected value is worked in the test's comments.
"""

from __future__ import annotations

import numpy as np
import pytest

import hg_marl.agents.models.chains as chains
from hg_marl.agents.models.chains import Chain, reached_rate
from hg_marl.agents.models.keyed import ranges, starts_of

# Five states. Policy: 0 -> 1 (1 s), 1 -> 2 (p 0.5, 2 s) or back to 0 (p 0.5, 2 s), 2 completes;
# 3 -> 4 and 4 -> 3 (1 s each), never reached from the re-draw (state 0).
EDGES = {0: [(1, 1.0, 1.0)], 1: [(2, 0.5, 2.0), (0, 0.5, 2.0)], 2: [], 3: [(4, 1.0, 1.0)], 4: [(3, 1.0, 1.0)]}
DONE = np.array([False, False, True, False, False])


def _asked(log: list[list[int]]) -> chains.Transitions:
    counts = np.array([len(EDGES[s]) for s in range(5)])
    t_start = starts_of(counts)
    flat = [e for s in range(5) for e in EDGES[s]]
    nxt = np.array([e[0] for e in flat], dtype=np.int64)
    prob = np.array([e[1] for e in flat])
    tau = np.array([e[2] for e in flat])

    def transitions_of(states: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        log.append(states.tolist())
        at = ranges(t_start[states], counts[states])
        return starts_of(counts[states]), nxt[at], prob[at], tau[at]

    return transitions_of


def _redraw(*entries: tuple[int, float, float]) -> Chain:
    empty = np.zeros(0)
    return Chain(
        np.zeros(1, dtype=np.int64),
        empty.astype(np.int64),
        empty,
        empty,
        np.array([e[0] for e in entries], dtype=np.int64),
        np.array([e[1] for e in entries]),
        np.array([e[2] for e in entries]),
    )


def test_only_the_states_reached_from_the_redraw_are_asked() -> None:
    # V(2) = 0; V(1) = 2 + 0.5 V(0); V(0) = 1 + V(1) -> V(0) = 1 + 2 + 0.5 V(0) -> V(0) = 6;
    # the re-draw onto state 0 takes 4 s: 10 s a task, 360 an hour
    log: list[list[int]] = []
    assert reached_rate(_redraw((0, 1.0, 4.0)), DONE, _asked(log)) == pytest.approx(360.0, rel=1e-12)
    asked = {s for states in log for s in states}
    assert asked == {0, 1, 2} and log[-1] == [0, 1, 2]  # the last question: every state reached, in id order


def test_a_redraw_onto_a_state_that_never_completes_is_rate_0_without_a_linear_system(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def no_solve(*args: object) -> None:
        raise AssertionError("a rate of 0 needs no linear system")

    monkeypatch.setattr(chains, "spsolve", no_solve)
    # half the re-draws land on 3, which cycles with 4 forever: infinite seconds a task
    chain = _redraw((0, 0.5, 4.0), (3, 0.5, 4.0))
    assert reached_rate(chain, DONE, _asked([])) == 0.0
