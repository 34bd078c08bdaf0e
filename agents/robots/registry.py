"""The registry of robot agents: ``make_robot(name, **params)``.

A :class:`hg_marl.core.registry.Registry` like the humans' and the criteria's: each
robot's parameters and defaults are read from its constructor's signature.
"""

from __future__ import annotations

from typing import Any

from hg_marl.agents.robots.base import Robot
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.agents.robots.hybrid import HybridRobot
from hg_marl.agents.robots.memory import MemoryRobot
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.agents.robots.sb3 import SB3Robot
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.core.errors import RobotError
from hg_marl.core.registry import Registry

ROBOTS = Registry(
    "robot", RobotError, (PlannerRobot, HabitRobot, HybridRobot, RandomRobot, SB3Robot, BeliefRobot, MemoryRobot)
)
"""Every robot by name (``ROBOTS[name].factory()`` is its class)."""


def available_robots() -> tuple[str, ...]:
    """Names accepted by :func:`make_robot`."""
    return tuple(ROBOTS)


def robot_params(name: str) -> tuple[str, ...]:
    """Parameter names a robot accepts."""
    return tuple(ROBOTS.lookup(name).defaults())


def make_robot(name: str, **params: Any) -> Robot:
    """Build a robot from a spec: ``make_robot("hybrid:criterion=vpi")`` = ``make_robot("hybrid", criterion="vpi")``.

    Parameters in the spec are read by the one spec parser (:mod:`hg_marl.core.spec`),
    typed by the constructor's defaults; keyword arguments win over them.

    Raises:
        RobotError: unknown name (the message lists the known ones), unknown parameter
            (lists the accepted ones) or a bad value; CriterionError for the criterion's own.
    """
    robot: Robot = ROBOTS.make(name, **params)
    return robot
