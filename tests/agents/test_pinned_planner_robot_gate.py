"""The ``planner`` robot's wiring, pinned for the mutation gate.

What is promised (agents/robots/planner.py's docstrings): the robot plans against a fixed
model of the human unless ``partner_aware`` is asked for; when what the human did changes
that model, the decision of that very turn is planned with the new model's planner; and
a decision the planner made is recorded as one for which the planner was consulted.
The planners here are stand-ins that always propose one chosen action, so which planner
decided is read from the action alone.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.planner.plan import PlanResult
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.core import WAIT, Agent, State, World
from hg_marl.policy import Turn


class FixedPlanner:
    """A planner that always proposes ``action`` for the robot (3 nodes, no expectation of the human)."""

    def __init__(self, action: int) -> None:
        self.action = action

    def plan(self, state: State, to_move: Agent = Agent.ROBOT, **_: Any) -> PlanResult:
        return PlanResult(True, None, 1.0, {}, 3, 0.0, "", True, self.action, -1)


def _turn(world: World, state: State) -> Turn:
    obs = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
    return Turn(world, state, Agent.ROBOT, obs)


def _started(robot: PlannerRobot) -> tuple[World, State]:
    world = World("paper2015")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    return world, world.initial_state(np.random.default_rng(0))


def test_a_planner_robot_plans_against_a_fixed_model_unless_asked_to_learn_its_partner() -> None:
    robot = PlannerRobot()
    assert robot.partner_aware is False
    world, state = _started(robot)
    robot.act(_turn(world, state))
    assert robot.last_decision is not None
    # a fixed model with nothing blocked names no partner type; a partner-aware robot names its best guess
    assert robot.last_decision.partner == ""
    aware = PlannerRobot(partner_aware=True)
    world, state = _started(aware)
    aware.act(_turn(world, state))
    assert aware.last_decision is not None
    assert aware.last_decision.partner in aware.partnering.posterior.types


def test_a_changed_model_of_the_partner_is_planned_with_on_the_same_turn() -> None:
    robot = PlannerRobot()
    world, state = _started(robot)
    old, new = world.index(Agent.ROBOT, WAIT), 0  # two different proposals: wait, and the first action
    robot.planner = robot.partnering.planner = FixedPlanner(old)
    switched = FixedPlanner(new)

    def observe(turn: Turn, last: Any) -> bool:  # the human's move changed the model: a new planner
        robot.partnering.planner = switched
        return True

    robot.partnering.observe = observe
    assert robot.act(_turn(world, state)) == new
    assert robot.planner is switched


def test_a_planned_decision_records_that_the_planner_was_consulted() -> None:
    robot = PlannerRobot()
    world, state = _started(robot)
    action = robot.act(_turn(world, state))
    record = robot.last_decision
    assert record is not None and record.expert == "planner"
    assert record.planner_consulted and record.planner_success
    assert record.planner_action == action
