"""Pinned against a planted bug: ``coverage`` moves a table by ``0 .. cycles - 1`` cycles, never more.

The recipe draws, per table reset, a number of cycles from ``rng.integers(cycles)`` (the
first draw when the members draw nothing at reset). With ``cycles = 2`` a table draws 0
or 1: drawn from the same seed by hand, a table that drew 0 must be left exactly as it
was, and one that drew 1 must be one cycle away: the state after one feasible robot
action and then one feasible human action, enumerated with the world's own rules. Every
table reset is marked stale (its observation is recomputed).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchState
from hg_marl.training.baselines.recipes import CoveragePartner


class _Member:
    """A member that draws nothing at reset (no ``reset_rows``)."""

    name = "member"


def one_cycle(world: World, state: State) -> set[State]:
    """Every state one feasible robot action and then one feasible human action lead to."""
    out = set()
    for r in world.feasible_indices(state, Agent.ROBOT):
        mid, _, _ = world.table.successor(state, Agent.ROBOT, r)
        for h in world.feasible_indices(mid, Agent.HUMAN):
            out.add(world.table.successor(mid, Agent.HUMAN, h)[0])
    return out


def test_a_table_that_draws_no_cycle_is_left_as_it_was_and_one_cycle_is_one_cycle() -> None:
    world = World("paper2015")
    n = 24
    states = [world.initial_state(np.random.default_rng(s)) for s in range(n)]
    assert not any(world.is_clean(s) for s in states)  # none is re-drawn for being clean
    env = SimpleNamespace(state=BatchState.of(states), _stale=np.zeros(n, dtype=bool))
    partner = CoveragePartner(world, _Member(), cycles=2)
    partner.attach(env)
    rows = np.arange(n)
    partner.reset_rows(rows, np.random.default_rng(3))
    drawn = np.random.default_rng(3).integers(2, size=n)
    assert set(drawn.tolist()) == {0, 1}
    after = [env.state.state(i) for i in range(n)]
    for i in range(n):
        if drawn[i] == 0:
            assert after[i] == states[i], i
        elif not world.is_clean(after[i]):
            assert after[i] in one_cycle(world, states[i]), i
    assert env._stale.all()


def test_fcp_init_draws_the_random_checkpoint_too_and_fcp_does_not() -> None:
    """FCP's pool holds each partner at its end, half way, early (eps 0, 0.3, 0.6); ``fcp_init``
    adds its start, a uniformly random policy (eps 1.0). Each table draws one level per reset,
    uniformly: drawn here from the same seed by hand."""
    from hg_marl.training.baselines.recipes import recipe_partner

    world = World("paper2015")
    rows = np.arange(400)
    expected = {"fcp": (0.0, 0.3, 0.6), "fcp_init": (0.0, 0.3, 0.6, 1.0)}
    for recipe, levels in expected.items():
        partner = recipe_partner(world, ("random",), recipe, None)
        partner.reset_rows(rows, np.random.default_rng(5))
        by_hand = np.array(levels)[np.random.default_rng(5).integers(len(levels), size=len(rows))]
        assert partner.eps.tolist() == by_hand.tolist(), recipe
        assert set(partner.eps.tolist()) == set(levels), recipe
