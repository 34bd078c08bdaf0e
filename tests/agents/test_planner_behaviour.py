"""The planner's failures, determinism, cache, human models, execution helpers and monitoring."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_planner_reference import execute, initial_states, reference_cost, reference_price, reference_terms

from hg_marl.agents.planner import (
    CostWeights,
    HumanModel,
    Planner,
    PlannerConfig,
    make_human_model,
)
from hg_marl.core import Agent, Kind, World
from hg_marl.core.scenario import parse_scenario
from tests.agents.plan_execution import PlanMonitor, expected_human_action, next_robot_action


def tiny(spot_robot: list[str], spot_human: bool, bin_human: bool = False, shared: bool = False) -> World:
    """One object on one spot; optionally a free spot both agents reach."""
    spots = [{"name": "s0", "robot_reach": spot_robot, "human_reach": spot_human}]
    if shared:
        spots.append({"name": "shared", "robot_reach": ["near"], "human_reach": True})
    data = {
        "name": "tiny",
        "robot_locations": ["near", "far"],
        "handover_locations": ["near"],
        "objects": [{"name": "o"}],
        "bins": [{"name": "b", "robot_reach": ["far"], "human_reach": bin_human}],
        "spots": spots,
        "layout": [{"count": 1, "spots": ["s0"]}],
    }
    return World(parse_scenario(data))


# ---- failures ------------------------------------------------------------------------
def test_unreachable_object_is_a_failure_with_reason() -> None:
    world = tiny([], spot_human=False)
    result = Planner(world).plan(world.initial_state(np.random.default_rng(0)))
    assert not result.success and result.plan is None
    assert result.reason.startswith("unreachable") and "dispose(o)" in result.reason
    assert result.robot_action == world.n_actions(Agent.ROBOT) - 1
    assert result.human_action == -1 and math.isinf(result.cost)


def test_restricted_human_can_make_an_object_unreachable() -> None:
    world = tiny([], spot_human=True)  # only a handover gets it to the robot's bin
    state = world.initial_state(np.random.default_rng(0))
    assert Planner(world).plan(state).success
    result = Planner(world, human_model=make_human_model("no_handover")).plan(state)
    assert not result.success and result.reason.startswith("unreachable")
    # with a shared spot, the no-handover human places it for the robot
    world = tiny([], spot_human=True, shared=True)
    result = Planner(world, human_model=make_human_model("no_handover")).plan(
        world.initial_state(np.random.default_rng(0))
    )
    assert result.success
    assert "human_places" in {s.method for s in result.plan.streams[Agent.HUMAN]}


def test_budget_exhausted_is_a_failure_with_reason() -> None:
    world = World("roboergosum")
    result = Planner(world, PlannerConfig(node_budget=3)).plan(world.initial_state(np.random.default_rng(0)))
    assert not result.success and result.reason.startswith("budget")
    assert result.nodes == 3


# ---- determinism and cache -----------------------------------------------------------
@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum", "generated:objects=6,seed=2,human_only=0.8"])
def test_deterministic(scenario: str) -> None:
    world = World(scenario)
    for state in initial_states(world, range(3)):
        a, b = Planner(world).plan(state), Planner(World(scenario)).plan(state)
        assert a.plan is not None and b.plan is not None
        assert a.plan.cycles == b.plan.cycles and a.cost == b.cost and a.nodes == b.nodes


def test_cache_serves_repeated_and_predicted_states() -> None:
    world = World("paper2015")
    planner = Planner(world)
    state = world.initial_state(np.random.default_rng(3))
    cold = planner.plan(state)
    warm = planner.plan(state)
    assert warm.cached and warm.nodes == 0 and warm.cost == cold.cost and warm.plan == cold.plan
    plan = cold.plan
    assert plan is not None
    weights = planner.config.weights
    for k in (1, 4, len(plan) - 1):
        sub = planner.plan(plan.states[k])
        assert sub.cached and sub.plan is not None and sub.plan.cycles == plan.cycles[k:]
        assert sub.cost == pytest.approx(reference_cost(world, plan.states[k], weights))
        mid = world.step(plan.states[k], Agent.ROBOT, plan.cycles[k][0]).state
        hsub = planner.plan(mid, Agent.HUMAN, robot_action=plan.cycles[k][0])
        assert hsub.cached and hsub.human_action == plan.cycles[k][1]
    uncached = Planner(world, PlannerConfig(cache_size=0))
    uncached.plan(state)
    assert not uncached.plan(state).cached


def test_action_distribution() -> None:
    world = World("paper2015")
    result = Planner(world).plan(world.initial_state(np.random.default_rng(0)))
    n = world.n_actions(Agent.ROBOT)
    dist = result.action_distribution(n, Agent.ROBOT)
    assert dist.sum() == pytest.approx(1.0) and dist[result.robot_action] == pytest.approx(1 - (n - 1) * 0.01)
    failed = Planner(tiny([], spot_human=False)).plan(
        tiny([], spot_human=False).initial_state(np.random.default_rng(0))
    )
    assert np.allclose(failed.action_distribution(5), 0.2)


# ---- human models --------------------------------------------------------------------
@pytest.mark.parametrize("name", ["no_handover", "lazy"])
@pytest.mark.parametrize(
    "scenario", ["paper2015", "generated:objects=3,seed=1", "generated:objects=3,seed=4,human_only=0.8"]
)
def test_restricted_models_are_optimal_and_respected(name: str, scenario: str) -> None:
    world = World(scenario)
    model = make_human_model(name)
    planner = Planner(world, human_model=model)
    for state in initial_states(world, range(2)):
        result = planner.plan(state)
        expected = reference_cost(world, state, planner.config.weights, model)
        if math.isinf(expected):
            assert not result.success
            continue
        assert result.cost == pytest.approx(expected)
        kinds = {world.actions(Agent.HUMAN)[s.action].kind for s in result.plan.streams[Agent.HUMAN]}
        assert kinds <= model.allowed_kinds
        clock, _, reward = execute(world, result.plan.cycles, state)
        assert reward == 1.0 and clock == pytest.approx(result.plan.duration)


def test_make_human_model() -> None:
    assert make_human_model("cooperative").allowed_kinds >= {Kind.GIVE, Kind.TAKE}
    assert Kind.TAKE not in make_human_model("lazy").allowed_kinds
    assert make_human_model("lazy", p_idle=0.2).stochastic
    assert isinstance(make_human_model("no_handover"), HumanModel)
    with pytest.raises(ValueError, match="unknown human model"):
        make_human_model("grumpy")
    with pytest.raises(ValueError, match="p_idle"):
        make_human_model("cooperative", p_idle=1.0)


def reference_expectimax(world: World, state, weights: CostWeights, p: float) -> float:  # type: ignore[no-untyped-def]
    """Value iteration over every feasible action: robot min, human idles w.p. p else min."""
    wait_h = world.n_actions(Agent.HUMAN) - 1
    hand_h = world.hand[Agent.HUMAN]
    states, frontier, trans = [], [state], {}
    while frontier:
        s = frontier.pop()
        if s in trans:
            continue
        states.append(s)
        trans[s] = []
        for ar in world.feasible_indices(s, Agent.ROBOT):
            o1 = world.step(s, Agent.ROBOT, ar)
            edges = []
            for ah in world.feasible_indices(o1.state, Agent.HUMAN):
                o2 = world.step(o1.state, Agent.HUMAN, ah)
                t = reference_terms(world, o1.duration, ar, o2.duration, ah, hand_h in o2.state.where)
                edges.append((ah, reference_price(weights, t), o2.state))
                if o1.reward == 0.0:
                    frontier.append(o2.state)
            trans[s].append((o1.reward == 1.0, edges))
    value = dict.fromkeys(states, 0.0)
    for _ in range(100_000):
        delta = 0.0
        for s in states:
            qs = []
            for done, edges in trans[s]:
                q = [c + (0.0 if done else value[s2]) for _, c, s2 in edges]
                idle = next(v for e, v in zip(edges, q, strict=True) if e[0] == wait_h)
                qs.append(p * idle + (1 - p) * min(q))
            new = min(qs)
            delta = max(delta, abs(new - value[s]))
            value[s] = new
        if delta < 1e-10:
            break
    return value[state]


@pytest.mark.parametrize(
    "scenario", ["generated:objects=2,seed=3", "generated:objects=2,seed=1,human_only=0.8", "paper2015"]
)
def test_stochastic_model_expectimax(scenario: str) -> None:
    world = World(scenario)
    state = world.initial_state(np.random.default_rng(0))
    weights = CostWeights()
    coop = Planner(world).plan(state)
    idle = Planner(world, human_model=make_human_model("cooperative", p_idle=0.3)).plan(state)
    assert idle.success and idle.optimal
    assert idle.cost >= coop.cost - 1e-9
    assert sum(idle.breakdown.values()) == pytest.approx(idle.cost)
    if world.n_objects <= 2:
        assert idle.cost == pytest.approx(reference_expectimax(world, state, weights, 0.3), rel=1e-6)
    _, _, reward = execute(world, idle.plan.cycles, state)
    assert reward == 1.0
    nearly = Planner(world, human_model=make_human_model("cooperative", p_idle=1e-9)).plan(state)
    assert nearly.cost == pytest.approx(coop.cost, rel=1e-6)


# ---- execution helpers and monitoring --------------------------------------------------
def test_next_robot_action_and_expected_human_action() -> None:
    world = World("roboergosum")
    state = world.initial_state(np.random.default_rng(1))
    result = Planner(world).plan(state)
    plan = result.plan
    assert plan is not None
    for k, (ar, ah) in enumerate(plan.cycles):
        assert next_robot_action(world, plan, plan.states[k]) == ar
        mid = world.step(plan.states[k], Agent.ROBOT, ar).state
        assert expected_human_action(world, plan, mid) == ah
    # a take whose offer never came is not executable: the robot waits instead
    takes = [k for k, (ar, _) in enumerate(plan.cycles) if world.actions(Agent.ROBOT)[ar].kind is Kind.TAKE]
    assert takes
    k = takes[0]
    off = plan.states[k]._replace(offer_by=-1, offer_obj=-1)
    action = next_robot_action(world, plan, off)
    assert world.mask(off, Agent.ROBOT)[action]


def test_human_turn_plan() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    plan = Planner(world).plan(state).plan
    assert plan is not None
    mid = world.step(state, Agent.ROBOT, plan.cycles[0][0]).state
    result = Planner(world).plan(mid, Agent.HUMAN)
    assert result.plan is not None and result.plan.cycles[0][0] == -1
    assert result.human_action == result.plan.cycles[0][1]
    assert result.robot_action == result.plan.cycles[1][0]


def test_monitor_notices_missing_human_action_and_replans() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    monitor = PlanMonitor(Planner(world))
    wait_h = world.n_actions(Agent.HUMAN) - 1
    refused = None
    clock = 0.0
    for _ in range(40):
        result = monitor.robot_turn(state)
        assert result.success, result.reason
        out_r = world.step(state, Agent.ROBOT, result.robot_action)
        if out_r.reward == 1.0:
            break
        mid = out_r.state
        expected = expected_human_action(world, result.plan, mid)
        action = expected
        if refused is None and world.actions(Agent.HUMAN)[expected].kind is Kind.GIVE:
            refused, action = expected, wait_h  # the human does not hand the tape over
        out_h = world.step(mid, Agent.HUMAN, action)
        on_plan = monitor.human_acted(mid, action, out_h.state)
        assert on_plan == (action == expected)
        if action != expected:
            assert world.actions(Agent.HUMAN)[refused] in monitor.blocked
        clock += max(out_r.duration, out_h.duration)
        state = out_h.state
    else:
        pytest.fail("the task was not completed")
    assert refused is not None and monitor.deviations == 1
    assert world.is_clean(state)


def test_cache_without_suffixes_answers_like_a_cold_search() -> None:
    world = World("roboergosum")
    planner = Planner(world, PlannerConfig(cache_suffixes=False))
    state = world.initial_state(np.random.default_rng(2))
    plan = planner.plan(state).plan
    assert plan is not None and planner.plan(state).cached
    later = plan.states[3]
    result = planner.plan(later)
    assert not result.cached
    assert result.plan == Planner(world).plan(later).plan
