"""Values that round 122's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.base import LearningRobot
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn
from hg_marl.training.adaptation import AdaptationConfig, adaptation_jobs


def test_the_habit_robots_step_in_act_bootstraps_from_the_next_state() -> None:
    # A step taken in act() is not the end of a run: Q-learning's target is the reward plus
    # gamma times the next state's best Q. Tabular habit (alpha 0.6, gamma 0.9, Q = 0 at the start):
    # 1. in SOLVED_FROM the robot acts, then the run ends with reward 1 (end, terminated): its Q
    #    there for that action becomes 0.6 * (1 - 0) = 0.6, the best Q of that state;
    # 2. in OTHER it acts, then in SOLVED_FROM it is asked again with reward 0: the step on OTHER's
    #    action moves its Q by 0.6 * (0 + 0.9 * 0.6 - 0) = 0.324 (a terminal step would leave 0).
    world = World("paper2015")
    solved_from = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    other = State(where=(2, 0, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    robot = make_robot("habit", share_objects=False, q_config={"features": "tabular"})
    assert isinstance(robot, LearningRobot)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))

    def turn(at: State, reward: float) -> Turn:
        observation = {"observation": world.facts(at), "action_mask": world.mask(at, Agent.ROBOT)}
        return Turn(world, at, Agent.ROBOT, observation, reward=reward)

    first = robot.act(turn(solved_from, 0.0))
    robot.end(turn(other, 1.0), terminated=True)
    assert float(robot.habit.q_values(world.facts(solved_from))[first]) == 0.6
    second = robot.act(turn(other, 0.0))
    robot.act(turn(solved_from, 0.0))
    expected = np.zeros(world.n_actions(Agent.ROBOT))
    expected[second] = 0.6 * 0.9 * 0.6
    np.testing.assert_allclose(robot.habit.q_values(world.facts(other)), expected)


def test_every_adaptation_job_runs_the_configured_scenario() -> None:
    # AdaptationConfig.scenario is "Scenario." of the whole experiment: each (switch, robot, seed)
    # job plays it, here roboergosum (1 switch x 2 robots x 2 seeds = 4 jobs).
    config = AdaptationConfig(scenario="roboergosum", seeds=2, switches=("lazy",), robots=("planner", "habit"))
    jobs = adaptation_jobs(config)
    assert len(jobs) == 4
    assert {job.scenario for job in jobs} == {"roboergosum"}
