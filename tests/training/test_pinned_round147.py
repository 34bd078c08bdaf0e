"""Values that round 147's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.family_out import Bursts, helpful
from hg_marl.agents.partner_model import LearnedPartner
from hg_marl.core import Agent, Kind, World
from tests.agents.test_partner_model import offered_state


@pytest.mark.parametrize(("clock", "resting"), [(100.0, True), (160.0, False), (240.0, True)])
def test_fo_bursts_by_default_works_90_s_and_rests_60_s(clock: float, resting: bool) -> None:
    # docs/adaptation.md: "fo_bursts | works 90 s, rests 60 s, by the clock". Period 150 s:
    # working on [0, 90) and [150, 240), resting on [90, 150) and [240, 300). So at 100 s it
    # rests, at 160 s (10 s into the second period) it works, at 240 s (90 s into it) it rests.
    # A 90 s rest (period 180 s) would rest at 160 s and work at 240 s.
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    working = helpful(world, state)
    assert working != wait_index(world)  # the initial table has work to do
    for human in (Bursts(), make_human("fo_bursts")):
        assert isinstance(human, Bursts)
        action = human.choose(SimpleNamespace(clock=clock, world=world, state=state))
        assert action == (wait_index(world) if resting else working)


def test_the_learned_partners_predictive_adds_alpha_to_every_count() -> None:
    # p(kind) = (n_kind + alpha) / sum over the k feasible kinds (n + alpha). With alpha = 2 and no
    # data every kind is 2 / 2k = 1 / k; after one wait (its count 1) wait is (1 + 2) / (1 + 2k) and
    # every other kind 2 / (1 + 2k); the kinds' probabilities sum to 1 either way.
    world = World("paper2015")
    mid, give = offered_state(world)
    acts = world.actions(Agent.HUMAN)
    feasible = world.feasible_indices(mid, Agent.HUMAN)
    k = len({acts[i].kind for i in feasible})
    wait = world.n_actions(Agent.HUMAN) - 1
    take = int(Kind.TAKE)
    model = LearnedPartner(alpha=2.0, forget=0.5)
    before = model.kind_distribution(world, mid, give)
    assert before[int(Kind.WAIT)] == pytest.approx(1.0 / k)
    assert sum(before.values()) == pytest.approx(1.0)
    model.update(world, mid, give, wait)
    after = model.kind_distribution(world, mid, give)
    assert after[int(Kind.WAIT)] == pytest.approx(3.0 / (1.0 + 2.0 * k))
    assert after[take] == pytest.approx(2.0 / (1.0 + 2.0 * k))
    assert sum(after.values()) == pytest.approx(1.0)
    assert sum(p for _, p in model.distribution(world, mid, give)) == pytest.approx(1.0)
