"""The learned partner model's context, pinned for the mutation gate.

Expected by hand: the second feature says whether the robot is offering; no offer
(``offer_by = -1``) and the human's offer (``offer_by = 1``) are both "not the robot's offer".
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.partner_model import LearnedPartner
from hg_marl.core import Agent, State, World


def test_the_robots_offer_is_the_only_offer_that_counts_as_one() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    assert state.offer_by == -1
    wait = world.n_actions(Agent.ROBOT) - 1
    assert LearnedPartner.context(world, state, wait)[1] is False
    robot_offer = State(state.where, state.robot_at, int(Agent.ROBOT), 0)
    human_offer = State(state.where, state.robot_at, int(Agent.HUMAN), 0)
    assert LearnedPartner.context(world, robot_offer, wait)[1] is True
    assert LearnedPartner.context(world, human_offer, wait)[1] is False
