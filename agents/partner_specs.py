"""A seat's partner as the user names it: a registry name, an Actor, or a list of them.

Humans: a registry name (``"lazy:p_idle=0.5"``), an Actor, or a list of them (a
population; one is drawn per episode with the view's generator). Robots likewise, with
names from ``hg_marl.agents.robots.make_robot`` (``planner``, ``habit``, ``hybrid``,
``random``). The partner's decision time is not charged to the clock.
"""

from __future__ import annotations

from collections.abc import Sequence

from hg_marl.agents.humans.registry import resolve_human
from hg_marl.core import Agent
from hg_marl.policy import Actor


def make_robot_actor(robot: str | Actor) -> Actor:
    """An Actor for the robot seat from a name or an instance (see the module docstring)."""
    if not isinstance(robot, str):
        if not isinstance(robot, Actor):
            raise ValueError(f"expected a robot name or an Actor (reset + act), got {robot!r}")
        return robot
    from hg_marl.agents.robots import make_robot

    return make_robot(robot)


def as_list(partner: str | Actor | Sequence[str | Actor]) -> list[str | Actor]:
    """One partner or a population, as a list."""
    if isinstance(partner, str) or not isinstance(partner, Sequence):
        return [partner]
    return list(partner)


def resolve_partner(seat: Agent, partner: str | Actor) -> Actor:
    """The Actor playing opposite ``seat``: a human for the robot's view, a robot for the human's."""
    return resolve_human(partner) if seat is Agent.ROBOT else make_robot_actor(partner)
