"""``random``: the paper's arbitration, a coin flip between the experts."""

from __future__ import annotations

from hg_marl.agents.meta.base import Criterion, Expert, HabitView, PlanProposal, check_probability


class RandomCriterion(Criterion):
    """Executes the planner's proposal with probability ``p``, the habit's otherwise.

    The coin is flipped before planning, and the planner is consulted only when it won:
    the outcome distribution is the paper's, but a decision that goes to the habit does
    not pay for a plan it would throw away.

    Args:
        p: probability of choosing the planner (Renaudo et al. 2015: 0.5).
    """

    name = "random"

    def __init__(self, p: float = 0.5) -> None:
        super().__init__()
        self.p = check_probability("random.p", p)

    def wants_plan(self, habit: HabitView) -> bool:
        """Flip the coin: plan iff the planner won."""
        return bool(self.rng.random() < self.p)

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """Reached only when the coin chose the planner."""
        return Expert.PLANNER
