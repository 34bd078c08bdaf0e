"""Pinned against a planted bug: the final observation of a same-step autoreset keeps the ended episode's history.

In ``same_step`` mode the batched table returns the new episode's observation and puts
the last one in ``info["final_obs"]``; :class:`HistoryVectorEnv` must append to it the
history of the episode that just ended, and only then forget it for the new episode.
Forgetting first would hand the learner a final observation whose history part reads
like a fresh table (all zero but ``partner_since_progress=0``).

Worked by hand on ``paper2015`` from the state ``where=(0, 4, 2), robot_at=0`` (the
human can pick tape2, the robot can go to tape1), two tables, ``max_cycles=2``, ``k=2``:

- cycle 1: the human picks tape2 (succeeds: progress); table 0's robot goes to tape1,
  table 1's waits;
- cycle 2: the human gives tape1, which it does not hold (fails: no progress); both
  robots wait. The episode is truncated.

So the final observation's history, most recent first, is the partner's ``give`` then
``pick``, its last action failed, the robot's own ``wait`` then ``goto`` (table 0) or
``wait`` then ``wait`` (table 1), neither failed, and one cycle since the partner's
progress. The observation returned beside it is the new episode's: no cycle yet.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.views import robot_vector_env
from hg_marl.core import State
from hg_marl.core.batch import BatchState
from hg_marl.envs.history import history_names

K = 2
START = State(where=(0, 4, 2), robot_at=0)
PICK_TAPE2, GIVE_TAPE1 = 1, 6  # the human's action indices on paper2015
GOTO_TAPE1, WAIT = 12, 17  # the robot's


class Plan:
    """A human partner (an ArrayPartner) playing the same given action on every table, cycle by cycle."""

    name = "plan"

    def __init__(self, plan: list[int]) -> None:
        self.plan, self.t = plan, 0

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        out = np.full(len(batch.where), self.plan[self.t], dtype=np.int64)
        self.t += 1
        return out


def _by_name(on: set[str]) -> np.ndarray:
    """The history part with exactly the entries named in ``on`` set (names from ``history_names``)."""
    names = history_names(K)
    assert on <= set(names)
    return np.array([int(n in on) for n in names], dtype=np.int8)


def test_same_step_final_observation_carries_the_ended_episodes_history_not_the_reset_one() -> None:
    env = robot_vector_env(
        2, "paper2015", partner=Plan([PICK_TAPE2, GIVE_TAPE1]), max_cycles=2, autoreset_mode="same_step", history=K
    )
    env.reset(seed=0, options={"states": [START, START]})
    n_f = env.world.n_facts
    env.step(np.array([GOTO_TAPE1, WAIT]))
    obs, _, terminated, truncated, info = env.step(np.array([WAIT, WAIT]))
    # the env agrees with the hand-worked cycle: truncated at cycle 2, the human's give failed
    assert truncated.all() and not terminated.any() and info["_final_obs"].all()
    assert info["final_info"]["human_action"].tolist() == [GIVE_TAPE1, GIVE_TAPE1]
    assert info["final_info"]["human_failed"].all() and not info["final_info"]["failed"].any()

    partner = {"partner_kind[-1]=give", "partner_kind[-2]=pick", "partner_failed[-1]", "partner_since_progress=1"}
    expected = [
        _by_name(partner | {"own_kind[-1]=wait", "own_kind[-2]=goto"}),
        _by_name(partner | {"own_kind[-1]=wait", "own_kind[-2]=wait"}),
    ]
    final = np.asarray(info["final_obs"])
    assert final.shape == (2, n_f + len(history_names(K)))
    assert np.array_equal(final[0, n_f:], expected[0])
    assert np.array_equal(final[1, n_f:], expected[1])
    # the returned observation is the new episode's: nothing recorded, 0 cycles since progress
    fresh = _by_name({"partner_since_progress=0"})
    assert np.array_equal(obs[0, n_f:], fresh) and np.array_equal(obs[1, n_f:], fresh)
