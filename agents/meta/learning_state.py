"""``learning_state``: the habit takes over once its weights have stopped changing.

The paper's own proposal (Renaudo et al. 2015, section V): "give to the MetaController
an information on the variation of MF weights". At each decision we measure the relative
change of the weight amplitude ``A = sum |w|`` since the previous decision,
``d = |A_t - A_{t-1}| / max(A_t, eps)``, low-pass filter it, ``f <- (1 - a) f + a d``
(``f`` starts at 1: nothing is known to have settled), and let the habit act while
``f < threshold``. The measure is relative so that one threshold fits any task's reward
scale and feature count. It is global, not per state: the weights are shared by all
states in the paper's linear habit.

Control returns to the planner by itself: when the habit's actions fail or the human
changes, TD errors move the weights again and ``f`` rises above the threshold.
"""

from __future__ import annotations

from hg_marl.agents.meta.base import (
    Criterion,
    Expert,
    HabitView,
    PlanProposal,
    check_positive,
    check_probability,
)


class LearningStateCriterion(Criterion):
    """Habit while the filtered relative weight change is below ``threshold``.

    Args:
        threshold: filtered relative change per decision under which the habit acts.
        rate: filter rate ``a``; smaller than the entropy filter's 0.6 because a single
            decision's change is noisy (many decisions leave the weights untouched).
        min_amplitude: the habit must have learnt something (``A`` above this) to act.
    """

    name = "learning_state"

    def __init__(self, threshold: float = 1e-3, rate: float = 0.1, min_amplitude: float = 1e-6) -> None:
        super().__init__()
        self.threshold = check_positive("learning_state.threshold", threshold, allow_zero=False)
        self.rate = check_probability("learning_state.rate", rate)
        self.min_amplitude = check_positive("learning_state.min_amplitude", min_amplitude)
        self._reset()

    def _reset(self) -> None:
        self.change = 1.0
        self._last: float | None = None

    def wants_plan(self, habit: HabitView) -> bool:
        """Update the filtered weight change; plan unless the habit has settled."""
        amplitude = habit.weight_amplitude
        if self._last is not None and max(amplitude, self._last) > 0.0:  # nothing learnt yet: no news
            d = abs(amplitude - self._last) / max(amplitude, 1e-12)
            self.change += self.rate * (d - self.change)
        self._last = amplitude
        settled = self.change < self.threshold and amplitude > self.min_amplitude
        self.stats = {"weight_change": self.change, "weight_amplitude": amplitude}
        return not settled

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """The habit has not settled: the planner acts."""
        return Expert.PLANNER
