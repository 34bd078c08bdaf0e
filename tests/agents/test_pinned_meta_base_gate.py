"""What every MetaController criterion shares (``agents/meta/base.py``), pinned for the mutation gate.

Expected values worked by hand: entropies of small distributions in bits (a fair coin is
1 bit, four equal outcomes 2), the planner's distribution ``1 - (N - 1) * eps`` on its
action and ``eps`` elsewhere, the range checks at their bounds, and the learned
criteria's ``min_visits=5`` that docs/results.md reports as the best measured setting.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.meta import make_criterion
from hg_marl.agents.meta.base import (
    DEFAULT_MIN_VISITS,
    PLANNER_EPSILON,
    Criterion,
    Expert,
    HabitView,
    PlanProposal,
    check_count,
    check_positive,
    check_probability,
    entropy_bits,
    normalised_entropy,
    planner_distribution,
)


def view(**fields: object) -> HabitView:
    base: dict[str, object] = {
        "key": b"s",
        "probs": np.full(4, 0.25),
        "action": 1,
        "q": np.zeros(4),
        "sd": np.ones(4),
        "weight_amplitude": 0.0,
        "cost": 0.001,
    }
    base.update(fields)
    return HabitView(**base)


@pytest.mark.parametrize("name", ["entropy", "entropy_and_cost", "vpi", "learning_state"])
def test_the_learned_criteria_trust_the_habit_after_five_visits_by_default(name: str) -> None:
    """docs/results.md: the habit is trusted in states it has learnt from at least ``min_visits=5`` times."""
    assert DEFAULT_MIN_VISITS == 5
    assert make_criterion(name).min_visits == 5


def test_a_habit_view_built_without_a_count_has_no_visits() -> None:
    assert view().visits == 0


def test_habit_views_compare_by_identity_and_can_be_hashed() -> None:
    """A view holds arrays, whose ``==`` has no single truth value: views are equal only to themselves."""
    a, b = view(), view()
    assert a == a and a != b
    assert len({a: 1, b: 2}) == 2


def test_the_planner_commits_to_its_action_with_all_but_epsilon_per_other_action() -> None:
    p = planner_distribution(2, 5)
    assert PLANNER_EPSILON == 0.01
    assert p.tolist() == pytest.approx([0.01, 0.01, 0.96, 0.01, 0.01])
    proposal = PlanProposal.make(2, 5, cost=0.3, nodes=7, human_action=4)
    assert proposal.success and proposal.action == 2 and proposal.cost == 0.3
    assert proposal.nodes == 7 and proposal.human_action == 4
    assert proposal.distribution.tolist() == pytest.approx(p.tolist())
    assert PlanProposal.make(0, 3, cost=0.0, success=False).success is False


def test_entropy_in_bits_and_normalised_by_its_maximum() -> None:
    assert entropy_bits(np.array([0.5, 0.5])) == pytest.approx(1.0)
    assert entropy_bits(np.array([0.25] * 4)) == pytest.approx(2.0)
    assert entropy_bits(np.array([1.0, 0.0, 0.0])) == 0.0  # zero terms contribute nothing (no NaN)
    assert normalised_entropy(np.array([0.5, 0.5, 0.0, 0.0])) == pytest.approx(0.5)  # 1 bit of log2(4) = 2
    h = -(0.9 * math.log2(0.9) + 0.1 * math.log2(0.1))
    assert entropy_bits(np.array([0.9, 0.1])) == pytest.approx(h)


@pytest.mark.parametrize("value", [0.0, 1.0, 0.5])
def test_a_probability_from_zero_to_one_inclusive_is_accepted(value: float) -> None:
    assert check_probability("x.p", value) == value


@pytest.mark.parametrize("value", [-0.5, -1e-9, 1.0 + 1e-9, 1.5])
def test_a_probability_outside_zero_to_one_is_refused(value: float) -> None:
    with pytest.raises(ValueError, match=r"x\.p: expected a value in \[0, 1\]"):
        check_probability("x.p", value)


def test_counts_are_non_negative_integers() -> None:
    assert check_count("n", 0) == 0 and check_count("n", 3.0) == 3
    for bad in (-1, 2.5, True, "3"):
        with pytest.raises(ValueError, match="n: expected a non-negative integer"):
            check_count("n", bad)


def test_zero_is_non_negative_but_not_positive() -> None:
    assert check_positive("t", 0) == 0.0
    assert check_positive("t", 1e-12, allow_zero=False) == 1e-12
    with pytest.raises(ValueError, match="t: expected a positive number, got 0"):
        check_positive("t", 0, allow_zero=False)
    for bad in (-0.5, -1e-9, -2.0):
        with pytest.raises(ValueError, match="t: expected a non-negative number"):
            check_positive("t", bad)


@pytest.mark.parametrize("allow_zero", [True, False])
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_a_criterion_parameter_that_is_not_finite_is_refused(bad: float, allow_zero: bool) -> None:
    # NaN is neither below nor at 0, so the sign checks alone accept it (vpi's tau = NaN
    # would make every gain NaN); infinity is no rate either.
    with pytest.raises(ValueError, match=r"^vpi\.tau: expected a finite number, got "):
        check_positive("vpi.tau", bad, allow_zero=allow_zero)


class _Counting(Criterion):
    """A criterion that counts its resets, to show what the base class does at the start of a run."""

    name = "counting"

    def __init__(self, level: float = 0.5) -> None:
        super().__init__()
        self.level = level
        self.resets = 0

    def _reset(self) -> None:
        self.resets += 1

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        return Expert.HABIT


def test_a_reset_takes_the_generator_clears_the_stats_and_calls_the_hook() -> None:
    crit, rng = _Counting(), np.random.default_rng(4)
    crit.stats = {"h": 1.0}
    crit.reset(rng)
    assert crit.rng is rng and crit.stats == {} and crit.resets == 1
    assert crit.wants_plan(view()) is True  # the default consults the planner
    assert crit.min_visits == 0
    assert crit.params() == {"level": 0.5}
    assert Expert.PLANNER == "planner" and Expert.HABIT == "habit"
