"""The array form of the progress guard at its edges, pinned for the mutation gate.

Expected values by hand from the rule (agents/progress.py): a state that differs from the
previous one in anything (here only the offered object) is a change and zeroes the
count; a reset table counts from 0; resetting no table makes room for none. A guard
``wait`` (nothing else feasible) is not a guard move: ``m`` counts only the moves taken, so
the next stall starts again at the first option.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.progress import ArrayProgressGuard, ProgressGuard
from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchState
from hg_marl.core.scenario import parse_scenario
from tests.agents.test_oracle import TINY


def _batch(offer_obj: int) -> BatchState:
    one = np.array([1], dtype=np.int64)
    return BatchState(np.zeros((1, 1), dtype=np.int64), one * 0, one * 0, one * offer_obj)


def test_a_change_of_the_offered_object_alone_is_a_change() -> None:
    guard = ArrayProgressGuard(World(TINY))
    proposed = np.array([3], dtype=np.int64)
    guard.apply(_batch(0), proposed)
    guard.apply(_batch(0), proposed)
    assert guard.unchanged.tolist() == [1]  # the same state twice: one unchanged turn
    guard.apply(_batch(1), proposed)  # only offer_obj differs, and it is larger
    assert guard.unchanged.tolist() == [0]
    guard.apply(_batch(0), proposed)  # and smaller
    assert guard.unchanged.tolist() == [0]


def test_a_reset_table_counts_from_zero_and_no_rows_make_no_room() -> None:
    guard = ArrayProgressGuard(World(TINY))
    guard.reset_rows(np.array([], dtype=np.int64))
    assert len(guard.unchanged) == len(guard.moves) == len(guard.fired) == 0
    proposed = np.array([3], dtype=np.int64)
    for _ in range(3):
        guard.apply(_batch(0), proposed)
    assert guard.unchanged.tolist() == [2]
    guard.reset_rows(np.array([0], dtype=np.int64))
    assert guard.unchanged.tolist() == [0]
    assert guard.moves.tolist() == [0] and guard.fired.tolist() == [False]
    assert len(guard.unchanged) == 1


ONE_PLACE = parse_scenario(
    {
        "name": "one-place",
        "robot_locations": ["near"],
        "handover_locations": ["near"],
        "robot_start": ["near"],
        "objects": [{"name": "o1"}, {"name": "o2"}],
        "bins": [{"name": "bin", "robot_reach": ["near"]}],
        "spots": [
            {"name": "a", "robot_reach": ["near"]},
            {"name": "b", "robot_reach": ["near"]},
            {"name": "h1", "human_reach": True},
            {"name": "h2", "human_reach": True},
        ],
        "layout": [{"count": 2, "spots": ["a", "b", "h1", "h2"]}],
    }
)
"""One robot location (so no ``goto`` is ever feasible): with both objects on the human's
spots the robot can only wait; with both on its own spots it can pick either."""
ONLY_WAIT = State((2, 3), 0)
"""o1 on h1, o2 on h2: only the human can act."""
TWO_PICKS = State((0, 1), 0)
"""o1 on a, o2 on b: the robot's options are pick(o1), pick(o2)."""


def test_the_scenario_gives_the_states_their_options_by_hand() -> None:
    world = World(ONE_PLACE)
    names = world.action_names[Agent.ROBOT]
    assert [names[i] for i in world.feasible_indices(ONLY_WAIT, Agent.ROBOT)] == ["wait"]
    assert [names[i] for i in world.feasible_indices(TWO_PICKS, Agent.ROBOT)] == ["pick(o1)", "pick(o2)", "wait"]


def test_a_guard_wait_is_not_counted_as_a_guard_move() -> None:
    world = World(ONE_PLACE)
    names = world.action_names[Agent.ROBOT]
    guard = ProgressGuard(1)
    assert names[guard.move(world, ONLY_WAIT)] == "wait"
    assert guard.moves == 0
    # m = 0 guard moves so far: the first option, then the second, then round again
    assert [names[guard.move(world, TWO_PICKS)] for _ in range(3)] == ["pick(o1)", "pick(o2)", "pick(o1)"]
    assert guard.moves == 3


def test_the_array_guard_counts_its_waits_alike() -> None:
    world = World(ONE_PLACE)
    names = world.action_names[Agent.ROBOT]
    wait = world.n_actions(Agent.ROBOT) - 1
    guard = ArrayProgressGuard(world, 1)

    def turn(state: State) -> str:
        one = np.array([1], dtype=np.int64)
        batch = BatchState(np.array([state.where]), one * state.robot_at, one * -1, one * -1, rows=np.array([0]))
        return names[int(guard.apply(batch, np.array([wait]))[0])]

    # the first turn sets the previous state; from the second on the state is unchanged (K = 1)
    assert [turn(ONLY_WAIT) for _ in range(3)] == ["wait"] * 3
    assert guard.moves.tolist() == [0] and guard.moves_taken == 0
    assert [turn(TWO_PICKS) for _ in range(4)] == ["wait", "pick(o1)", "pick(o2)", "pick(o1)"]
    assert guard.moves.tolist() == [3] and guard.moves_taken == 3
