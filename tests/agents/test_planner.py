"""The planner: optimality against exhaustive search, executability, failures, determinism."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_planner_reference import execute, initial_states, reference_cost, reference_price

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig
from hg_marl.core import Agent, State, World

SMALL = (
    [f"generated:objects={n},seed={seed}" for n in (1, 2, 3) for seed in range(8)]
    + [f"generated:objects={n},seed={seed},human_only=0.8" for n in (2, 3) for seed in range(6)]
    + [f"generated:objects=3,seed={seed},bins=2,locations=3" for seed in range(4)]
)
WEIGHTS = {"default": CostWeights(), "time_only": CostWeights.time_only()}


def check_plan(world: World, planner: Planner, state: State, result, to_move=Agent.ROBOT, robot_part=(0.0, -1)):  # type: ignore[no-untyped-def]
    """The plan runs with World.step, completes, and takes the time and cost it predicted."""
    assert result.success, result.reason
    plan = result.plan
    clock, parts, reward = execute(world, plan.cycles, state, robot_part)
    assert reward == 1.0, "the last robot action must complete the task"
    assert clock == pytest.approx(plan.duration)
    weights = planner.config.weights
    cost = sum(reference_price(weights, p) for p in parts)
    assert cost == pytest.approx(result.cost)
    assert sum(result.breakdown.values()) == pytest.approx(result.cost)
    assert result.breakdown["time"] == pytest.approx(weights.time * plan.duration)


@pytest.mark.parametrize("weights", WEIGHTS.values(), ids=WEIGHTS.keys())
@pytest.mark.parametrize("scenario", SMALL)
def test_optimal_on_small_generated(scenario: str, weights: CostWeights) -> None:
    world = World(scenario)
    planner = Planner(world, PlannerConfig(weights=weights))
    for state in initial_states(world, range(3)):
        result = planner.plan(state)
        expected = reference_cost(world, state, weights)
        if math.isinf(expected):
            assert not result.success and result.reason
            continue
        check_plan(world, planner, state, result)
        assert result.cost == pytest.approx(expected), scenario
        assert result.optimal


@pytest.mark.parametrize("weights", WEIGHTS.values(), ids=WEIGHTS.keys())
def test_optimal_on_paper2015(weights: CostWeights) -> None:
    world = World("paper2015")
    planner = Planner(world, PlannerConfig(weights=weights))
    for state in initial_states(world, range(12)):
        result = planner.plan(state)
        check_plan(world, planner, state, result)
        assert result.cost == pytest.approx(reference_cost(world, state, weights))


def random_walk(world: World, state: State, rng: np.random.Generator, cycles: int) -> list[tuple[State, Agent, int]]:
    """Mid-task situations: (state, to_move, robot action under way) along random feasible play."""
    out: list[tuple[State, Agent, int]] = []
    for _ in range(cycles):
        if world.is_clean(state):
            break
        ar = int(rng.choice(world.feasible_indices(state, Agent.ROBOT)))
        state = world.step(state, Agent.ROBOT, ar).state
        out.append((state, Agent.HUMAN, ar))
        ah = int(rng.choice(world.feasible_indices(state, Agent.HUMAN)))
        state = world.step(state, Agent.HUMAN, ah).state
        out.append((state, Agent.ROBOT, -1))
    return out


MID = (
    [f"generated:objects=3,seed={seed}" for seed in range(6)]
    + [f"generated:objects=3,seed={seed},human_only=0.8" for seed in range(4)]
    + ["paper2015"]
)


@pytest.mark.parametrize("scenario", MID)
def test_optimal_mid_task(scenario: str) -> None:
    """From states with objects in hands and pending offers, at either agent's turn."""
    world = World(scenario)
    planner = Planner(world)
    weights = planner.config.weights
    rng = np.random.default_rng(7)
    seen_offer = seen_hand = 0
    for start in initial_states(world, range(2)):
        for state, to_move, ar in random_walk(world, start, rng, 12):
            seen_offer += state.offer_by >= 0
            seen_hand += any(p in world.hand for p in state.where)
            ra = ar if to_move is Agent.HUMAN else None
            result = planner.plan(state, to_move, robot_action=ra)
            part = (0.0, -1)
            if ra is not None:
                part = (world.durations.of(world.actions(Agent.ROBOT)[ra].kind), ra)
            expected = reference_cost(world, state, weights, to_move=to_move, robot_part=part)
            if math.isinf(expected):
                assert not result.success
                continue
            check_plan(world, planner, state, result, to_move, part)
            assert result.cost == pytest.approx(expected)
    assert seen_hand > 0
    if scenario == MID[0]:
        assert seen_offer > 0, "this walk passes through pending offers"


FOUR = [f"generated:objects=4,seed={seed}" for seed in range(3)] + [
    f"generated:objects=4,seed={seed},human_only=0.8" for seed in range(2)
]


@pytest.mark.parametrize("weights", WEIGHTS.values(), ids=WEIGHTS.keys())
@pytest.mark.parametrize("scenario", FOUR)
def test_optimal_four_objects(scenario: str, weights: CostWeights) -> None:
    world = World(scenario)
    planner = Planner(world, PlannerConfig(weights=weights))
    state = world.initial_state(np.random.default_rng(0))
    result = planner.plan(state)
    check_plan(world, planner, state, result)
    assert result.cost == pytest.approx(reference_cost(world, state, weights))


@pytest.mark.slow
@pytest.mark.parametrize("weights", WEIGHTS.values(), ids=WEIGHTS.keys())
@pytest.mark.parametrize(
    "scenario",
    [f"generated:objects=4,seed={seed}" for seed in range(3, 12)]
    + [f"generated:objects=4,seed={seed},human_only=0.8,bins=2" for seed in range(6)],
)
def test_optimal_four_objects_many_seeds(scenario: str, weights: CostWeights) -> None:
    world = World(scenario)
    planner = Planner(world, PlannerConfig(weights=weights))
    for state in initial_states(world, range(3)):
        result = planner.plan(state)
        expected = reference_cost(world, state, weights)
        if math.isinf(expected):
            assert not result.success
            continue
        check_plan(world, planner, state, result)
        assert result.cost == pytest.approx(expected)


@pytest.mark.slow
@pytest.mark.parametrize(("seed", "weights"), [(0, "default"), (1, "time_only"), (2, "default")])
def test_optimal_on_roboergosum(seed: int, weights: str) -> None:
    """The file's slowest cases: the exhaustive reference explores every joint cycle.

    Three layouts, each weighting on at least one (every seed with every weighting
    doubled the slow stage's longest tests for the same check on the same table).
    """
    world = World("roboergosum")
    planner = Planner(world, PlannerConfig(weights=WEIGHTS[weights]))
    state = world.initial_state(np.random.default_rng(seed))
    result = planner.plan(state)
    check_plan(world, planner, state, result)
    assert result.cost == pytest.approx(reference_cost(world, state, WEIGHTS[weights]))


@pytest.mark.parametrize("seed", range(6))
def test_roboergosum_plans_execute(seed: int) -> None:
    world = World("roboergosum")
    planner = Planner(world)
    state = world.initial_state(np.random.default_rng(seed))
    check_plan(world, planner, state, planner.plan(state))


@pytest.mark.parametrize(
    ("setting", "value"),
    [
        ("value_tolerance", -1e-9),
        ("value_tolerance", math.nan),
        ("value_tolerance", math.inf),
        ("max_sweeps", 0),
        ("node_budget", 0),
        ("cache_size", -1),
    ],
)
def test_search_settings_no_search_can_use_are_refused(setting: str, value: float) -> None:
    """Value iteration stops when no value moves more than the tolerance: a negative one
    (or NaN) is never met and every stochastic search would end in 'budget', an infinite
    one stops after the first sweep, and no sweep at all computes nothing; a search of no
    node finds nothing, and a cache cannot hold fewer than no plans. Each is refused with
    the setting named; the least usable values (tolerance 0, one sweep, one node, no cache)
    are accepted."""
    with pytest.raises(ValueError, match=f"PlannerConfig.{setting} must be"):
        PlannerConfig(**{setting: value})
    least = PlannerConfig(value_tolerance=0.0, max_sweeps=1, node_budget=1, cache_size=0)
    assert (least.value_tolerance, least.max_sweeps, least.node_budget, least.cache_size) == (0.0, 1, 1, 0)
