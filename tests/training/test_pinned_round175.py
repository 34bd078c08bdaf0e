"""Values that round 175's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses

import numpy as np

from hg_marl.agents.meta.base import Expert, PlanProposal
from hg_marl.agents.meta.coin import RandomCriterion
from hg_marl.agents.meta.controller import MetaController
from tests.agents.test_pinned_meta_coin_gate import VIEW


def test_the_random_coin_trusts_the_habit_where_it_never_learnt() -> None:
    # The paper's random mix is a plain coin: it trusts the habit everywhere (min_visits 0, as the
    # criteria's base documents for the fixed and random criteria). So a coin with p = 0 never
    # consults the planner, not even in a state the habit has made no update from (visits 0): every
    # decision is the habit's own proposal (action 0 of VIEW), with reason "habit_only".
    asked: list[int] = []

    def plan() -> PlanProposal:
        asked.append(1)
        return PlanProposal.make(2, 3, cost=0.1)

    controller = MetaController(RandomCriterion(0.0))
    controller.reset(np.random.default_rng(0))
    for visits in (0, 1, 4):
        decision = controller.decide(dataclasses.replace(VIEW, visits=visits), plan)
        assert (decision.expert, decision.action, decision.reason) == (Expert.HABIT, 0, "habit_only")
        assert decision.plan is None
    assert asked == []
    assert RandomCriterion().min_visits == 0
