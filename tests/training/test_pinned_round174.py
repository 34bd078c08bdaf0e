"""Values that round 174's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.agents.humans.adversarial import AdversarialHuman
from hg_marl.agents.humans.family_out import FreezeOnOffer, helpful
from hg_marl.core import Agent, State, World
from tests.agents.test_pinned_human_adversarial_gate import PAPER, named


def test_a_helpful_family_out_partner_hands_over_to_the_robot_at_the_handover_place() -> None:
    # paper2015 by hand: the human holds tape1 (its hand is place 8), tape2 lies on human_mat_1 (4),
    # tape3 on mat_centre (1), nothing is offered. The human reaches no bin, so its tidying rule
    # either hands tape1 over, which it does exactly when the robot (empty-handed) stands at the
    # handover location 3, or puts it on mat_shared, the one free spot the robot reaches.
    world = World("paper2015")
    at_handover, away = State((8, 4, 1), 3), State((8, 4, 1), 0)
    names = world.action_names[Agent.HUMAN]
    assert names[helpful(world, at_handover)] == "give(tape1)"
    assert names[helpful(world, away)] == "place(tape1,mat_shared)"
    # fo_freeze_on_offer with no offer pending tidies by the same rule, handing over included.
    assert named(world, FreezeOnOffer().distribution(world, at_handover)) == [("give(tape1)", 1.0)]


@pytest.mark.parametrize("p_idle", [-0.1, 1.5])
def test_the_adversarial_human_refuses_an_idle_chance_that_is_not_a_probability(p_idle: float) -> None:
    with pytest.raises(ValueError, match=r"p_idle must be a probability in \[0, 1\]"):
        AdversarialHuman(p_idle=p_idle)
    # the bounds themselves are probabilities: p_idle 1 idles for sure on the shared-mat steal
    dist = named(PAPER, AdversarialHuman(p_idle=1.0).distribution(PAPER, State((3, 0, 1), 3)))
    assert dist == [("pick(tape1)", 0.0), ("wait", 1.0)]
