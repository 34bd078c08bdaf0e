"""The half-step search agrees with the core's rules and with the joint-cycle reference search."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig, make_human_model
from hg_marl.agents.planner.costs import cycle_cost, cycle_terms
from hg_marl.agents.planner.halfstep import astar
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, World
from tests.agents import joint_search

SCENARIOS = [
    "paper2015",
    "roboergosum",
    "generated:objects=3,seed=1,human_only=0.8",
    "generated:objects=3,seed=2,bins=2,locations=3",
]


@pytest.mark.parametrize("model", ["cooperative", "no_handover", "lazy"])
@pytest.mark.parametrize("scenario", SCENARIOS)
def test_candidates_are_feasible_and_cover_every_object_move(scenario: str, model: str) -> None:
    """Candidates are feasible (core rules), end with wait, and the table's fast successor
    equals ``World.step``; a robot holding nothing always has a move or a goto."""
    world = World(scenario)
    planner = Planner(world, human_model=make_human_model(model))
    space = planner.space
    frontier = [world.initial_state(np.random.default_rng(s)) for s in range(3)]
    seen = set(frontier)
    while frontier and len(seen) < 1500:
        s = frontier.pop()
        for agent in Agent:
            cands = space.candidates(s, agent)
            assert cands[-1] == world.n_actions(agent) - 1
            assert set(cands) <= set(world.feasible_indices(s, agent))
            for i in cands:
                out = world.step(s, agent, i)
                assert out.ok
                assert world.table.successor_feasible(s, agent, i) == (out.state, out.duration)
                if out.state not in seen:
                    seen.add(out.state)
                    frontier.append(out.state)


def test_cycle_cost_is_the_weighted_sum_of_the_cycle_terms() -> None:
    weights = CostWeights(time=1.0, human_effort=0.3, effort_balance=0.7, human_idle=0.11, human_holding=0.13)
    for d_r, a_r, d_h, a_h, hold in [
        (2.0, True, 1.5, True, False),
        (0.0, False, 2.0, True, True),
        (3.0, True, 1.0, False, True),
    ]:
        expected = weights.total(cycle_terms(d_r, a_r, d_h, a_h, hold))
        assert cycle_cost(weights.vector, d_r, a_r, d_h, a_h, hold) == pytest.approx(expected)


@pytest.mark.parametrize("weights", [CostWeights(), CostWeights.time_only()], ids=["default", "time_only"])
@pytest.mark.parametrize("scenario", [*SCENARIOS[:3], "generated:objects=6,seed=2,human_only=0.8"])
def test_same_cost_as_joint_cycle_search(scenario: str, weights: CostWeights) -> None:
    world = World(scenario)
    for model in ("cooperative", "no_handover", "lazy"):
        planner = Planner(world, PlannerConfig(weights=weights), human_model=make_human_model(model))
        for seed in range(3):
            state = world.initial_state(np.random.default_rng(seed))
            a = joint_search.astar(planner.space, state, Agent.ROBOT, (0.0, -1), 200_000)
            b = astar(planner.space, state, Agent.ROBOT, (0.0, -1), 200_000)
            assert (a.cycles is None) == (b.cycles is None)
            if a.cycles is not None:
                assert b.cost == pytest.approx(a.cost, abs=1e-9)
                # mid-cycle start: the robot's first planned action under way
                mid = world.step(state, Agent.ROBOT, a.cycles[0][0]).state
                part = (world.step(state, Agent.ROBOT, a.cycles[0][0]).duration, a.cycles[0][0])
                a2 = joint_search.astar(planner.space, mid, Agent.HUMAN, part, 200_000)
                b2 = astar(planner.space, mid, Agent.HUMAN, part, 200_000)
                assert b2.cost == pytest.approx(a2.cost, abs=1e-9)


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum"])
def test_intent_answers_like_a_full_plan(scenario: str) -> None:
    """``Planner.intent`` (no Plan built) gives the actions, duration and cost of ``plan``
    (on canonical states, where no relabelling happens)."""
    world = World(scenario)
    config = PlannerConfig(cache_suffixes=False)
    relabel = Relabel(world)
    for seed in range(3):
        state, _ = relabel.canonical(world.initial_state(np.random.default_rng(seed)))
        for to_move, robot_action in ((Agent.ROBOT, None), (Agent.HUMAN, None), (Agent.HUMAN, 0)):
            full = Planner(World(scenario), config).plan(state, to_move, robot_action=robot_action)
            light = Planner(World(scenario), config).intent(state, to_move, robot_action=robot_action)
            assert full.plan is not None
            assert (light.robot_action, light.human_action) == (full.robot_action, full.human_action)
            assert light.duration == pytest.approx(full.plan.duration)
            assert light.cost == pytest.approx(full.cost)


def test_planners_of_one_world_share_their_space() -> None:
    world = World("paper2015")
    assert Planner(world).space is Planner(world, PlannerConfig(cache_size=0)).space
    assert Planner(world).space is not Planner(world, human_model=make_human_model("lazy")).space
    assert Planner(world).space is not Planner(World("paper2015")).space


@pytest.mark.parametrize("scenario", ["roboergosum", "paper2015"])
def test_intent_on_a_relabelled_state_is_optimal_and_feasible(scenario: str) -> None:
    """Answering for the canonical relabelling keeps the answer feasible and optimal: the
    proposed human action followed by the plan from there costs what a full plan costs."""
    world = World(scenario)
    planner = Planner(world, PlannerConfig(cache_suffixes=False))
    reference = Planner(World(scenario), PlannerConfig(cache_suffixes=False, cache_size=0))
    rng = np.random.default_rng(7)
    state = world.initial_state(rng)
    for _ in range(12):
        ar = int(rng.choice(world.feasible_indices(state, Agent.ROBOT)))
        mid = world.step(state, Agent.ROBOT, ar).state
        intent = planner.intent(mid, Agent.HUMAN, robot_action=ar)
        full = reference.plan(mid, Agent.HUMAN, robot_action=ar)
        assert intent.success == full.success
        if not full.success:
            break
        assert world.mask(mid, Agent.HUMAN)[intent.human_action]
        assert intent.cost == pytest.approx(full.cost)
        state = world.step(mid, Agent.HUMAN, intent.human_action).state
        if world.is_clean(state):
            break
