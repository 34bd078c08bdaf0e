"""``habit``: the model-free Q-learner alone, learning online (the paper's "MF alone").

It samples from its Boltzmann distribution over *all* actions, feasible or not: the
action mask is not used, so, as in the paper, it must learn from failures (which cost
only the precondition check) which actions are infeasible where.
"""

from __future__ import annotations

from hg_marl.agents.robots.base import LearningRobot
from hg_marl.policy import Turn


class HabitRobot(LearningRobot):
    """Q-learner alone; see :class:`~hg_marl.agents.robots.base.LearningRobot` for the arguments."""

    name = "habit"

    def act(self, turn: Turn) -> int:
        """TD step on the previous transition, then sample the Boltzmann policy."""
        facts = self._habit_facts(turn)
        self._learn_from(turn.reward, facts)
        _, _, action, wall = self._habit_proposal(facts)
        self._remember(facts, action)
        self._record(
            "habit",
            action,
            habit_action=action,
            decision_time=self.cost.habit_cost(wall),
            weight_amplitude=self.habit.weight_amplitude,
        )
        return action
