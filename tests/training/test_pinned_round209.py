"""Values that round 209's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.planner.plan import PlanResult, failure
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, World
from hg_marl.core.errors import OutputError, output_error
from hg_marl.policy import Turn


def writing_is_an_output_error_naming_it(path: Path, failure: type[OSError]) -> None:
    """Opening ``path`` for writing fails with ``failure``: ``output_error`` makes it one OutputError line naming it."""
    with pytest.raises(failure) as raised:
        open(path, "w")  # noqa: SIM115 (the open is meant to fail)
    error = output_error(raised.value, path)
    assert isinstance(error, OutputError)
    assert str(error).startswith(f"cannot write {path}: ")


def test_writing_onto_a_folder_is_an_output_error_naming_it(tmp_path: Path) -> None:
    # Opening a folder for writing fails with EISDIR, one of the errnos a user causes (a
    # folder where an output file should go): one OutputError line naming the path.
    writing_is_an_output_error_naming_it(tmp_path, IsADirectoryError)


def test_a_failed_plans_action_distribution_is_uniform_whatever_its_wait_action() -> None:
    # A failed result carries the robot's wait (index 4 of 5 actions) as its robot_action, but
    # there is no planned action: maximum entropy, 1/5 = 0.2 on each action, for either seat.
    result = failure("no plan: test", 3, 0.0, robot_wait=4)
    assert result.robot_action == 4
    np.testing.assert_allclose(result.action_distribution(5), [0.2] * 5)
    hand_made = PlanResult(False, None, float("inf"), {}, 0, 0.0, "budget", robot_action=1, human_action=2)
    np.testing.assert_allclose(hand_made.action_distribution(4), [0.25] * 4)
    np.testing.assert_allclose(hand_made.action_distribution(4, Agent.HUMAN), [0.25] * 4)


def test_a_planner_robot_plans_with_the_model_its_follow_turn_learnt() -> None:
    # roboergosum, seed 0: the cooperative planner expects the human to pick object 0 (human
    # action 0). The partner monitor now rules that pick out, and a turn another expert decided
    # (``follow``, the robot waits) takes the blocked model in. The robot's next plan must come
    # from a planner that knows the pick is out, so it never expects it (a blocked action is one
    # the model never performs), where the planner of before the block expects it again.
    world = World("roboergosum")
    state = world.initial_state(np.random.default_rng(0))
    pick0 = world.actions(Agent.HUMAN)[0]
    assert pick0.kind.name == "PICK" and pick0.obj == 0
    free = make_robot("planner")
    free.reset(world, Agent.ROBOT, np.random.default_rng(0))
    free.act(Turn(world, state, Agent.ROBOT, {}))
    assert free.last_decision is not None and free.last_decision.expected_human_action == 0

    robot = make_robot("planner")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    monitor = robot.partnering.monitor
    monitor.refusals, monitor.blocked = {pick0: 2}, frozenset({pick0})
    robot.follow(Turn(world, state, Agent.ROBOT, {}), world.n_actions(Agent.ROBOT) - 1)
    robot.act(Turn(world, state, Agent.ROBOT, {}))
    decision = robot.last_decision
    assert decision is not None and decision.expert == "planner"
    assert decision.expected_human_action != 0
    assert pick0 in robot.planner.human_model.blocked
