"""Property tests: random action sequences, infeasible ones included, keep the invariants."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from hg_marl.core import Agent, Kind, State, World

WORLDS = {name: World(name) for name in ("paper2015", "roboergosum", "generated:objects=5,locations=3,bins=2,seed=1")}


def check_invariants(world: World, state: State) -> None:
    places = state.where
    # each object in exactly one place, and a valid one
    assert len(places) == world.n_objects
    assert all(0 <= p <= world.hand[Agent.HUMAN] for p in places)
    # no agent holds two objects
    assert sum(p == world.hand[Agent.ROBOT] for p in places) <= 1
    assert sum(p == world.hand[Agent.HUMAN] for p in places) <= 1
    # at most one object per spot
    on_spots = [p for p in places if p < world.n_spots]
    assert len(on_spots) == len(set(on_spots))
    # an object in a bin is in its own bin
    for o, p in enumerate(places):
        if world.is_in_bin(p):
            assert p == world.n_spots + world.bin_of[o]
    # a pending offer is of an object the giver holds
    if state.offer_by >= 0:
        assert places[state.offer_obj] == world.hand[state.offer_by]


@settings(max_examples=60, deadline=None)
@given(
    name=st.sampled_from(sorted(WORLDS)),
    seed=st.integers(0, 2**31),
    actions=st.lists(st.floats(0, 1, exclude_max=True), min_size=1, max_size=300),
    feasible_share=st.floats(0, 1),
)
def test_random_sequences_keep_invariants(name: str, seed: int, actions: list[float], feasible_share: float) -> None:
    world = WORLDS[name]
    rng = np.random.default_rng(seed)
    state = world.initial_state(rng)
    clock = 0.0
    for i, u in enumerate(actions):
        agent = Agent(i % 2)
        if u < feasible_share:
            legal = world.feasible_indices(state, agent)
            index = legal[int(u / max(feasible_share, 1e-9) * len(legal)) % len(legal)]
        else:
            index = int(u * world.n_actions(agent))
        out = world.step(state, agent, index)
        assert out.duration > 0
        clock_next = clock + out.duration
        assert clock_next > clock, "the clock never goes back"
        clock = clock_next
        assert out.ok == bool(world.mask(state, agent)[index]), "the mask marks exactly the feasible actions"
        if not out.ok:
            # no effect besides a lapsing offer
            assert out.state.where == state.where and out.state.robot_at == state.robot_at
        state = world.initial_state(rng) if out.reward else out.state
        check_invariants(world, state)


@settings(max_examples=40, deadline=None)
@given(name=st.sampled_from(sorted(WORLDS)), seed=st.integers(0, 2**31), steps=st.integers(1, 200))
def test_fast_mask_matches_preconditions(name: str, seed: int, steps: int) -> None:
    world = WORLDS[name]
    rng = np.random.default_rng(seed)
    state = world.initial_state(rng)
    for i in range(steps):
        agent = Agent(i % 2)
        cleared = state._replace(offer_by=-1, offer_obj=-1) if state.offer_by == agent.other else state
        reference = [
            j
            for j, a in enumerate(world.actions(agent))
            if world.feasible(state if a.kind is Kind.TAKE and a.obj == state.offer_obj else cleared, agent, a)
        ]
        assert world.feasible_indices(state, agent) == reference
        legal = world.feasible_indices(state, agent)
        out = world.step(state, agent, int(rng.choice(legal)))
        state = world.initial_state(rng) if out.reward else out.state
