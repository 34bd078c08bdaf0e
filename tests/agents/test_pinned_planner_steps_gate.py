"""The compiled steps on a table with more fixed places than objects (one object, two places).

A robot's ``goto`` to a fixed place is numbered after the objects' (target ``n + j`` for
the ``j``-th place); with one object the second place is target 2, which only the rule
``j = target - n`` maps back to place 1. Every feasible action of every state of seeded
walks is compared with :meth:`RuleTable.successor_feasible`, the rules the steps were
compiled from (the reference), and the walks are checked to have sent the robot to the
second place.
"""

from __future__ import annotations

from hg_marl.agents.planner.steps import Steps
from hg_marl.core import Agent, Kind, World
from tests.agents.test_planner_compiled import walk


def test_steps_reach_every_fixed_place_as_the_rules_do() -> None:
    world = World("generated:objects=1,seed=1")
    table = world.table
    n = world.n_objects
    assert n == 1 and len(table.goto_static[0]) == 2
    steps = Steps(table)
    places = set()
    for seed in range(3):
        for state in walk(world, seed, 20):
            for agent in Agent:
                for index in world.feasible_indices(state, agent):
                    assert steps.apply(state, agent, index) == table.successor_feasible(state, agent, index)
                    kind, _, target, _ = table.specs[agent][index]
                    if kind is Kind.GOTO and target >= n:
                        places.add(target - n)
    assert 1 in places  # target n + 1: the place only ``target - n`` finds
