"""Robot agents, each an :class:`hg_marl.policy.Actor`, and their registry.

=============  ==============================================================
``planner``    the human-aware planner alone, replanning at every decision
``habit``      the Q-learner alone, learning online (the paper's "MF")
``hybrid``     planner + Q-learner arbitrated by a MetaController ``criterion``
``random``     uniform over the feasible actions (from the mask)
``sb3``        a trained Stable-Baselines3 model (``path=``; torch loads on first use)
=============  ==============================================================

After every ``act`` a robot's ``last_decision`` dict holds: ``expert`` ("planner",
"habit" or "random"), ``action``, ``planner_action`` and ``habit_action`` (-1 when that
expert did not propose), ``planning_time`` (wall seconds), ``planner_nodes``,
``planner_success``, ``decision_time`` (simulated seconds to charge to the clock; the
deterministic :class:`~hg_marl.agents.meta.cost.CostModel` by default),
``expected_human_action`` (-1 if none) and, for learning robots, ``weight_amplitude``.
The hybrid adds ``planner_consulted``, ``reason`` and the criterion's ``meta_*`` numbers.
"""

from hg_marl.agents.robots.base import LearningRobot, Robot
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.agents.robots.hybrid import HybridRobot
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.agents.robots.registry import ROBOTS, available_robots, make_robot, robot_params
from hg_marl.agents.robots.uniform import RandomRobot

__all__ = [
    "ROBOTS",
    "HabitRobot",
    "HybridRobot",
    "LearningRobot",
    "PlannerRobot",
    "RandomRobot",
    "Robot",
    "available_robots",
    "make_robot",
    "robot_params",
]
