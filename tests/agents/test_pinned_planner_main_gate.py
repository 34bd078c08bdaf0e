"""The planner's intents, its plan cache and the times it reports, pinned for the mutation gate.

``Planner`` (``agents/planner/planner.py``) answers from a search or from its cache. The
expected values follow from its documented contract: an intent is the answer its plan
would give (for a stochastic human model, the expectimax plan's); a failed answer is the
robot's ``wait``; a plan's suffix cached from a longer plan answers as a cold plan would;
the cache drops its least recently used entry; a result's ``wall_time`` is the clock's
advance during the call (read here from a clock the test drives); the debug line reports
the result's own figures.
"""

from __future__ import annotations

import logging
from collections.abc import Iterator
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from test_pinned_planner_plan_gate import TO_THE_ROBOT, layout

import hg_marl.agents.planner.planner as planner_module
from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.agents.planner.halfstep import astar
from hg_marl.agents.planner.models import cooperative
from hg_marl.agents.planner.planner import Intent
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, State, World


def test_a_stochastic_models_intent_is_its_expectimax_plans_answer(tmp_path: Path) -> None:
    # with an idle probability the expected cost exceeds the deterministic optimum, so an
    # intent answered by the deterministic search instead would differ in cost
    world = layout(tmp_path, TO_THE_ROBOT)
    root = State((0,), 0)
    planned = Planner(world, human_model=cooperative(p_idle=0.3)).plan(root)
    assert planned.plan is not None
    assert planned.cost > Planner(world).plan(root).cost
    intent = Planner(world, human_model=cooperative(p_idle=0.3)).intent(root)
    assert intent == Intent(True, planned.robot_action, planned.human_action, planned.plan.duration, planned.cost)


@pytest.mark.parametrize("planned_first", [False, True])
def test_an_intent_that_finds_no_plan_is_the_robots_wait_at_infinite_cost(planned_first: bool) -> None:
    # one node cannot prove a plan on paper2015; the robot's wait is its last action (17).
    # Asked cold the intent runs its own search; after a plan of the same state it reads
    # the cached failure (of a state in canonical order: the intent asks that one).
    world = World("paper2015")
    planner = Planner(world, PlannerConfig(node_budget=1))
    state = Relabel(world).canonical(world.initial_state(np.random.default_rng(0)))[0]
    if planned_first:
        assert not planner.plan(state).success
    assert world.action_names[Agent.ROBOT][17] == "wait"
    assert planner.intent(state) == Intent(False, 17, -1, float("inf"), float("inf"))


def test_the_cached_last_cycle_answers_the_robots_wait_as_a_cold_plan_does(tmp_path: Path) -> None:
    # the plan's last cycle is both agents' wait on the clean table; asked at the human's
    # turn after the robot's completing wait, the cached one-cycle suffix answers the
    # robot's wait next (no cycle follows) and the human's wait now, as a cold search does
    world = layout(tmp_path, TO_THE_ROBOT)
    wait_r = world.action_names[Agent.ROBOT].index("wait")
    wait_h = world.action_names[Agent.HUMAN].index("wait")
    planner = Planner(world)
    plan = planner.plan(State((0,), 0)).plan
    assert plan is not None and plan.cycles[-1] == (wait_r, wait_h)
    done = plan.mids[-1]
    cached = planner.plan(done, Agent.HUMAN, robot_action=wait_r)
    cold = Planner(world).plan(done, Agent.HUMAN, robot_action=wait_r)
    assert cached.cached and not cold.cached
    assert (cached.robot_action, cached.human_action) == (wait_r, wait_h) == (cold.robot_action, cold.human_action)


def test_the_plan_cache_drops_its_least_recently_used_entry() -> None:
    world = World("paper2015")
    a, b, c = (world.initial_state(np.random.default_rng(seed)) for seed in (0, 1, 2))
    assert len({a, b, c}) == 3
    planner = Planner(world, PlannerConfig(cache_size=2, cache_suffixes=False))
    for state in (a, b, c):
        assert not planner.plan(state).cached
    # two entries: c (the newest) and b; a, the least recently used, was dropped
    assert planner.plan(c).cached
    assert planner.plan(b).cached
    assert not planner.plan(a).cached


def clock(*readings: float) -> SimpleNamespace:
    """A stand-in for the ``time`` module whose ``perf_counter`` returns ``readings`` in turn."""
    it: Iterator[float] = iter(readings)
    return SimpleNamespace(perf_counter=lambda: next(it))


@pytest.mark.parametrize("budget", [1, 200_000])
def test_a_cached_answer_reports_the_clocks_advance_during_the_call(
    monkeypatch: pytest.MonkeyPatch, budget: int
) -> None:
    # a failure (one node) and a plan are cached alike; the second call reads the clock at
    # its start (0.5) and when it answers (1.75): 1.25 s
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    planner = Planner(world, PlannerConfig(node_budget=budget))
    first = planner.plan(state)
    assert first.success is (budget > 1)
    monkeypatch.setattr(planner_module, "time", clock(0.5, 1.75))
    again = planner.plan(state)
    assert again.cached and again.nodes == 0
    assert again.wall_time == 1.25


def test_a_cold_answer_reports_the_clocks_advance_during_the_call(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # a cold plan reads the clock at the call's start (0.5) and once the search is done
    # (1.75): 1.25 s, the search's time (the plan built from its path after it is not counted)
    world = layout(tmp_path, TO_THE_ROBOT)
    monkeypatch.setattr(planner_module, "time", clock(0.5, 1.75))
    res = Planner(world).plan(State((0,), 0))
    assert res.success and not res.cached
    assert res.wall_time == 1.25


def test_the_debug_line_reports_the_results_cycles_cost_nodes_and_milliseconds(
    tmp_path: Path, caplog: pytest.LogCaptureFixture, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the clock advances 0.5 s during the search: 500.00 ms
    world = layout(tmp_path, TO_THE_ROBOT)
    caplog.set_level(logging.DEBUG, logger=planner_module.__name__)
    monkeypatch.setattr(planner_module, "time", clock(100.0, 100.5))
    res = Planner(world).plan(State((0,), 0))
    assert res.plan is not None
    expected = f"planned {len(res.plan)} cycles, cost {res.cost:.3f}, {res.nodes} nodes, 500.00 ms"
    assert expected in caplog.messages


def test_a_human_turn_plan_without_the_robots_action_gives_the_robot_no_time(tmp_path: Path) -> None:
    # asked at the human's turn without the robot action under way, the first cycle's robot
    # part lasts 0 s (the cycle lasts the human's action); with goto(human) under way, 3 s
    world = layout(tmp_path, TO_THE_ROBOT)
    goto_human = world.action_names[Agent.ROBOT].index("goto(human)")
    state = State((0,), 1)  # the robot already at the human's side
    unknown = Planner(world).plan(state, Agent.HUMAN).plan
    known = Planner(world).plan(state, Agent.HUMAN, robot_action=goto_human).plan
    assert unknown is not None and known is not None
    assert unknown.durations[0][0] == 0.0 and known.durations[0][0] == 3.0


def test_only_a_stochastic_models_result_carries_its_nominal_plans_cost(tmp_path: Path) -> None:
    # the expectimax result's extras hold the cost of the plan it returns, priced as a plan
    # is priced (its terms under the weights); a deterministic search adds nothing
    world = layout(tmp_path, TO_THE_ROBOT)
    root = State((0,), 0)
    planner = Planner(world, human_model=cooperative(p_idle=0.3))
    res = planner.plan(root)
    assert res.plan is not None
    assert res.extras == {"nominal_plan_cost": res.plan.cost(planner.config.weights)}
    assert Planner(world).plan(root).extras == {}


def test_an_intent_is_searched_once_for_a_state_and_its_relabellings(monkeypatch: pytest.MonkeyPatch) -> None:
    # paper2015's three tapes are interchangeable: a state and the same state with two
    # tapes' places swapped are one canonical state, so the second intent is the memoised
    # answer of the first (its actions mapped back to the swapped objects), not a search
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    where = list(state.where)
    where[0], where[1] = where[1], where[0]
    swapped = state._replace(where=tuple(where))
    assert swapped != state and Relabel(world).canonical(swapped)[0] == Relabel(world).canonical(state)[0]
    searches = []

    def counted(*args: object, **kwargs: object) -> object:
        searches.append(args[1])
        return astar(*args, **kwargs)

    monkeypatch.setattr(planner_module, "astar", counted)
    planner = Planner(world)
    planner.intent(state)
    planner.intent(swapped)
    assert len(searches) == 1
