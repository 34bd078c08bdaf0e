"""The batched table draw covers exactly the layout distribution, pinned for the mutation gate.

Expected by hand for paper2015 (3 objects; two go to distinct spots of {0, 1, 2}, one to a
spot of {4, 5}; the robot starts at 0): 3 choices of the lone object x 2 spots x 3 x 2
ordered spots for the other two = 36 tables, each reachable.
"""

from __future__ import annotations

import itertools

import numpy as np

from hg_marl.core import Agent, Event, Kind, World


def _by_hand() -> set[tuple[int, ...]]:
    tables = set()
    for lone in range(3):
        pair = [o for o in range(3) if o != lone]
        for lone_spot in (4, 5):
            for a, b in itertools.permutations((0, 1, 2), 2):
                where = [0, 0, 0]
                where[lone], where[pair[0]], where[pair[1]] = lone_spot, a, b
                tables.add(tuple(where))
    return tables


def test_initial_states_draw_every_table_of_the_layout_and_nothing_else() -> None:
    world = World("paper2015")
    expected = _by_hand()
    assert len(expected) == 36
    where, robot_at = world.initial_states(np.random.default_rng(2015), 2000)
    assert where.shape == (2000, 3) and robot_at.shape == (2000,)
    assert {tuple(int(x) for x in row) for row in where} == expected
    assert set(robot_at.tolist()) == {0}


def test_a_pick_is_told_with_the_spot_the_object_left() -> None:
    # seeded random walks: every pick either agent makes is told with the picker, the object and
    # the spot the object stood on (the scenario's own name for it), never a hand
    world = World("paper2015")
    picks = {"robot": 0, "human": 0}
    for seed in range(3):
        rng = np.random.default_rng(seed)
        state = world.initial_state(rng)
        for _ in range(60):
            for agent, who in ((Agent.ROBOT, "robot"), (Agent.HUMAN, "human")):
                index = int(rng.choice(world.feasible_indices(state, agent)))
                action = world.actions(agent)[index]
                outcome = world.step(state, agent, index)
                if action.kind is Kind.PICK:
                    spot = world.scenario.spots[state.where[action.obj]].name
                    assert Event("picked", who, world.scenario.objects[action.obj], spot) in outcome.events
                    picks[who] += 1
                state = outcome.state
    assert min(picks.values()) >= 1, picks
