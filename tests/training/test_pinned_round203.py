"""Values that round 203's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal
from hg_marl.agents.meta.entropy import EntropyCriterion
from hg_marl.agents.partner_specs import make_robot_actor, resolve_partner
from hg_marl.core import Agent
from hg_marl.core.errors import RobotError
from tests.training.test_pinned_round68 import habit_robot_turns

# --- agents/meta/entropy.py ---


def test_entropies_a_tenth_apart_are_a_tie_under_a_tolerance_of_a_half() -> None:
    # The habit is sure of action 0 (probabilities 1, 0, 0): normalised entropy 0. The planner
    # commits to action 0 over 3 actions: 0.98, 0.01, 0.01. Worked by hand: H = -(0.98 log2 0.98
    # + 2 * 0.01 log2 0.01) = 0.02856 + 0.13288 = 0.16144 bits, over log2 3 = 1.58496: 0.1019.
    # |0 - 0.1019| <= 0.5, the tolerance given: a tie at every decision, broken by a fair coin,
    # so 60 fresh states draw both experts (one expert only has chance 2 * 2**-60). With the
    # tolerance ignored (1e-9), the sharper habit would win every time.
    criterion = EntropyCriterion(tie_tolerance=0.5)
    criterion.reset(np.random.default_rng(5))
    plan = PlanProposal.make(0, 3, 0.0)
    chosen = set()
    for i in range(60):
        view = HabitView(bytes([i]), np.array([1.0, 0.0, 0.0]), 0, np.zeros(3), np.ones(3), 0.0, 0.0)
        chosen.add(criterion.choose(view, plan))
        assert criterion.stats["h_habit"] == 0.0
        assert math.isclose(criterion.stats["h_planner"], 0.16144 / 1.58496, rel_tol=1e-3)
    assert chosen == {Expert.HABIT, Expert.PLANNER}


# --- agents/robots/habit.py ---


def test_the_habit_robots_decisions_name_no_planner_proposal() -> None:
    # The habit robot is "the model-free Q-learner alone": it has no planner, and
    # Decision.planner_action is "the planner's proposal (-1: the planner did not propose)".
    # So every decision logs planner_action -1 (checked over ten turns), beside its own action.
    for action, decision in habit_robot_turns():
        assert decision is not None and decision.expert == "habit"
        assert decision.planner_action == -1
        assert decision.habit_action == action


# --- agents/partner_specs.py ---


@pytest.mark.parametrize("name", ["Planner", "HABIT"])
def test_a_robot_name_in_capitals_is_refused_as_unknown(name: str) -> None:
    # The registry's names are lower case ("planner", "habit", ...) and a name is built by the
    # registry as given: another spelling is an unknown robot, refused with its name, whether
    # named directly or as the partner opposite the human's seat.
    with pytest.raises(RobotError, match=f"unknown robot '{name}'"):
        make_robot_actor(name)
    with pytest.raises(RobotError, match=f"unknown robot '{name}'"):
        resolve_partner(Agent.HUMAN, name)
