"""The planner's compiled inner loop against the rules it was compiled from.

:class:`Steps` must give what ``RuleTable.successor_feasible`` gives for every feasible
action, and :class:`ExactSums` what ``math.fsum`` gives over the bound's tables, on every
state of seeded random walks (both agents, offers included) and on a hand-made table whose
plain left-to-right sum is known to differ from the exactly rounded one.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig
from hg_marl.agents.planner.exactsum import ExactSums
from hg_marl.agents.planner.plan import build_plan
from hg_marl.agents.planner.space import Space
from hg_marl.agents.planner.steps import Steps
from hg_marl.agents.planner.tables import candidate_entries
from hg_marl.core import Agent, Kind, State, World

SCENARIOS = ("paper2015", "roboergosum", "generated:objects=6,human_only=0.8,seed=1")


def walk(world: World, seed: int, length: int) -> list[State]:
    """States of a seeded random walk, the agents alternating."""
    rng = np.random.default_rng(seed)
    state = world.initial_state(rng)
    out = [state]
    agent = Agent.ROBOT
    for _ in range(length):
        acts = world.feasible_indices(state, agent)
        state = world.step(state, agent, int(acts[int(rng.integers(len(acts)))])).state
        out.append(state)
        agent = Agent.HUMAN if agent is Agent.ROBOT else Agent.ROBOT
    return out


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_steps_equal_successor_feasible(scenario: str) -> None:
    world = World(scenario)
    steps = Steps(world.table)
    checked = 0
    for seed in range(4):
        for state in walk(world, seed, 30):
            for agent in Agent:
                for index in world.feasible_indices(state, agent):
                    assert steps.apply(state, agent, index) == world.table.successor_feasible(state, agent, index)
                    checked += 1
    assert checked > 500


def per_entry_candidates(space: Space, state: State, agent: int) -> tuple[int, ...]:
    """The candidates as first written: every tabulated entry of every object tested by its kind.

    A pick or a take passes with the hand empty (a pick once per symmetry signature, a
    take of the partner's offered object), a place, throw or give with the object in the
    hand (a place once per signature, on a free spot); then the robot's gotos, one per
    destination; sorted, ``wait`` last.
    """
    where, at, by, obj = state
    hand = space.table.hand[agent]
    statuses = list(where)
    if obj >= 0:
        statuses[obj] = space.domain.human_offer if by == 1 else space.domain.robot_offer
    empty = hand not in where
    seen: set[object] = set()
    out: list[int] = []
    for o, st in enumerate(statuses):
        for kind, i, sig, spot in candidate_entries(space)[agent][at][o][st]:
            if kind is Kind.PICK:
                ok = empty and sig not in seen
            elif kind is Kind.TAKE:
                ok = empty and 0 <= by != agent and obj == o
            elif kind is Kind.PLACE:
                ok = where[o] == hand and sig not in seen and spot not in where
            else:
                ok = where[o] == hand
            if ok:
                if sig is not None:
                    seen.add(sig)
                out.append(i)
    if agent == 0:
        dests: set[int] = set()
        goto = space.table.action_index(0, Kind.GOTO, target=0)
        for t, p in enumerate(where):
            dest = space.table.goto_obj[at][p]
            if dest >= 0 and dest not in dests:
                dests.add(dest)
                out.append(goto + t)
        for k, dest in enumerate(space.table.goto_static[at]):
            if dest >= 0 and dest not in dests:
                dests.add(dest)
                out.append(goto + space.world.n_objects + k)
    return (*sorted(out), space.wait[agent])


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_candidates_by_the_hands_content_equal_every_entry_tested_by_its_kind(scenario: str) -> None:
    """The candidates read per what the hand holds (:func:`split_entries`) are those of
    the per-entry reference, on walks that pass through both agents' offers; each is feasible."""
    world = World(scenario)
    space = Planner(world, PlannerConfig()).space
    offers = checked = 0
    for seed in range(6):
        for state in walk(world, seed, 40):
            offers += state.offer_by >= 0
            for agent in Agent:
                got = space._candidates(state, agent)
                assert got == per_entry_candidates(space, state, agent), (state, agent)
                assert set(got) <= set(world.feasible_indices(state, agent))
                checked += 1
    assert checked > 400 and offers > 0


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("weights", [CostWeights(), CostWeights(0.1, 0.3, 0.7, 1 / 3, 0.01)])
def test_packed_sums_equal_fsum(scenario: str, weights: CostWeights) -> None:
    world = World(scenario)
    space = Planner(world, PlannerConfig(weights=weights)).space
    assert space._exact.packed is not None
    d = space.domain
    for seed in range(4):
        for state in walk(world, seed, 30):
            statuses = space.statuses(state)
            tabs = space.tables if state.offer_by != 0 else space.offer_tables
            expected = tuple(math.fsum(tab[state.robot_at][o][st] for o, st in enumerate(statuses)) for tab in tabs)
            got = space._exact.sums(state.offer_by == 0, state.robot_at, statuses)
            status = statuses[state.offer_obj] if state.offer_obj >= 0 else 0
            places = space._exact.of_places(state.offer_by == 0, state.robot_at, state.where, state.offer_obj, status)
            if math.inf in expected:
                assert got is None and places is None
            else:
                assert got == expected == places, state
            assert d.n_status > max(statuses)


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_the_fsum_path_gives_the_packed_sums(scenario: str) -> None:
    # two implementations of one number: fsum over the tables (the path for tables that do
    # not pack) and the packed integer sum; besides the walks' states, each agent offering
    # the first object from its hand
    world = World(scenario)
    packed = Planner(world).space
    fallback = Planner(World(scenario)).space  # a space of its own (spaces are per world)
    fallback._exact.packed = None
    checked = 0
    for seed in range(6):
        for state in walk(world, seed, 40):
            offered = [State((world.hand[agent], *state.where[1:]), state.robot_at, int(agent), 0) for agent in Agent]
            for s in (state, *offered):
                assert fallback.sums(s) == packed.sums(s), s
                checked += packed.sums(s) is not None
    assert checked > 200


def test_packed_sums_are_exactly_rounded_on_a_hand_made_table() -> None:
    # one location, three objects with one status each; 0.1 + 0.2 + 0.3 is 0.6000000000000001
    # summed left to right, 0.6 exactly rounded (what fsum gives)
    plain = [[[[0.1], [0.2], [0.3]]], [[[1e-3], [2.5], [math.inf]]]]
    exact = ExactSums(plain, plain, 3)
    assert 0.1 + 0.2 + 0.3 != 0.6
    assert exact.sums(False, 0, [0, 0, 0]) is None  # an infinite value: a dead end
    two = ExactSums([[[[0.1], [0.2], [0.3]]]], [[[[0.1], [0.2], [0.3]]]], 3)
    assert two.sums(False, 0, [0, 0, 0]) == (0.6,)
    assert two.sums(True, 0, [0, 0, 0]) == (0.6,)


def test_the_places_form_swaps_the_offered_objects_term_exactly() -> None:
    # two objects, statuses 0..2; object 1 offered (status 2) instead of at its place (0):
    # 0.1 + 0.3 exactly rounded; an infinite place swapped out is no dead end, one swapped in is
    tabs = [[[[0.1, 0.2, 0.7], [0.25, math.inf, 0.3]]]]
    exact = ExactSums(tabs, tabs, 2)
    assert exact.of_places(False, 0, (0, 0), 1, 2) == (math.fsum([0.1, 0.3]),)
    assert exact.of_places(False, 0, (1, 1), 1, 2) == (math.fsum([0.2, 0.3]),)
    assert exact.of_places(False, 0, (1, 1), -1, 2) is None
    assert exact.of_places(False, 0, (2, 0), 0, 1) == (math.fsum([0.2, 0.25]),)


@pytest.mark.parametrize(
    ("values", "fields"),
    [
        ((0.1, 0.2, 0.3, 0.7, 1.5, 2.25), True),  # every field within 64 bits: read back with struct
        ((1.0, 2.0**-60, 0.3, 7.0, 0.1, 0.5), False),  # 2**-60 beside 7: fields of 114 bits
        ((5e-324, 1e-310, 2.5e-320, 3e-315, 1e-300, 4e-308), False),  # 2**exp below the normal floats
        ((1e-300, 3e-301, 7e-302, 2e-300, 5e-301, 1e-299), True),  # 2**exp a subnormal float: still exact
        ((5e-324, 1e-323, 1.5e-323, 2e-323, 5e-324, 1e-323), True),  # subnormals only: narrow fields, 2**exp not normal
    ],
)
def test_five_weights_give_fsum_exactly_whatever_the_fields_width(values: tuple[float, ...], fields: bool) -> None:
    # five weights (the bound's), three objects with two statuses each, one location; every
    # sum stated as fsum over the chosen values, on each packing path
    tabs = [[[[values[(k + o) % 6], values[(k + 2 * o + 1) % 6]] for o in range(3)]] for k in range(5)]
    exact = ExactSums(tabs, tabs, 3)
    assert exact.packed is not None and exact.fields is fields
    for where in [(0, 0, 0), (1, 0, 1), (1, 1, 1), (0, 1, 0)]:
        expected = tuple(math.fsum(tabs[k][0][o][st] for o, st in enumerate(where)) for k in range(5))
        assert exact.of_places(False, 0, where, -1, 0) == expected, where
        assert exact.sums(True, 0, list(where)) == expected, where
        swapped = (where[0], 1 - where[1], where[2])  # object 1 "offered" in its other status
        expected = tuple(math.fsum(tabs[k][0][o][st] for o, st in enumerate(swapped)) for k in range(5))
        assert exact.of_places(False, 0, where, 1, swapped[1]) == expected, where


@pytest.mark.parametrize("scenario", [*SCENARIOS, "generated:objects=8,bins=2"])
def test_canonical_keys_are_equal_exactly_for_states_equal_up_to_symmetry(scenario: str) -> None:
    # the symmetry, stated from its definition: objects of one bin class are interchangeable,
    # and so are spots of one reach class; a state up to symmetry is the multiset of
    # (reach class of the place, bin class of the object), with the robot's place and the offerer
    world = World(scenario)
    space = Planner(world).space
    assert space.symmetric
    seen: dict[object, object] = {}
    for seed in range(6):
        for state in walk(world, seed, 40):
            classes = sorted((space.place_code[p], space.object_class[o]) for o, p in enumerate(state.where))
            up_to_symmetry = (tuple(classes), state.robot_at, state.offer_by)
            assert seen.setdefault(space.key(state), up_to_symmetry) == up_to_symmetry, state
    assert len(set(seen.values())) == len(seen) > 20


@pytest.mark.parametrize("symmetric", [True, False])
@pytest.mark.parametrize("scenario", SCENARIOS)
def test_a_human_nodes_key_is_equal_exactly_for_equal_mid_states_durations_and_activity(
    scenario: str, symmetric: bool
) -> None:
    # the search merges two robot moves into one human node when the mid-cycle states are
    # equal up to symmetry and the robot's part of the cycle lasts as long and is as active;
    # a layout without symmetries keys on the states themselves (forced here on a fresh space)
    world = World(scenario)
    space = Planner(world).space
    space.symmetric = symmetric
    wait_r = world.n_actions(Agent.ROBOT) - 1
    seen: dict[object, object] = {}
    for seed in range(4):
        for state in walk(world, seed, 30):
            for edge in space.robot_edges(state):
                identity = (space.key(edge.state), edge.duration, edge.action != wait_r)
                assert seen.setdefault(edge.key, identity) == identity, (state, edge)
    assert len(set(seen.values())) == len(seen) > 20


def test_a_world_with_a_planner_is_freed_when_its_last_user_lets_it_go() -> None:
    # the world holds its planners' shared space; the space must not hold the world back,
    # or every world that planned would wait for the cycle collector
    import gc
    import weakref

    enabled = gc.isenabled()
    gc.disable()
    try:
        world = World("paper2015")
        planner = Planner(world)
        assert planner.plan(world.initial_state(np.random.default_rng(0))).plan is not None
        alive = weakref.ref(world)
        del world, planner
        assert alive() is None
    finally:
        if enabled:
            gc.enable()


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_the_search_keys_and_sums_successors_as_the_space_does(scenario: str) -> None:
    # twice over the same states: the second pass reads the sums from the memo
    world = World(scenario)
    space = Planner(world).space
    fresh = Planner(World(scenario)).space  # no memo shared with ``space``
    for _ in range(2):
        for seed in range(3):
            for state in walk(world, seed, 20):
                for agent in Agent:
                    acts = tuple(int(a) for a in world.feasible_indices(state, agent))
                    for _, nxt, _, key, sums in space._successors(state, int(agent), acts):
                        assert key == space.key(nxt)
                        assert sums == fresh.sums(nxt)


def test_negative_values_keep_to_fsum() -> None:
    exact = ExactSums([[[[-1.0], [2.0]]]], [[[[-1.0], [2.0]]]], 2)
    assert exact.packed is None


def test_values_too_far_apart_to_scale_keep_to_fsum() -> None:
    # the least subnormal (2**-1074) and 1e10 (about 2**33): scaling 1e10 by 2**1126 to an
    # integer is past the largest float (about 2**1024), so the tables keep to fsum, and a
    # planner whose weights give such tables (CostWeights accepts a time weight of 5e-324)
    # plans like any other instead of raising OverflowError
    tabs = [[[[5e-324, 1e10]]]]
    assert ExactSums(tabs, tabs, 1).packed is None
    assert ExactSums([[[[2.0**-60, 1e10]]]], [[[[2.0**-60, 1e10]]]], 1).packed is not None  # 2**94 apart: packs
    # the time weight is then far below an ulp of the effort sums, so the plan is the one a
    # time weight of 2**-900 gives, whose tables (2**-952 to about 2**7) still pack
    plans = []
    for time in (5e-324, 2.0**-900):
        world = World("paper2015")
        planner = Planner(world, PlannerConfig(weights=CostWeights(time=time, human_effort=1.0, human_idle=0.0)))
        assert (planner.space._exact.packed is None) == (time == 5e-324)
        result = planner.plan(world.initial_state(np.random.default_rng(0)))
        assert result.success
        plans.append((result.robot_action, result.cost))
    assert plans[0] == plans[1]


@pytest.mark.parametrize("scenario", ["paper2015", "generated:objects=5,human_only=0.8,seed=1"])
def test_a_plan_from_the_search_path_is_the_plan_a_replay_builds(scenario: str) -> None:
    # the search hands its path's states to build_plan instead of a replay; the plan must be
    # the one replaying its cycles with the rule table gives: states, mid-cycle states,
    # durations and terms, from robot-turn and human-turn starts
    world = World(scenario)
    planner = Planner(world, PlannerConfig(cache_size=0))
    compared = 0
    for seed in range(3):
        states = walk(world, seed, 16)
        for state in states[::2]:
            starts = [(state, Agent.ROBOT, None)]
            for ra in world.feasible_indices(state, Agent.ROBOT)[:2]:
                starts.append((world.table.successor(state, Agent.ROBOT, ra)[0], Agent.HUMAN, ra))
            for root, to_move, ra in starts:
                result = planner.plan(root, to_move, robot_action=ra)
                if result.plan is None:
                    continue
                plan = result.plan
                part = (0.0, -1) if ra is None else (world.durations.of(world.actions(Agent.ROBOT)[ra].kind), ra)
                replay = build_plan(world, root, to_move, list(plan.cycles), part)
                assert plan == replay
                assert (plan.mids, plan.durations) == (replay.mids, replay.durations)
                assert len(plan.mids) == len(plan.cycles) == len(plan.states) - 1
                compared += 1
    assert compared > 20
