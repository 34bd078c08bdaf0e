"""The compiled rule table agrees with the naive reference rules on random states, every action."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hg_marl.core import Agent, State, World
from tests.core import reference_rules as ref

SCENARIOS = [
    "paper2015",
    "roboergosum",
    "generated:objects=4,seed=3,bins=2,locations=3",
    "generated:objects=3,seed=5,human_only=0.8",
]
_WORLDS = {name: World(name) for name in SCENARIOS}


@st.composite
def states(draw: st.DrawFn, world: World) -> State:
    """Any state the encoding allows: objects on spots, in bins or in hands (one per hand), any offer."""
    n, places = world.n_objects, world.n_spots + world.n_bins + 2
    where = draw(st.lists(st.integers(0, places - 1), min_size=n, max_size=n))
    for hand in world.hand:  # a hand holds at most one object
        holders = [o for o, p in enumerate(where) if p == hand]
        for o in holders[1:]:
            where[o] = 0
    at = draw(st.integers(0, len(world.scenario.robot_locations) - 1))
    by = draw(st.sampled_from([-1, 0, 1]))
    obj = draw(st.integers(0, n - 1)) if by >= 0 else -1
    return State(tuple(where), at, by, obj)


@pytest.mark.parametrize("name", SCENARIOS)
def test_table_matches_reference_rules(name: str) -> None:
    world = _WORLDS[name]
    sc = world.scenario

    @settings(max_examples=150, deadline=None)
    @given(state=states(world))
    def check(state: State) -> None:
        for agent in Agent:
            feasible = []
            for i, action in enumerate(world.actions(agent)):
                ok = ref.feasible(sc, state, agent, action)
                assert world.table.feasible(state, agent, i) == ok, (state, agent, action)
                expected, expected_ok = ref.successor(sc, state, agent, action)
                nxt, got_ok, duration = world.table.successor(state, agent, i)
                assert (nxt, got_ok) == (expected, expected_ok), (state, agent, action)
                assert duration == world.durations.of(action.kind, ok)
                step = world.step(state, agent, i)
                assert (step.state, step.ok) == (expected, expected_ok)
                assert step.reward == (
                    1.0
                    if ok and agent is Agent.ROBOT and action.kind.name == "WAIT" and ref.is_clean(sc, state)
                    else 0.0
                )
                if ok:
                    feasible.append(i)
                    assert world.table.successor_feasible(state, agent, i) == (nxt, duration)
            assert world.feasible_indices(state, agent) == feasible
            assert list(world.mask(state, agent).nonzero()[0]) == feasible
        assert world.is_clean(state) == ref.is_clean(sc, state)
        assert world.compute_facts(state).tolist() == ref.facts(sc, state)

    check()
