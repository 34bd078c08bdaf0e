"""Values that round 130's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.array_partners import LiveRobots
from hg_marl.agents.humans.random_human import RandomHuman
from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchState
from hg_marl.policy import Turn
from hg_marl.training.aggregate import profiles
from tests.training.test_aggregate import _table


def test_a_seat_with_one_feasible_action_takes_it_for_sure() -> None:
    # paper2015's clean table (every object in bin 6): the human's one feasible action is its
    # wait, the last of its 31 actions (index 30); uniform over one action is probability 1.
    world = World("paper2015")
    clean = State((6, 6, 6), 0, -1, -1)
    assert world.feasible_indices(clean, Agent.HUMAN) == [30]
    assert RandomHuman().distribution(world, clean) == [(30, 1.0)]


def test_two_seeds_per_task_get_a_bootstrapped_profile_band() -> None:
    # One robot, one task, scores 0 and 1, tau 0.5: the curve is 1/2 (one run of two above).
    # A resample of the two runs has 0, 1 or 2 runs above with probability 1/4, 1/2, 1/4,
    # so over 200 replications the 2.5th percentile is 0 and the 97.5th is 1 (a replication
    # count of zeros or of ones under 5 has probability about 200 * 0.75**199, nil).
    curves, bands = profiles(_table({"r": {"h": [0.0, 1.0]}}), np.array([0.5]))
    assert curves["r"].tolist() == [0.5]
    assert bands["r"].tolist() == [[0.0], [1.0]]


class _Constant:
    """A robot stand-in that always answers ``action``."""

    name = "constant"

    def __init__(self, action: int) -> None:
        self.action = action

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        pass

    def act(self, turn: Turn) -> int:
        return self.action


def test_live_robots_answer_a_subset_of_tables_with_those_tables_actors() -> None:
    # Two actors for two tables: table 0 plays the one answering 3, table 1 the one answering 5.
    # A batch holding table 1 alone (its row 0 names table 1) must be answered by table 1's actor.
    world = World("paper2015")
    live = LiveRobots(world, [_Constant(3), _Constant(5)], 2)
    state = world.initial_state(np.random.default_rng(0))
    one = np.array([state.robot_at], dtype=np.int64)
    batch = BatchState(
        np.array([state.where], dtype=np.int64),
        one,
        np.full(1, state.offer_by, dtype=np.int64),
        np.full(1, state.offer_obj, dtype=np.int64),
        np.array([1]),
    )
    assert live.act(batch, np.zeros(1, dtype=bool), np.random.default_rng(0)).tolist() == [5]
