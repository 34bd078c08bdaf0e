"""How a seat's partner is named (a name, an Actor, or a population), pinned for the mutation gate.

Expected values from the module's own promises (its docstrings): a robot name is built by
the robots' registry, an Actor instance is used as it is, anything else is refused with a
message saying what was expected; one partner becomes a one-element list and a sequence
of partners a list of the same members in the same order; the partner opposite the robot
is a human and the partner opposite the human is a robot.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.humans.cooperative import CooperativeHuman
from hg_marl.agents.humans.lazy import LazyHuman
from hg_marl.agents.humans.random_human import RandomHuman
from hg_marl.agents.partner_specs import as_list, make_robot_actor, resolve_partner
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.core import Agent, World
from hg_marl.core.errors import HumanError, RobotError
from hg_marl.policy import Turn


class _Scripted:
    """A minimal Actor (reset + act), neither a registry robot nor a registry human."""

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Nothing to remember."""

    def act(self, turn: Turn) -> int:
        """Always the first action."""
        return 0


def test_a_robot_name_is_built_by_the_registry_with_its_parameters() -> None:
    """``"random"`` is the uniform robot; a spec's parameters reach the robot's constructor."""
    assert type(make_robot_actor("random")) is RandomRobot
    habit = make_robot_actor("habit:share_objects=true")
    assert type(habit) is HabitRobot
    assert habit.share_objects is True


def test_an_actor_instance_is_used_as_it_is_for_either_seat() -> None:
    """The same object comes back, not a copy: the caller keeps its handle on it."""
    actor = _Scripted()
    assert make_robot_actor(actor) is actor
    assert resolve_partner(Agent.HUMAN, actor) is actor
    assert resolve_partner(Agent.ROBOT, actor) is actor


def test_something_that_is_neither_a_name_nor_an_actor_is_refused_saying_what_was_expected() -> None:
    """An object without ``reset`` and ``act`` is not a robot: a ValueError naming the value."""
    with pytest.raises(ValueError, match=r"expected a robot name or an Actor \(reset \+ act\), got 42"):
        make_robot_actor(42)


def test_one_partner_is_a_one_element_list_and_a_population_keeps_its_members_in_order() -> None:
    """A name is one partner (not its characters); an Actor is one partner; a tuple or list is a population."""
    actor = _Scripted()
    assert as_list("lazy") == ["lazy"]
    assert as_list(actor) == [actor]
    assert as_list(("lazy", actor, "random")) == ["lazy", actor, "random"]
    members: list[str | _Scripted] = ["cooperative", "lazy"]
    out = as_list(members)
    assert out == members and out is not members  # a new list: the caller's is never edited


def test_the_partner_opposite_the_robot_is_a_human_and_opposite_the_human_a_robot() -> None:
    """``random`` names both a human and a robot: the seat decides which registry reads it.

    A robot-only name (``planner``) is no human, a human-only one (``lazy``) no robot.
    """
    assert type(resolve_partner(Agent.ROBOT, "random")) is RandomHuman
    assert type(resolve_partner(Agent.HUMAN, "random")) is RandomRobot
    assert type(resolve_partner(Agent.ROBOT, "lazy")) is LazyHuman
    assert type(resolve_partner(Agent.ROBOT, "cooperative")) is CooperativeHuman
    with pytest.raises(HumanError):
        resolve_partner(Agent.ROBOT, "planner")
    with pytest.raises(RobotError):
        resolve_partner(Agent.HUMAN, "lazy")
