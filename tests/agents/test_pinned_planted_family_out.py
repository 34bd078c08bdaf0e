"""Pinned against planted bugs in the family-out partners, each expected value worked by hand.

``fo_bursts`` works ``work`` seconds then rests ``rest``, period ``work + rest``: for
work = 90 s, rest = 60 s (period 150 s), working on [0, 90) and [150, 240), resting on
[90, 150) and [240, 300). ``fo_after_waits`` takes an offer only when the two robot
moves before the offering one were waits (the offer itself is this cycle's move).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.family_out import Bursts, helpful
from hg_marl.core import Agent, World
from hg_marl.core.types import Kind


@pytest.mark.parametrize(
    ("clock", "resting"),
    [
        (0.0, False),
        (30.0, False),
        (89.0, False),
        (90.0, True),
        (100.0, True),
        (149.0, True),
        (150.0, False),
        (160.0, False),
        (239.0, False),
        (240.0, True),
        (299.0, True),
    ],
)
def test_bursts_phase_by_the_clock(clock: float, resting: bool) -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    working = helpful(world, state)
    assert working != wait_index(world)  # the initial table has work to do
    human = Bursts(work=90.0, rest=60.0)
    action = human.choose(SimpleNamespace(clock=clock, world=world, state=state))
    assert action == (wait_index(world) if resting else working)


def _after_waits_answers(world: World, robot_moves: list[int]) -> list[int]:
    """``fo_after_waits``'s answers on ``paper2015``, a turn per robot move, the robot offering object 0."""
    from hg_marl.agents.humans.family_out import AfterWaits
    from hg_marl.core import State

    # object 0 in the robot's hand (spot 7), offered to the human; the robot at the human's side
    offer = State(where=(7, 4, 2), robot_at=3, offer_by=int(Agent.ROBOT), offer_obj=0)
    human = AfterWaits()
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    return [human.choose(SimpleNamespace(world=world, state=offer, last_actions=(m, -1))) for m in robot_moves]


def test_after_waits_takes_the_offer_made_right_after_two_waits() -> None:
    world = World("paper2015")
    wait, give0 = world.n_actions(Agent.ROBOT) - 1, 6  # robot action 6: GIVE object 0
    assert world.actions(Agent.ROBOT)[give0].kind == Kind.GIVE
    answers = _after_waits_answers(world, [wait, wait, give0])
    took = world.actions(Agent.HUMAN)[answers[-1]]
    assert (took.kind, took.obj) == (Kind.TAKE, 0)  # wait, wait, then the offer: "this is for you"


@pytest.mark.parametrize("moves", [[0, 6], [17, 6], [0, 17, 6], [17, 0, 6], [6, 17, 6]])
def test_after_waits_leaves_an_offer_without_two_waits_just_before(moves: list[int]) -> None:
    world = World("paper2015")
    answers = _after_waits_answers(world, moves)
    assert world.actions(Agent.HUMAN)[answers[-1]].kind != Kind.TAKE
