"""Pinned against a planted bug: ``fo_bursts`` works ``work`` seconds then rests ``rest``, period ``work + rest``.

Expected phases worked by hand for work = 90 s, rest = 60 s (period 150 s): working on
[0, 90) and [150, 240), resting on [90, 150) and [240, 300).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.family_out import Bursts, helpful
from hg_marl.core import World


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
