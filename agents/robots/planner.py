"""``planner``: the goal-directed expert alone, replanning at every decision.

Replanning each turn (rather than executing a stored plan step by step, as HATP's
supervisor does) keeps the robot correct when the human deviates from the plan; the
planner is deterministic, so with a cooperative human it reproduces the stored plan.
On failure the planner's result proposes ``wait``.
"""

from __future__ import annotations

from typing import Any

from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.robots.base import Robot, make_planner, plan_proposal
from hg_marl.core import World
from hg_marl.policy import Turn


class PlannerRobot(Robot):
    """Executes the planner's next robot action.

    Args:
        planner_config: a ``PlannerConfig`` (None: defaults).
        human_model: the human model the planner assumes (None: cooperative).
        cost: decision cost model.
    """

    name = "planner"

    def __init__(self, planner_config: Any = None, human_model: Any = None, cost: CostModel | None = None) -> None:
        super().__init__(cost)
        self.planner_config = planner_config
        self.human_model = human_model
        self.planner: Any = None

    def _reset(self, world: World) -> None:
        self.planner = make_planner(world, self.planner_config, self.human_model)

    def act(self, turn: Turn) -> int:
        """Plan from the current state and return the plan's first robot action."""
        result = self.planner.plan(turn.state, to_move=self.agent)
        prop = plan_proposal(result, self.n_actions, self.agent, self.cost)
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
        )
        return prop.action
