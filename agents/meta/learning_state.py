"""``learning_state``: the habit takes over where its values have stopped changing.

The paper's own proposal (Renaudo et al. 2015, section V): "give to the MetaController
an information on the variation of MF weights". The habit acts in a state when the
variation of its value there has settled: the running root-mean-square TD error of the
proposed action in this state (``HabitView.sd``, the same estimate VPI uses) is below
``threshold``, and the habit has learnt from this state at least ``min_visits`` times.

Why per state. An earlier version filtered the *global* relative change of the weight
amplitude, ``|A_t - A_{t-1}| / A_t``. As a tabular habit meets new states the amplitude
grows roughly linearly, so that ratio decays like ``1 / t`` whatever the habit knows:
it crossed the threshold at the same simulated time in every run, and the habit then
took over everywhere, including states it had never seen (``docs/results.md`` has the
runs). In the adaptation runs this happened at the same moment for every switch (before
the switch, the runs are identical), which is why the criterion seemed to "anticipate"
the human's switch. Variation taken where the decision is taken has no such drift, and
it rises again when the human changes (TD errors grow), which returns control to the
planner by itself.
"""

from __future__ import annotations

from hg_marl.agents.meta.base import (
    DEFAULT_MIN_VISITS,
    Criterion,
    Expert,
    HabitView,
    PlanProposal,
    check_count,
    check_positive,
)


class LearningStateCriterion(Criterion):
    """Habit where its value's running RMS TD error is below ``threshold``.

    Args:
        threshold: RMS TD error (reward units) of the habit's proposed action in this
            state under which the habit acts.
        min_visits: the habit acts only in states it has learnt from this many times.
    """

    name = "learning_state"

    def __init__(self, threshold: float = 0.5, min_visits: int = DEFAULT_MIN_VISITS) -> None:
        super().__init__()
        self.threshold = check_positive("learning_state.threshold", threshold, allow_zero=False)
        self.min_visits = check_count("learning_state.min_visits", min_visits)

    def wants_plan(self, habit: HabitView) -> bool:
        """Plan unless the habit's value for its proposal has settled in this state."""
        change = float(habit.sd[habit.action])
        settled = change < self.threshold and habit.visits >= self.min_visits
        self.stats = {"td_rms": change, "visits": float(habit.visits)}
        return not settled

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """The habit has not settled: the planner acts."""
        return Expert.PLANNER
