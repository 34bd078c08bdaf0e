"""The planner's candidate table: a partner's offer is taken wherever the robot stands.

The rules let an agent take an offered object from any location (``RuleTable`` checks no
location for TAKE; only GIVE needs the handover place), so when the human holds out an
object the planner must consider the robot's take at every robot location, the ones
outside the handover place included. States are built by hand: the human holding out
each object in turn, the others where the scenario's first layout puts them.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.planner import Planner
from hg_marl.core import Agent, Kind, State, World


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum"])
def test_the_robot_may_take_an_offer_from_every_location(scenario: str) -> None:
    world = World(scenario)
    table = world.table
    space = Planner(world).space
    start = world.initial_state(np.random.default_rng(0))
    assert not all(table.give_ok), "some location must be outside the handover place"
    for o in range(world.n_objects):
        where = tuple(table.hand[Agent.HUMAN] if k == o else p for k, p in enumerate(start.where))
        take = table.action_index(Agent.ROBOT, Kind.TAKE, o)
        for at in range(len(table.give_ok)):
            state = State(where, at, int(Agent.HUMAN), o)
            assert table.feasible(state, Agent.ROBOT, take)
            assert take in space._candidates(state, Agent.ROBOT), (o, at)
