"""``vpi`` (Keramati et al. 2011): plan only when perfect information is worth its time.

For each action the value of perfect information (VPI) is the expected gain of knowing
its true value, given the habit's mean ``Q`` and sd ``sigma`` (Gaussian belief):

- for the habit's best action ``a1``, knowing it is worse than the second best ``a2``
  would change the choice: ``VPI(a1) = E[max(Q(a2) - X, 0)]``, ``X ~ N(Q(a1), sigma_a1^2)``;
- for any other action ``a``: ``VPI(a) = E[max(X - Q(a1), 0)]``, ``X ~ N(Q(a), sigma_a^2)``.

With ``g(d, s) = E[max(d + s Z, 0)] = d Phi(d/s) + s phi(d/s)`` both are ``g`` of a gap.
The planner is consulted when ``max_a VPI(a) > tau * R``: the benefit of planning against
its opportunity cost, the average reward ``R`` forgone while deliberating for ``tau``.
``R`` is a running average of the reward per decision, ``R <- R + sigma_R (r - R)``.

Effect: in a new state the habit's uncertainty is the prior, VPI is large and the robot
plans; as TD errors shrink VPI falls below the threshold and the (cheap) habit acts; a
changed human raises TD errors and planning resumes. When the planner is consulted it
is executed (perfect information replaces the habit's estimate for this decision).
"""

from __future__ import annotations

import math

import numpy as np

from hg_marl.agents.meta.base import (
    DEFAULT_MIN_VISITS,
    Criterion,
    Expert,
    HabitView,
    PlanProposal,
    check_count,
    check_positive,
    check_probability,
)

_SQRT2 = math.sqrt(2.0)
_INV_SQRT_2PI = 1.0 / math.sqrt(2.0 * math.pi)


def expected_gain(gap: float, sd: float) -> float:
    """``E[max(gap + sd * Z, 0)]`` for a standard normal ``Z``."""
    if sd <= 0.0:
        return max(gap, 0.0)
    z = gap / sd
    cdf = 0.5 * (1.0 + math.erf(z / _SQRT2))
    pdf = _INV_SQRT_2PI * math.exp(-0.5 * z * z)
    return gap * cdf + sd * pdf


def vpi(q: np.ndarray, sd: np.ndarray) -> np.ndarray:
    """Keramati et al.'s value of perfect information for every action."""
    order = np.argsort(-q, kind="stable")
    a1, a2 = int(order[0]), int(order[1])
    q1 = float(q[a1])
    out = np.array([expected_gain(float(q[a]) - q1, float(sd[a])) for a in range(len(q))])
    out[a1] = expected_gain(float(q[a2]) - q1, float(sd[a1]))
    return out


class VPICriterion(Criterion):
    """Plan iff ``max_a VPI(a) > tau * R``.

    Args:
        tau: planning time in units of decisions, the cost multiplier (default 0.08).
        rate_step: step of the running average reward ``R`` (default 0.02).
        min_visits: the habit acts only in states it has learnt from this many times
            (see ``Criterion.min_visits``).
    """

    name = "vpi"

    def __init__(self, tau: float = 0.08, rate_step: float = 0.02, min_visits: int = DEFAULT_MIN_VISITS) -> None:
        super().__init__()
        self.min_visits = check_count("vpi.min_visits", min_visits)
        self.tau = check_positive("vpi.tau", tau)
        self.rate_step = check_probability("vpi.rate_step", rate_step)
        self._reset()

    def _reset(self) -> None:
        self.reward_rate = 0.0

    def wants_plan(self, habit: HabitView) -> bool:
        """Compare the largest VPI with the opportunity cost of planning."""
        gain = float(vpi(habit.q, habit.sd).max())
        threshold = self.tau * self.reward_rate
        self.stats = {"vpi": gain, "threshold": threshold, "reward_rate": self.reward_rate}
        return gain > threshold

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """Planning was worth it: execute the plan."""
        return Expert.PLANNER

    def observe(self, reward: float) -> None:
        """Update the average reward per decision."""
        self.reward_rate += self.rate_step * (float(reward) - self.reward_rate)
