"""The paper's coin flip (``agents/meta/coin.py``), pinned for the mutation gate.

The coin plans when a uniform draw ``u`` in [0, 1) falls below ``p``: then
``P(plan) = p`` exactly (``u < 0`` never happens, so ``p = 0`` never plans, and
``u < 1`` always does). A stand-in generator returns chosen draws, so the boundary
``u == p`` is checked without waiting for it to come up.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal
from hg_marl.agents.meta.coin import RandomCriterion

VIEW = HabitView(b"s", np.full(3, 1 / 3), 0, np.zeros(3), np.ones(3), 0.0, 0.0)


class _Draws:
    """A generator whose ``random()`` returns the given values in turn."""

    def __init__(self, *values: float) -> None:
        self.values = list(values)

    def random(self) -> float:
        return self.values.pop(0)


def coin(p: float, *draws: float) -> RandomCriterion:
    crit = RandomCriterion(p)
    crit.reset(_Draws(*draws))
    return crit


def test_a_draw_equal_to_p_goes_to_the_habit() -> None:
    """``u < p``: a draw of exactly ``p`` is in the habit's share ``[p, 1)``."""
    crit = coin(0.5, 0.5, 0.4999999)
    assert crit.wants_plan(VIEW) is False
    assert crit.wants_plan(VIEW) is True


def test_a_coin_with_p_zero_never_plans_even_on_a_draw_of_zero() -> None:
    assert coin(0.0, 0.0).wants_plan(VIEW) is False


def test_a_coin_with_p_one_always_plans() -> None:
    assert coin(1.0, 0.9999999999).wants_plan(VIEW) is True


def test_the_planner_is_chosen_once_it_was_consulted_and_the_default_is_a_fair_coin() -> None:
    crit = RandomCriterion()
    assert crit.p == 0.5
    plan = PlanProposal.make(1, 3, cost=0.1)
    assert crit.choose(VIEW, plan) is Expert.PLANNER
