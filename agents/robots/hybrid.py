"""``hybrid``: the paper's architecture, planner and habit arbitrated by a MetaController.

Per decision: the habit (always, it is cheap) learns from the previous executed
transition and proposes an action; the MetaController's criterion decides whether the
planner is consulted (so criteria such as ``vpi`` or ``entropy_and_cost`` can spare
its cost) and whose proposal is executed; a planner failure falls back to the habit.
The habit learns from every executed transition, whoever proposed it, which is how the
planner bootstraps it (the paper's Fig. 5). The decision time charged is the habit's
cost plus, when it was consulted, the planner's.

The planner's model of the human is revised from what the human does (see
:mod:`hg_marl.agents.partner`); when the partner keeps not doing what the plan expects,
the habit's best *feasible* move other than ``wait`` is taken for that decision instead of
the planner's (``reason="partner_stalled"``; never an infeasible no-op). Before either
expert, the progress guard every robot obeys (:mod:`hg_marl.agents.progress`) takes a
feasible move when the state has not changed for ``K`` of its turns (``reason="no_progress"``);
the habit learns from that move like from any other.
With ``partner_aware=True`` the planner plans against the most probable partner type.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.habit import QLearner, QLearnerConfig
from hg_marl.agents.meta.base import Criterion, HabitView, PlanProposal
from hg_marl.agents.meta.controller import MetaController
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.partner_model import LearnedPartner, observe_move, partner_features
from hg_marl.agents.progress import ProgressGuard
from hg_marl.agents.robots.base import LearningRobot, habit_stall_move, plan_proposal
from hg_marl.agents.robots.partnering import Partnering
from hg_marl.core import State, World
from hg_marl.core.errors import RobotError, check_bool
from hg_marl.policy import Turn


class HybridRobot(LearningRobot):
    """Planner + Q-learner + MetaController.

    The defaults are the best measured settings (docs/results.md): the ``entropy_and_cost``
    criterion, which spares the planner once the habit is sure, over a *tabular* habit,
    which is sure only where it has learnt, learning on canonical states
    (``share_objects``: what it learns about one tape holds for its interchangeable
    twins, so it is sure sooner). The paper's configuration is
    ``criterion="random", q_config={"features": "facts"}, share_objects=False``.

    Args:
        criterion: a criterion name (``hg_marl.agents.meta.available_criteria()``) or instance.
        criterion_params: parameters of a criterion given by name.
        planner_config: a ``PlannerConfig`` (None: defaults).
        human_model: the human model the planner assumes (None: cooperative).
        partner_aware: plan against the most probable partner type, learnt online
            (:class:`~hg_marl.agents.partner.PartnerPosterior`) instead of ``human_model``.
        partner_features: the habit also reads the learned partner model's verdicts (does the
            partner refuse to take, to give: :func:`~hg_marl.agents.partner_model.partner_features`),
            so what is learnt about this partner splits the habit's states where it matters.
        q_config, learner, learn, cost, share_objects: as for :class:`~hg_marl.agents.robots.base.LearningRobot`.
    """

    name = "hybrid"
    default_habit = QLearnerConfig(features="tabular")

    def __init__(
        self,
        criterion: str | Criterion = "entropy_and_cost",
        criterion_params: dict[str, Any] | None = None,
        planner_config: Any = None,
        human_model: Any = None,
        q_config: QLearnerConfig | dict[str, Any] | None = None,
        learner: QLearner | None = None,
        learn: bool = True,
        cost: CostModel | None = None,
        partner_aware: bool = False,
        share_objects: bool = True,
        partner_features: bool = False,
    ) -> None:
        super().__init__(q_config, learner, learn, cost, share_objects)
        self.partner_features = check_bool(partner_features, f"{self.name}.partner_features", RobotError)
        self.partner_model = LearnedPartner() if self.partner_features else None
        self.meta = MetaController(criterion, **(criterion_params or {}))
        self.planner_config = planner_config
        self.human_model = human_model
        self.partner_aware = check_bool(partner_aware, f"{self.name}.partner_aware", RobotError)
        self.planner: Any = None
        self.partnering: Any = None
        self.progress = ProgressGuard()

    def _reset(self, world: World) -> None:
        super()._reset(world)
        self.meta.reset(self.rng)
        self.partnering = Partnering(world, self.planner_config, self.human_model, self.partner_aware)
        self.planner = self.partnering.planner
        self.progress.reset()
        if self.partner_model is not None:
            self.partner_model.reset()
            if self._given_learner is None:  # the habit's state grows by the partner model's verdicts
                self.learner = QLearner(world.n_facts + 2, self.n_actions, self.q_config)

    def _habit_facts(self, turn: Turn) -> np.ndarray:
        """The facts (canonical with ``share_objects``), followed by the partner model's verdicts when enabled."""
        facts = super()._habit_facts(turn)
        if self.partner_model is None:
            return facts
        observe_move(self.partner_model, turn.world, self.partnering.previous, turn)
        return np.concatenate([facts, partner_features(self.partner_model)]).astype(facts.dtype)

    def _plan(self, state: State) -> tuple[PlanProposal, float]:
        result = self.planner.plan(state, to_move=self.agent)
        return plan_proposal(result, self.n_actions, self.agent, self.cost), float(result.wall_time)

    def act(self, turn: Turn) -> int:
        """Learn, let both experts propose as the criterion requires, execute the choice."""
        facts = self._habit_facts(turn)
        if self._learn_from(turn.reward, facts):
            self.meta.observe(turn.reward)
        if self.partnering.observe(turn, self.last_decision):
            self.planner = self.partnering.planner
        habit = self.habit
        q, probs, habit_action, wall = self._habit_proposal(facts)
        view = HabitView(
            key=facts.tobytes(),
            probs=probs,
            action=habit_action,
            q=q,
            sd=self._to_robot_actions(habit.uncertainty(facts)),
            weight_amplitude=habit.weight_amplitude,
            cost=self.cost.habit_cost(wall),
            visits=habit.visits(facts),
        )
        planning_time = [0.0]

        def plan() -> PlanProposal:
            proposal, planning_time[0] = self._plan(turn.state)
            return proposal

        guarded = self.progress.observe(turn.state)
        if guarded or self.partnering.monitor.stalled:
            if guarded:
                move = self.progress.move(turn.world, turn.state, self.agent)
            else:
                move = habit_stall_move(turn, q, self.rng)
                self.partnering.monitor.fell_back()
            self.partnering.acted(turn.state, move)
            self._remember(facts, move)
            self._record(
                "guard" if guarded else "habit",
                move,
                habit_action=habit_action,
                decision_time=view.cost,
                weight_amplitude=habit.weight_amplitude,
                reason=self.progress.reason if guarded else "partner_stalled",
                partner=self.partnering.estimate,
            )
            return move
        decision = self.meta.decide(view, plan)
        prop = decision.plan
        if prop is not None:
            self.partnering.planned(prop.success)
            self.planner = self.partnering.planner
        self.partnering.acted(turn.state, decision.action)
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
            partner=self.partnering.estimate,
        )
        return decision.action

    def end(self, turn: Turn, terminated: bool = True) -> None:
        """Last TD step and reward for the criterion (see the base class)."""
        if self.has_pending:
            self.meta.observe(turn.reward)
        super().end(turn, terminated)
