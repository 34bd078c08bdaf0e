"""``hybrid``: the paper's architecture, planner and habit arbitrated by a MetaController.

Per decision: the habit (always, it is cheap) learns from the previous executed
transition and proposes an action; the MetaController's criterion decides whether the
planner is consulted (so criteria such as ``vpi`` or ``entropy_and_cost`` can spare
its cost) and whose proposal is executed; a planner failure falls back to the habit.
The habit learns from every executed transition, whoever proposed it, which is how the
planner bootstraps it (the paper's Fig. 5). The decision time charged is the habit's
cost plus, when it was consulted, the planner's.
"""

from __future__ import annotations

from typing import Any

from hg_marl.agents.habit import QLearner, QLearnerConfig
from hg_marl.agents.meta.base import Criterion, HabitView, PlanProposal
from hg_marl.agents.meta.controller import MetaController
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.robots.base import LearningRobot, make_planner, plan_proposal
from hg_marl.core import State, World
from hg_marl.policy import Turn


class HybridRobot(LearningRobot):
    """Planner + Q-learner + MetaController.

    Args:
        criterion: a criterion name (``hg_marl.agents.meta.available_criteria()``) or instance.
        criterion_params: parameters of a criterion given by name.
        planner_config: a ``PlannerConfig`` (None: defaults).
        human_model: the human model the planner assumes (None: cooperative).
        q_config, learner, learn, cost: as for :class:`~hg_marl.agents.robots.base.LearningRobot`.
    """

    name = "hybrid"

    def __init__(
        self,
        criterion: str | Criterion = "random",
        criterion_params: dict[str, Any] | None = None,
        planner_config: Any = None,
        human_model: Any = None,
        q_config: QLearnerConfig | dict[str, Any] | None = None,
        learner: QLearner | None = None,
        learn: bool = True,
        cost: CostModel | None = None,
    ) -> None:
        super().__init__(q_config, learner, learn, cost)
        self.meta = MetaController(criterion, **(criterion_params or {}))
        self.planner_config = planner_config
        self.human_model = human_model
        self.planner: Any = None

    def _reset(self, world: World) -> None:
        super()._reset(world)
        self.meta.reset(self.rng)
        self.planner = make_planner(world, self.planner_config, self.human_model)

    def _plan(self, state: State) -> tuple[PlanProposal, float]:
        result = self.planner.plan(state, to_move=self.agent)
        return plan_proposal(result, self.n_actions, self.agent, self.cost), float(result.wall_time)

    def act(self, turn: Turn) -> int:
        """Learn, let both experts propose as the criterion requires, execute the choice."""
        facts = turn.observation["observation"]
        if self._learn_from(turn.reward, facts):
            self.meta.observe(turn.reward)
        habit = self.habit
        q, probs, habit_action, wall = self._habit_proposal(facts)
        view = HabitView(
            key=facts.tobytes(),
            probs=probs,
            action=habit_action,
            q=q,
            sd=habit.uncertainty(facts),
            weight_amplitude=habit.weight_amplitude,
            cost=self.cost.habit_cost(wall),
        )
        planning_time = [0.0]

        def plan() -> PlanProposal:
            proposal, planning_time[0] = self._plan(turn.state)
            return proposal

        decision = self.meta.decide(view, plan)
        prop = decision.plan
        self._remember(facts, decision.action)
        self._record(
            str(decision.expert),
            decision.action,
            habit_action=habit_action,
            planner_action=prop.action if prop is not None and prop.success else -1,
            planning_time=planning_time[0],
            planner_nodes=prop.nodes if prop is not None else 0,
            planner_success=bool(prop is not None and prop.success),
            planner_consulted=prop is not None,
            decision_time=view.cost + (prop.cost if prop is not None else 0.0),
            expected_human_action=prop.human_action if prop is not None else -1,
            weight_amplitude=habit.weight_amplitude,
            reason=decision.reason,
            stats=tuple((k, float(v)) for k, v in decision.stats.items()),
        )
        return decision.action

    def end(self, turn: Turn, terminated: bool = True) -> None:
        """Last TD step and reward for the criterion (see the base class)."""
        if self.has_pending:
            self.meta.observe(turn.reward)
        super().end(turn, terminated)
