"""``planner``: the goal-directed expert alone, replanning at every decision.

Replanning each turn (rather than executing a stored plan step by step, as HATP's
supervisor does) keeps the robot correct when the human deviates from the plan; the
planner is deterministic, so with a cooperative human it reproduces the stored plan.
On failure the planner's result proposes ``wait``.

The model of the human is revised from what the human does (see
:mod:`hg_marl.agents.partner`): expected actions the human keeps refusing are ruled out,
and a robot whose partner keeps not doing what is expected takes any feasible move for
one decision, so no partner who leaves the task solvable can hold it waiting forever; and
the progress guard every robot obeys (:mod:`hg_marl.agents.progress`) takes a feasible
move when the state has not changed for ``K`` of its turns (``reason="no_progress"``).
With ``partner_aware=True`` the planner plans against the most probable partner type.
"""

from __future__ import annotations

from typing import Any

from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.progress import ProgressGuard
from hg_marl.agents.robots.base import Robot, plan_proposal, stall_move
from hg_marl.agents.robots.partnering import Partnering
from hg_marl.core import World
from hg_marl.core.errors import RobotError, check_bool
from hg_marl.policy import Turn


class PlannerRobot(Robot):
    """Executes the planner's next robot action.

    Args:
        planner_config: a ``PlannerConfig`` (None: defaults).
        human_model: the human model the planner assumes (None: cooperative).
        cost: decision cost model.
        partner_aware: plan against the most probable partner type, learnt online
            (:class:`~hg_marl.agents.partner.PartnerPosterior`) instead of ``human_model``.
    """

    name = "planner"

    def __init__(
        self,
        planner_config: Any = None,
        human_model: Any = None,
        cost: CostModel | None = None,
        partner_aware: bool = False,
    ) -> None:
        super().__init__(cost)
        self.planner_config = planner_config
        self.human_model = human_model
        self.partner_aware = check_bool(partner_aware, f"{self.name}.partner_aware", RobotError)
        self.planner: Any = None
        self.partnering: Any = None
        self.progress = ProgressGuard()

    def _reset(self, world: World) -> None:
        self.partnering = Partnering(world, self.planner_config, self.human_model, self.partner_aware)
        self.planner = self.partnering.planner
        self.progress.reset()

    def act(self, turn: Turn) -> int:
        """Plan from the current state and return the plan's first robot action."""
        if self.partnering.observe(turn, self.last_decision):
            self.planner = self.partnering.planner
        if self.progress.observe(turn.state):
            action = self.progress.move(turn.world, turn.state, self.agent)
            self.partnering.acted(turn.state, action)
            self._record("guard", action, reason=self.progress.reason, partner=self.partnering.estimate)
            return action
        if self.partnering.monitor.stalled:
            action = stall_move(turn, self.rng)
            self.partnering.monitor.fell_back()
            self.partnering.acted(turn.state, action)
            self._record("random", action, reason="partner_stalled", partner=self.partnering.estimate)
            return action
        result = self.planner.plan(turn.state, to_move=self.agent)
        prop = plan_proposal(result, self.n_actions, self.agent, self.cost)
        self.partnering.planned(prop.success)
        self.planner = self.partnering.planner
        self._record(
            "planner",
            prop.action,
            planner_action=prop.action,
            planning_time=float(result.wall_time),
            planner_nodes=prop.nodes,
            planner_success=prop.success,
            decision_time=prop.cost,
            planner_consulted=True,
            expected_human_action=prop.human_action,
            reason=str(result.reason),
            partner=self.partnering.estimate,
        )
        self.partnering.acted(turn.state, prop.action)
        return prop.action

    def follow(self, turn: Turn, action: int) -> None:
        """Keep the partner model in step on a turn another expert decided ``action``.

        A robot that consults this planner only now and then (the belief robot, off its
        members) would otherwise hold blocks past the tasks solved in between, and compare
        the human's move with an expectation from an earlier spell.
        """
        self.partnering.observe(turn, self.last_decision)
        self.planner = self.partnering.planner
        self._record_none()
        self.partnering.acted(turn.state, action)
