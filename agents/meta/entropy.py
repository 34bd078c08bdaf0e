"""``entropy``: trust the expert whose (filtered) action distribution is sharper.

Renaudo et al. 2015 (ICDL, "Which criteria...") and Dromnelle et al.: each expert's
distribution over actions is low-pass filtered per state, ``p <- (1 - a) p + a p_new``,
and the expert with the lower normalised entropy ``H / log2 |A|`` is executed (ties
broken at random). The planner always commits to one action, so its distribution is
``1 - (N - 1) * 0.01`` on it and 0.01 elsewhere (normalised entropy ~0.32 for 18
actions); the habit wins once its Boltzmann distribution is sharper than that in the
state, or when the planner's proposals in a state keep changing.

A filter starts at the first distribution it sees in a state (no uniform prior, which
would make the planner look uncertain in every new state). Both experts are consulted
at every decision, as in the original criterion.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.meta.base import (
    DEFAULT_MIN_VISITS,
    Criterion,
    Expert,
    HabitView,
    PlanProposal,
    check_count,
    check_probability,
    normalised_entropy,
)


class StateFilter:
    """Per-state low-pass filter of a probability vector."""

    def __init__(self, rate: float) -> None:
        self.rate = rate
        self.values: dict[bytes, np.ndarray] = {}

    def update(self, key: bytes, p_new: np.ndarray) -> np.ndarray:
        """Filter ``p_new`` into the state's value and return it."""
        p = self.values.get(key)
        p = p_new.copy() if p is None else (1.0 - self.rate) * p + self.rate * p_new
        self.values[key] = p
        return p


class EntropyCriterion(Criterion):
    """Argmin of the filtered normalised entropies; random tie-break.

    Args:
        rate: filter rate ``a`` (lineage default 0.6).
        tie_tolerance: entropies closer than this count as a tie.
        min_visits: the habit acts only in states it has learnt from this many times
            (see ``Criterion.min_visits``).
    """

    name = "entropy"

    def __init__(self, rate: float = 0.6, tie_tolerance: float = 1e-9, min_visits: int = DEFAULT_MIN_VISITS) -> None:
        super().__init__()
        self.min_visits = check_count("entropy.min_visits", min_visits)
        self.rate = check_probability("entropy.rate", rate)
        self.tie_tolerance = float(tie_tolerance)
        self._reset()

    def _reset(self) -> None:
        self._habit = StateFilter(self.rate)
        self._planner = StateFilter(self.rate)

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """Filter both distributions for this state and pick the lower entropy."""
        h_habit = normalised_entropy(self._habit.update(habit.key, habit.probs))
        h_planner = normalised_entropy(self._planner.update(habit.key, plan.distribution))
        self.stats = {"h_habit": h_habit, "h_planner": h_planner}
        if abs(h_habit - h_planner) <= self.tie_tolerance:
            return Expert.HABIT if self.rng.random() < 0.5 else Expert.PLANNER
        return Expert.HABIT if h_habit < h_planner else Expert.PLANNER
