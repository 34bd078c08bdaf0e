"""Pinned against a planted bug: the learned partner forgets its chances as it forgets its counts.

Expected values worked by hand: with ``forget = 0.5`` each refusal of an offer adds 1 to
the weighted number of chances of ``take`` after halving the old ones, so after n refusals
the chances are ``1 + 0.5 + ... + 0.5**(n-1) = 2 - 2**(1-n)``, always under 2: the
default verdict (3 chances) is never reached, and the kind is never refused.
"""

from __future__ import annotations

import pytest

from hg_marl.agents.partner_model import LearnedPartner
from hg_marl.core import Agent, Kind, World
from tests.agents.test_partner_model import offered_state


def test_chances_are_forgotten_like_the_counts() -> None:
    world = World("paper2015")
    mid, give = offered_state(world)
    wait = world.n_actions(Agent.HUMAN) - 1
    model = LearnedPartner(forget=0.5)
    for n in range(1, 7):
        model.update(world, mid, give, wait)
        assert model.chances[int(Kind.TAKE)] == pytest.approx(2 - 2 ** (1 - n))
        assert model.taken[int(Kind.TAKE)] == 0
    assert Kind.TAKE not in model.refused_kinds()  # at most 2 weighted chances, under the 3 asked
    assert Kind.TAKE in model.refused_kinds(min_chances=1.9)
