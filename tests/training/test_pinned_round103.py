"""Values that round 103's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.array_partners import CompiledPopulation
from hg_marl.agents.humans import make_human
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, World
from hg_marl.envs.array_partner import FollowsClock, ResetsRows
from hg_marl.envs.batched import BatchedTable
from tests.training.test_pinned_round28 import _Waiter


def test_the_random_human_goes_by_its_registry_name() -> None:
    # The registry entry is "random" and the module documents it as the human's name: what a
    # run's records and the robot view's reset info call the partner.
    assert make_human("random").name == "random"
    _, info = RobotView(human="random").reset(seed=0)
    assert info["human"] == "random"


def test_a_population_without_a_clock_draws_each_tables_member_at_reset() -> None:
    # A compiled population keeps a member per table (reset_rows) and follows no clock: it is
    # a ResetsRows partner, so the table's reset draws each table's member. With 40 tables and
    # two members, each member answers the tables it was drawn for (both drawn: the chance of
    # one member everywhere is 2 / 2**40), every table once per step.
    world = World("paper2015")
    wait_h, wait_r = world.table.wait[Agent.HUMAN], world.table.wait[Agent.ROBOT]
    first, second = _Waiter("first", wait_h), _Waiter("second", wait_h)
    population = CompiledPopulation([first, second])
    capabilities: object = population  # checked through another name: isinstance would narrow the population's type
    assert isinstance(capabilities, ResetsRows)
    assert not isinstance(capabilities, FollowsClock)
    env = BatchedTable(population, 40, world, Agent.ROBOT, continuing=True, max_cycles=None)
    env.reset(seed=0)
    assert population.member.shape == (40,)
    drawn = population.member.tolist()
    assert set(drawn) == {0, 1}
    env.step(np.full(40, wait_r))
    assert (first.answered, second.answered) == (drawn.count(0), drawn.count(1))
