"""``entropy_and_cost`` (Dromnelle et al. 2022): sharpness traded against decision time.

Each expert ``i`` gets the value ``-(H_i + exp(-kappa * H_MF) * t_i)`` and the larger wins:

- ``H_i``: normalised entropy of its per-state filtered action distribution;
- ``H_MF``: the habit's (filtered) entropy in bits: while the habit is unsure, the cost
  term is damped and sharpness decides (the planner); as the habit becomes sure, the
  cost weight tends to 1 and the cheap habit is preferred;
- ``t_i``: its per-state filtered decision cost over the larger of the two.

The choice is made *before* planning, from the filters, and the planner is consulted
only when it wins, which is the criterion's purpose (cutting the planner's cost). So
the planner's filters are updated only when it is consulted. Before the planner has
been consulted in a state, its distribution there is taken as the canonical committed
one (entropy of ``1 - (N - 1) * 0.01`` on one action) and its cost as its filtered
cost over all states (0 before any planning, which makes it tried first).
"""

from __future__ import annotations

import math

from hg_marl.agents.meta.base import (
    DEFAULT_MIN_VISITS,
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
from hg_marl.agents.meta.entropy import StateFilter


class EntropyAndCostCriterion(Criterion):
    """Argmax of ``-(H_i + exp(-kappa * H_MF) * t_i)``; see the module docstring.

    Args:
        kappa: how fast the cost weight rises as the habit's entropy falls (default 1).
        rate: filter rate for distributions and costs (lineage default 0.6).
        min_visits: the habit acts only in states it has learnt from this many times
            (see ``Criterion.min_visits``).
    """

    name = "entropy_and_cost"

    def __init__(self, kappa: float = 1.0, rate: float = 0.6, min_visits: int = DEFAULT_MIN_VISITS) -> None:
        super().__init__()
        self.min_visits = check_count("entropy_and_cost.min_visits", min_visits)
        self.kappa = check_positive("entropy_and_cost.kappa", kappa)
        self.rate = check_probability("entropy_and_cost.rate", rate)
        self._reset()

    def _reset(self) -> None:
        self._habit = StateFilter(self.rate)
        self._planner = StateFilter(self.rate)
        self._habit_cost: dict[bytes, float] = {}
        self._planner_cost: dict[bytes, float] = {}
        self._planner_cost_all = 0.0
        self._choice = Expert.PLANNER

    def _filter(self, table: dict[bytes, float], key: bytes, value: float) -> float:
        old = table.get(key)
        new = value if old is None else (1.0 - self.rate) * old + self.rate * value
        table[key] = new
        return new

    def wants_plan(self, habit: HabitView) -> bool:
        """Score both experts from the filters; plan only if the planner wins."""
        key = habit.key
        p_habit = self._habit.update(key, habit.probs)
        h_habit = normalised_entropy(p_habit)
        h_mf_bits = entropy_bits(p_habit)
        p_planner = self._planner.values.get(key)
        if p_planner is None:
            p_planner = planner_distribution(0, len(habit.probs))
        h_planner = normalised_entropy(p_planner)
        c_habit = self._filter(self._habit_cost, key, habit.cost)
        c_planner = self._planner_cost.get(key, self._planner_cost_all)
        scale = max(c_habit, c_planner)
        t_habit, t_planner = (c_habit / scale, c_planner / scale) if scale > 0 else (0.0, 0.0)
        weight = math.exp(-self.kappa * h_mf_bits)
        v_habit = -(h_habit + weight * t_habit)
        v_planner = -(h_planner + weight * t_planner)
        self.stats = {
            "h_habit": h_habit,
            "h_planner": h_planner,
            "t_habit": t_habit,
            "t_planner": t_planner,
            "value_habit": v_habit,
            "value_planner": v_planner,
        }
        if v_habit == v_planner:
            self._choice = Expert.HABIT if self.rng.random() < 0.5 else Expert.PLANNER
        else:
            self._choice = Expert.HABIT if v_habit > v_planner else Expert.PLANNER
        return self._choice is Expert.PLANNER

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """The planner won in :meth:`wants_plan`; record its fresh distribution and cost."""
        self._planner.update(habit.key, plan.distribution)
        self._filter(self._planner_cost, habit.key, plan.cost)
        self._planner_cost_all = (1.0 - self.rate) * self._planner_cost_all + self.rate * plan.cost
        return Expert.PLANNER
