"""The registry of robot agents: ``make_robot(name, **params)``."""

from __future__ import annotations

import inspect
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
from hg_marl.core.spec import construct

ROBOTS: dict[str, type[Robot]] = {
    c.name: c for c in (PlannerRobot, HabitRobot, HybridRobot, RandomRobot, SB3Robot, BeliefRobot, MemoryRobot)
}
"""Robot classes by name (a registry of classes: the only module-level table)."""


def available_robots() -> tuple[str, ...]:
    """Names accepted by :func:`make_robot`."""
    return tuple(ROBOTS)


def robot_params(name: str) -> tuple[str, ...]:
    """Parameter names a robot accepts."""
    return tuple(inspect.signature(_lookup(name)).parameters)


def _lookup(name: str) -> type[Robot]:
    try:
        return ROBOTS[name]
    except KeyError:
        raise RobotError(f"unknown robot {name!r}; available: {', '.join(ROBOTS)}") from None


def make_robot(name: str, **params: Any) -> Robot:
    """Build a robot from a spec: ``make_robot("hybrid:criterion=vpi")`` = ``make_robot("hybrid", criterion="vpi")``.

    Parameters in the spec are read by the one spec parser (:mod:`hg_marl.core.spec`),
    typed by the constructor's defaults; keyword arguments win over them.

    Raises:
        RobotError: unknown name (the message lists the known ones), unknown parameter
            (lists the accepted ones) or a bad value; CriterionError for the criterion's own.
    """
    robot: Robot = construct(name, ROBOTS, params, kind="robot", error=RobotError)
    return robot
