"""The belief robot reused between runs, and the statistics its explanations report.

Reuse: one robot object run twice must play the second run exactly as a fresh robot
does (the posterior, the stall counters and the planner hand-over all start anew; only
the members' oracles, a pure cache, are kept, and re-solved in another world).

Statistics: ``expected_seconds`` is the expected time to the next success of the chosen
action under the belief (MAP: the most probable member's; QMDP: the weighted mean of
the members'), ``belief_top`` the largest member probability. They are checked against
the oracle's own values (:func:`~hg_marl.agents.oracle.oracle_rate`): at a robot-turn
state the value of a member's optimal action *is* the member's value there.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.oracle import OracleRobot, oracle_rate
from hg_marl.agents.planner.space import Relabel
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, State, World
from hg_marl.policy import Decision, Turn
from hg_marl.training.runner import RunConfig, run

COOP = "preference"
MAT = "preference:handover=-1.0,shared=1.0"
TIMING = ["planning_time", "decision_time"]
"""Wall-clock columns of a run's log (the rest is a function of the seed)."""


def _population(tmp_path: Path) -> str:
    text = 'name = "t"\nscenario = "paper2015"\n'
    for name, split, spec in (("coop", "train", COOP), ("mat", "train", MAT), ("idle", "held_out", "lazy")):
        text += f'\n[[members]]\nname = "{name}"\nsplit = "{split}"\nspec = "{spec}"\n'
    path = tmp_path / "population.toml"
    path.write_text(text)
    return str(path)


def _log(robot: BeliefRobot, human: str, scenario: str = "paper2015", seed: int = 0) -> pd.DataFrame:
    log = run(robot, make_human(human), RunConfig(scenario=scenario, duration=400.0, seed=seed)).log
    return log.drop(columns=[c for c in TIMING if c in log])


def test_a_reused_robot_plays_its_second_run_as_a_fresh_one(tmp_path: Path) -> None:
    population = _population(tmp_path)
    reused = BeliefRobot(population=population, splits="train")
    _log(reused, MAT, seed=3)  # evidence about "mat" (and a stall history) from a first run
    second = _log(reused, "cooperative", seed=0)
    fresh = _log(BeliefRobot(population=population, splits="train"), "cooperative", seed=0)
    pd.testing.assert_frame_equal(second, fresh)


def test_reset_returns_the_posterior_to_the_prior(tmp_path: Path) -> None:
    robot = BeliefRobot(population=_population(tmp_path), splits="train", unknown=0.1)
    _log(robot, MAT, seed=1)
    robot.reset(World("paper2015"), Agent.ROBOT, np.random.default_rng(0))
    post = robot.posterior.posterior()
    assert post == pytest.approx({COOP: 0.45, MAT: 0.45, "random": 0.1})
    assert robot._prev is None and not robot._planner_mode and robot._wait_run == 1.0
    assert not robot._off_population


def test_a_robot_reused_in_another_world_solves_that_worlds_oracles(tmp_path: Path) -> None:
    population = _population(tmp_path)
    reused = BeliefRobot(population=population, splits="train")
    _log(reused, MAT)
    other = "forced_coordination"
    fresh = BeliefRobot(population=population, splits="train")
    pd.testing.assert_frame_equal(_log(reused, MAT, other), _log(fresh, MAT, other))
    world = World(other)
    assert [reused.members.result(m).rate_per_hour for m in range(2)] == pytest.approx(
        [oracle_rate(world, spec).rate_per_hour for spec in (COOP, MAT)]
    )


def _first_decision(robot: BeliefRobot, seed: int = 0) -> tuple[World, State, int]:
    world = World("paper2015")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(seed))
    action = robot.act(Turn(world, state, Agent.ROBOT, {}))
    return world, state, action


def _decision(robot: BeliefRobot) -> Decision:
    assert robot.last_decision is not None
    return robot.last_decision


def _value(world: World, spec: str, state: State) -> float:
    return float(oracle_rate(world, spec).value_at(world, state, Relabel(world)))


def test_map_reports_the_most_probable_members_expected_seconds_and_its_probability(tmp_path: Path) -> None:
    # equal priors (0.95 / 2 each, 0.05 on "none of them"): the first member is the most probable
    robot = BeliefRobot(population=_population(tmp_path), splits="train", hedge="map")
    world, state, action = _first_decision(robot)
    stats = dict(_decision(robot).stats)
    assert stats["belief_top"] == pytest.approx(0.475)
    assert stats["expected_seconds"] == pytest.approx(_value(world, COOP, state))
    assert _decision(robot).partner == "coop" and _decision(robot).action == action


def test_map_follows_the_evidence_to_the_other_member(tmp_path: Path) -> None:
    robot = BeliefRobot(population=_population(tmp_path), splits="train", hedge="map")
    world, state, _ = _first_decision(robot)
    weights = {COOP: 0.2, MAT: 0.7, "random": 0.1}
    robot.posterior.posterior = lambda: weights
    robot._prev = None
    robot.act(Turn(world, state, Agent.ROBOT, {}))
    stats = dict(_decision(robot).stats)
    assert stats["belief_top"] == pytest.approx(0.7) and _decision(robot).partner == "mat"
    assert stats["expected_seconds"] == pytest.approx(_value(world, MAT, state))


def test_qmdp_reports_the_weighted_mean_of_the_members_expected_seconds(tmp_path: Path) -> None:
    robot = BeliefRobot(population=_population(tmp_path), splits="train", hedge="qmdp")
    world, state, action = _first_decision(robot)
    # each member's own optimal action here (the oracle robot's choice) is the one the mixture takes,
    # so each member's expected seconds after it is that member's value
    for spec in (COOP, MAT):
        oracle = OracleRobot(result=oracle_rate(world, spec))
        oracle.reset(world, Agent.ROBOT, np.random.default_rng(0))
        assert oracle.act(Turn(world, state, Agent.ROBOT, {})) == action
    stats = dict(_decision(robot).stats)
    expected = (_value(world, COOP, state) + _value(world, MAT, state)) / 2  # equal weights
    assert stats["expected_seconds"] == pytest.approx(expected)
    assert stats["belief_top"] == pytest.approx(0.475)


def test_qmdp_weights_the_members_by_the_posterior(tmp_path: Path) -> None:
    robot = BeliefRobot(population=_population(tmp_path), splits="train", hedge="qmdp")
    world, state, action = _first_decision(robot)
    robot.posterior.posterior = lambda: {COOP: 0.6, MAT: 0.3, "random": 0.1}
    robot._prev = None
    assert robot.act(Turn(world, state, Agent.ROBOT, {})) == action
    expected = (0.6 * _value(world, COOP, state) + 0.3 * _value(world, MAT, state)) / 0.9
    assert dict(_decision(robot).stats)["expected_seconds"] == pytest.approx(expected)


def test_the_held_out_member_is_never_believed_by_default(tmp_path: Path) -> None:
    robot = BeliefRobot(population=_population(tmp_path))
    assert robot.member_names == ("coop", "mat") and robot.member_specs == (COOP, MAT)
    assert BeliefRobot(population=_population(tmp_path), splits="held_out").member_names == ("idle",)


def test_a_probe_is_the_most_telling_action_within_the_budget(tmp_path: Path) -> None:
    """Expected seconds 10 (the best), 16, 24 and 40 under a belief of total weight 0.5; budget 10 s.

    Replies tell 0.1, 0.3, 0.9 and 2.0 nats: the action of 16 s is the most telling within
    10 + 10 = 20 s (24 s and 40 s are over it); it tells 0.2 nats more than the best, over MIN_GAIN.
    """
    robot = BeliefRobot(population=_population(tmp_path), splits="train", probe=10.0)
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    info = {1: 0.1, 2: 0.3, 3: 0.9, 4: 2.0}
    robot.information = lambda w, s, a, weights: info[a]  # type: ignore[method-assign]
    mixed = {1: 5.0, 2: 8.0, 3: 12.0, 4: 20.0}  # seconds x total weight
    assert robot._probe(world, state, [0.25, 0.25], mixed, 0.5) == (2, 0.3)
    info[2] = 0.14  # 0.04 nats more than the best action's own reply: not worth a move
    assert robot._probe(world, state, [0.25, 0.25], mixed, 0.5) == (1, 0.1)
    info[2] = 0.1  # no more telling than the best: the best
    assert robot._probe(world, state, [0.25, 0.25], mixed, 0.5) == (1, 0.1)
    mixed[4] = float("inf")  # a hopeless action is never a probe, however telling
    robot.probe = 1000.0
    assert robot._probe(world, state, [0.25, 0.25], mixed, 0.5) == (3, 0.9)
