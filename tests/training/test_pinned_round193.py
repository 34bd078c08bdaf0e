"""Values that round 193's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.planner.models import RestrictedHuman, cooperative, no_handover
from hg_marl.agents.robots.partnering import Partnering
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.core import Agent, World


def test_a_planning_robot_plans_with_the_human_model_it_is_given() -> None:
    # The robot is told its human never gives nor takes: its planner, the partnering's base and
    # its fixed model are that model (name "no_handover", GIVE and TAKE left out), not the
    # cooperative default.
    world = World("paper2015")
    given = no_handover()
    robot = PlannerRobot(human_model=given)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    assert robot.partnering.base == given and robot.partnering.fixed == given
    assert robot.partnering.model == given and robot.planner.human_model == given
    assert robot.planner.human_model.name == "no_handover"
    assert robot.planner.human_model != cooperative()
    # the same without the robot around it; None (no model given) is the cooperative one
    assert Partnering(world, None, given, partner_aware=False).base == given
    assert Partnering(world, None, None, partner_aware=False).base == cooperative()


def test_a_human_idling_five_percent_of_turns_is_planned_with_its_idling() -> None:
    # "does nothing with probability p, else cooperative": p = 0.05 gives two choice sets,
    # the human's wait (the last human action) with 0.05 and every candidate with 0.95.
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    wait = world.n_actions(Agent.HUMAN) - 1
    candidates = tuple(world.feasible_indices(state, Agent.HUMAN))
    assert len(candidates) > 1
    model = RestrictedHuman("cooperative", p_idle=0.05)
    assert model.stochastic
    assert model.choices(world, state, candidates) == ((0.05, (wait,)), (0.95, candidates))
    # p = 0 is the deterministic restriction: one set with everything
    assert RestrictedHuman("cooperative").choices(world, state, candidates) == ((1.0, candidates),)
