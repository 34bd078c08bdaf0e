"""The MetaController: asks its criterion whether to plan, then whose action to execute.

It owns the rule common to all criteria: when the planner was consulted and found no
plan, the habit acts (the paper's point that the habit "is always able to propose an
action"). Everything else is the criterion's (see :mod:`hg_marl.agents.meta.base`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, TypeAlias

import numpy as np

from hg_marl.agents.meta.base import Criterion, Expert, HabitView, PlanProposal
from hg_marl.agents.meta.registry import make_criterion

PlanSource: TypeAlias = PlanProposal | Callable[[], PlanProposal] | None
"""A ready proposal, a thunk that plans on demand (so unneeded plans cost nothing), or None."""


@dataclass(frozen=True)
class Decision:
    """The outcome of one arbitration."""

    expert: Expert
    """Whose proposal is executed."""
    action: int
    """The executed action index."""
    plan: PlanProposal | None
    """The planner's proposal if it was consulted, else None."""
    reason: str
    """``"criterion"``, ``"planner_failed"`` (fallback), ``"habit_only"`` (planner not consulted) or
    ``"habit_untrained"`` (the habit has not learnt enough in this state: ``Criterion.min_visits``)."""
    stats: dict[str, float] = field(default_factory=dict)
    """The criterion's numbers behind the choice (entropies, VPI, ...)."""

    @property
    def record(self) -> dict[str, Any]:
        """A flat dict for logs."""
        out: dict[str, Any] = {"expert": str(self.expert), "action": self.action, "reason": self.reason}
        out.update(self.stats)
        return out


class MetaController:
    """Arbitrates between the planner and the habit with one criterion.

    Args:
        criterion: a :class:`Criterion` or a registry name (see ``available_criteria``).
        **params: the criterion's parameters when it is given by name.
    """

    def __init__(self, criterion: Criterion | str = "random", **params: Any) -> None:
        if isinstance(criterion, str):
            criterion = make_criterion(criterion, **params)
        elif params:
            raise ValueError("MetaController: parameters are only accepted with a criterion name")
        self.criterion = criterion

    def reset(self, rng: np.random.Generator) -> None:
        """Start a run; random choices (coin flips, tie-breaks) draw from ``rng``."""
        self.criterion.reset(rng)

    def observe(self, reward: float) -> None:
        """Reward received since the previous decision."""
        self.criterion.observe(reward)

    def decide(self, habit: HabitView, plan: PlanSource) -> Decision:
        """Choose the expert and action for this decision.

        Args:
            habit: the habit's view of the state, including its proposal.
            plan: the planner's proposal, or a thunk producing it, called only if the
                criterion wants a plan; None when no planner is available.
        """
        crit = self.criterion
        if plan is not None and habit.visits < crit.min_visits:
            proposal = plan() if callable(plan) else plan
            crit.stats = {**crit.stats, "visits": float(habit.visits)}
            if proposal.success:
                return Decision(Expert.PLANNER, proposal.action, proposal, "habit_untrained", dict(crit.stats))
            return Decision(Expert.HABIT, habit.action, proposal, "planner_failed", dict(crit.stats))
        if plan is None or not crit.wants_plan(habit):
            return Decision(Expert.HABIT, habit.action, None, "habit_only", dict(crit.stats))
        proposal = plan() if callable(plan) else plan
        if not proposal.success:
            return Decision(Expert.HABIT, habit.action, proposal, "planner_failed", dict(crit.stats))
        expert = crit.choose(habit, proposal)
        action = proposal.action if expert is Expert.PLANNER else habit.action
        return Decision(expert, action, proposal, "criterion", dict(crit.stats))
