"""The half-step search's compiled parts agree with the core and with the joint-cycle search."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig, make_human_model, search
from hg_marl.agents.planner.halfstep import Candidates, Transitions, astar
from hg_marl.core import Agent, World

SCENARIOS = [
    "paper2015",
    "roboergosum",
    "generated:objects=3,seed=1,human_only=0.8",
    "generated:objects=3,seed=2,bins=2,locations=3",
]


@pytest.mark.parametrize("model", ["cooperative", "no_handover", "lazy"])
@pytest.mark.parametrize("scenario", SCENARIOS)
def test_compiled_candidates_and_transitions_match(scenario: str, model: str) -> None:
    world = World(scenario)
    planner = Planner(world, human_model=make_human_model(model))
    cands, trans = Candidates(planner.space), Transitions(planner.space)
    frontier = [world.initial_state(np.random.default_rng(s)) for s in range(3)]
    seen = set(frontier)
    while frontier and len(seen) < 1500:
        s = frontier.pop()
        for agent in Agent:
            expected = planner.space.candidates(s, agent)
            assert cands(s, agent) == expected
            for i in expected:
                out = world.step(s, agent, i)
                assert out.ok
                assert trans.apply(s, agent, i) == (out.state, out.duration)
                if out.state not in seen:
                    seen.add(out.state)
                    frontier.append(out.state)


@pytest.mark.parametrize("weights", [CostWeights(), CostWeights.time_only()], ids=["default", "time_only"])
@pytest.mark.parametrize("scenario", [*SCENARIOS[:3], "generated:objects=6,seed=2,human_only=0.8"])
def test_same_cost_as_joint_cycle_search(scenario: str, weights: CostWeights) -> None:
    world = World(scenario)
    for model in ("cooperative", "no_handover", "lazy"):
        planner = Planner(world, PlannerConfig(weights=weights), human_model=make_human_model(model))
        for seed in range(3):
            state = world.initial_state(np.random.default_rng(seed))
            a = search.astar(planner.space, state, Agent.ROBOT, (0.0, -1), 200_000)
            b = astar(planner.space, state, Agent.ROBOT, (0.0, -1), 200_000)
            assert (a.cycles is None) == (b.cycles is None)
            if a.cycles is not None:
                assert b.cost == pytest.approx(a.cost, abs=1e-9)
                # mid-cycle start: the robot's first planned action under way
                mid = world.step(state, Agent.ROBOT, a.cycles[0][0]).state
                part = (world.step(state, Agent.ROBOT, a.cycles[0][0]).duration, a.cycles[0][0])
                a2 = search.astar(planner.space, mid, Agent.HUMAN, part, 200_000)
                b2 = astar(planner.space, mid, Agent.HUMAN, part, 200_000)
                assert b2.cost == pytest.approx(a2.cost, abs=1e-9)
