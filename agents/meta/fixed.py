"""Single-expert criteria: ``planner`` and ``habit`` (the paper's "alone" conditions)."""

from __future__ import annotations

from hg_marl.agents.meta.base import Criterion, Expert, HabitView, PlanProposal


class PlannerOnly(Criterion):
    """Always the planner (the habit still learns from the executed transitions)."""

    name = "planner"

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """The planner, always."""
        return Expert.PLANNER


class HabitOnly(Criterion):
    """Always the habit; the planner is never consulted, so its cost is never paid."""

    name = "habit"

    def wants_plan(self, habit: HabitView) -> bool:
        """Never."""
        return False

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """The habit, always."""
        return Expert.HABIT
