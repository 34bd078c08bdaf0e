"""The belief robot's planner kept in step on the turns another expert decides.

The belief robot hands the decision to its planner only while no member explains the
partner. The planner's partner monitor forgets its blocks when a task is solved and
compares the human's move with the expectation of the planner's own last decision; on
the turns the members (or the guard, or the observed model) decide, the planner still
follows: a solved task clears its blocks, and an expectation is compared once, with the
move that answered it, never with a later one.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, World
from hg_marl.policy import Decision, Turn

POPULATION = "populations/hard_layouts.toml"


def _members_drive(monkeypatch: pytest.MonkeyPatch) -> tuple[World, BeliefRobot]:
    """A belief robot on ``forced_coordination`` whose posterior is all on its first member."""
    world = World("forced_coordination")
    robot = make_robot("belief", population=POPULATION, cache="")
    assert isinstance(robot, BeliefRobot)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    first = robot.member_specs[0]
    names = [*robot.member_specs, robot._unknown_name]
    monkeypatch.setattr(robot.posterior, "posterior", lambda: {n: float(n == first) for n in names})
    return world, robot


def test_a_task_solved_while_a_member_drives_clears_the_planners_blocks(monkeypatch: pytest.MonkeyPatch) -> None:
    world, robot = _members_drive(monkeypatch)
    monitor = robot._planner.partnering.monitor
    pick = next(a for a in world.actions(Agent.HUMAN) if a.kind.name == "PICK")
    monitor.refusals, monitor.blocked = {pick: 2}, frozenset({pick})
    state = world.initial_state(np.random.default_rng(0))
    action = robot.act(Turn(world, state, Agent.ROBOT, {}, reward=1.0))
    assert robot.last_decision is not None and robot.last_decision.expert == "belief"
    assert monitor.blocked == frozenset() and monitor.refusals == {}
    # The planner knows the robot's move of this turn, to reconstruct the human's answer.
    assert robot._planner.partnering.previous == (state, action)


def test_without_a_task_solved_the_blocks_stay(monkeypatch: pytest.MonkeyPatch) -> None:
    world, robot = _members_drive(monkeypatch)
    monitor = robot._planner.partnering.monitor
    pick = next(a for a in world.actions(Agent.HUMAN) if a.kind.name == "PICK")
    monitor.refusals, monitor.blocked = {pick: 2}, frozenset({pick})
    robot.act(Turn(world, world.initial_state(np.random.default_rng(0)), Agent.ROBOT, {}))
    assert monitor.blocked == frozenset({pick})


def test_the_planners_expectation_is_compared_once_then_spent(monkeypatch: pytest.MonkeyPatch) -> None:
    """The planner expected the human's first non-wait action (index 0) and the human waited:
    one refusal counted on the turn that answered it, none on the next (the same wait is
    no answer to an expectation made two turns ago)."""
    world, robot = _members_drive(monkeypatch)
    planner = robot._planner
    monitor = planner.partnering.monitor
    wait = world.n_actions(Agent.HUMAN) - 1
    expected = 0
    assert world.actions(Agent.HUMAN)[expected].kind.name != "WAIT"
    planner.last_decision = Decision("planner", 0, expected_human_action=expected)
    state = world.initial_state(np.random.default_rng(0))
    robot.act(Turn(world, state, Agent.ROBOT, {}, last_actions=(0, wait)))
    assert monitor.misses == 1 and monitor.refusals == {world.actions(Agent.HUMAN)[expected]: 1}
    assert planner.last_decision is None
    robot.act(Turn(world, state, Agent.ROBOT, {}, last_actions=(0, wait)))
    assert monitor.misses == 1 and sum(monitor.refusals.values()) == 1
