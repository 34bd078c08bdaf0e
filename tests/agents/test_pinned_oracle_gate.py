"""The oracle's cache hit and its off-model decision record, pinned for the mutation gate.

Expected values are stated by hand: a second call with the same content is answered from
the cache with the same figures as the first; the off-model decision records the
planner's expected human answer only when the planner found a plan (-1 otherwise), and
its planning time is the difference of two readings of the clock (a fake clock here).
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import hg_marl.agents.oracle as oracle_module
from hg_marl.agents.oracle import OracleResult, OracleRobot, oracle_rate
from hg_marl.core import Agent, World
from hg_marl.policy import Turn
from tests.agents.test_oracle import TINY


def test_a_cached_result_is_read_back_with_the_same_figures(tmp_path: Path) -> None:
    world = World(TINY)
    first = oracle_rate(world, "cooperative", failed_actions=False, cache=tmp_path)
    assert any(tmp_path.rglob("*")), "the first call stores an entry"
    second = oracle_rate(world, "cooperative", failed_actions=False, cache=tmp_path)
    assert (second.rate_per_hour, second.n_states, second.n_transitions, second.n_layouts) == (
        first.rate_per_hour,
        first.n_states,
        first.n_transitions,
        first.n_layouts,
    )
    assert first.rate_per_hour > 0.0


class _Clock:
    """perf_counter readings 100.0, 100.25, 100.5, ...: each planning takes 0.25 s."""

    def __init__(self) -> None:
        self.now = 100.0

    def perf_counter(self) -> float:
        value = self.now
        self.now += 0.25
        return value


@pytest.mark.parametrize("success", [True, False])
def test_off_model_decision_records_the_planners_answer_and_time(
    monkeypatch: pytest.MonkeyPatch, success: bool
) -> None:
    world = World(TINY)
    empty = OracleResult(0.0, 0.0, 0, 0, 0, 0, True, policy={}, values={}, scenario=world.scenario.name)
    robot = OracleRobot(result=empty)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(1))
    intent = SimpleNamespace(success=success, robot_action=0, human_action=2)
    robot._planner = SimpleNamespace(world=world, intent=lambda s, a: intent)
    monkeypatch.setattr(oracle_module, "time", _Clock())
    action = robot.act(Turn(world, state, Agent.ROBOT, {}))
    decision = robot.last_decision
    assert decision is not None
    wait = world.n_actions(Agent.ROBOT) - 1
    assert action == (0 if success else wait)
    assert decision.planner_action == (0 if success else -1)
    assert decision.expected_human_action == (2 if success else -1)
    assert decision.planning_time == pytest.approx(0.25)
    assert robot.off_model == 1


def test_a_robot_reset_on_another_scenario_solves_that_scenario() -> None:
    """The policy belongs to the table it was solved on: after paper2015, a reset on
    forced_coordination solves forced_coordination (its rate is that table's oracle rate)."""
    robot = OracleRobot(human="cooperative")
    robot.reset(World("paper2015"), Agent.ROBOT, np.random.default_rng(0))
    assert robot.result is not None and robot.result.scenario == "paper2015"
    robot.reset(World("forced_coordination"), Agent.ROBOT, np.random.default_rng(0))
    assert robot.result.scenario == "forced_coordination"
    assert robot.result.rate_per_hour == pytest.approx(oracle_rate("forced_coordination", "cooperative").rate_per_hour)
    assert robot.result.rate_per_hour != pytest.approx(oracle_rate("paper2015", "cooperative").rate_per_hour)


def test_the_cache_keeps_apart_results_with_and_without_failed_actions(tmp_path: Path) -> None:
    # the robot's infeasible actions (0.2 s no-ops) are pairs of the model only with
    # failed_actions=True: the two models differ, and a cached one never answers for the other
    world = World(TINY)
    fresh = {flag: oracle_rate(world, "cooperative", failed_actions=flag) for flag in (True, False)}
    assert fresh[True].n_transitions > fresh[False].n_transitions
    for flag in (True, False, True):
        got = oracle_rate(world, "cooperative", failed_actions=flag, cache=tmp_path)
        assert (got.n_transitions, got.rate_per_hour) == (fresh[flag].n_transitions, fresh[flag].rate_per_hour)
