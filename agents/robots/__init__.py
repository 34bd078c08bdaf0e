"""Robot agents, each an :class:`hg_marl.policy.Actor`, and their registry.

=============  ==============================================================
``planner``    the human-aware planner alone, replanning at every decision
``habit``      the Q-learner alone, learning online (the paper's "MF")
``hybrid``     planner + Q-learner arbitrated by a MetaController ``criterion``
``random``     uniform over the feasible actions (from the mask)
``sb3``        a trained Stable-Baselines3 model (``path=``; torch loads on first use)
=============  ==============================================================

After every ``act`` a robot's ``last_decision`` is a :class:`hg_marl.policy.Decision`
(its fields are documented there): who decided, both experts' proposals, planning time
and nodes, the decision time to charge to the clock (the deterministic
:class:`~hg_marl.agents.meta.cost.CostModel` by default), the human action the plan
expects, the habit's weight amplitude and the criterion's numbers.
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
