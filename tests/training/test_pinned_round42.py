"""Round 42 of the fresh planted bugs: the values its missed bug changed, pinned.

The expected values are stated from the documented rules, not from the code under test:
a :class:`~hg_marl.policy.Decision`'s ``habit_action`` is "the habit's proposal (-1: no
habit)", so every action index from 0 up is a proposal, and
:func:`~hg_marl.training.play.session.robot_move` keeps "the habit's weight amplitude
only when the robot has a habit (it proposed, or acted)".
"""

from __future__ import annotations

import pytest

from hg_marl.core import Agent, World
from hg_marl.policy import Decision
from hg_marl.training.play.session import robot_move


class _Recorded:
    """An actor whose last decision is the given record (what ``decision_of`` reads)."""

    name = "recorded"

    def __init__(self, decision: Decision) -> None:
        self.last_decision = decision


@pytest.mark.parametrize("proposal", [0, 1, "last"])
def test_a_habit_proposal_of_any_action_index_keeps_its_weight_amplitude(proposal: int | str) -> None:
    """The planner acted, the habit proposed action ``proposal``: the robot has a habit, so the
    play page shows its weight amplitude (1.5 here), whichever index it proposed, the first
    (0) included; without a proposal (-1) and with the planner acting there is none to show."""
    world = World("paper2015")
    last = len(world.action_names[Agent.ROBOT]) - 1
    index = last if proposal == "last" else int(proposal)
    proposed = Decision(expert="planner", action=last, habit_action=index, weight_amplitude=1.5)
    assert robot_move(_Recorded(proposed), world, last, False).weight_amplitude == 1.5
    none = Decision(expert="planner", action=last, habit_action=-1, weight_amplitude=1.5)
    assert robot_move(_Recorded(none), world, last, False).weight_amplitude is None
