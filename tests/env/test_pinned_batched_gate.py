"""The batch's memory refusal names its limit in MB, pinned for the mutation gate.

Expected by hand: a limit of 2**20 bytes is "1 MB"; 3 * 2**20 is "3 MB".
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.core import World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.batched import check_batch


@pytest.mark.parametrize(("limit", "text"), [(2**20, "1 MB limit"), (3 * 2**20, "3 MB limit")])
def test_the_refusal_names_the_limit_in_mb(limit: int, text: str) -> None:
    with pytest.raises(ConfigError, match=f"over the {text} \\(memory_limit\\)"):
        check_batch(World("paper2015"), 10**6, memory_limit=limit)


def test_a_taken_batch_copies_its_rows_and_keeps_which_env_tables_they_are() -> None:
    """``take([2, 0, 2])`` of tables 0-2 (themselves env tables 5, 6, 7) is tables 2, 0, 2 again,
    as copies (a change to the copy leaves the batch alone), each still naming its env table."""
    from hg_marl.core.batch import BatchState

    where = np.array([[0, 1], [2, 3], [4, 5]], dtype=np.int64)
    b = BatchState(where, np.array([0, 1, 0]), np.array([-1, 0, 1]), np.array([-1, 1, 0]), np.array([5, 6, 7]))
    t = b.take(np.array([2, 0, 2]))
    assert t.where.tolist() == [[4, 5], [0, 1], [4, 5]]
    assert t.robot_at.tolist() == [0, 0, 0] and t.offer_by.tolist() == [1, -1, 1] and t.offer_obj.tolist() == [0, -1, 0]
    assert t.rows.tolist() == [7, 5, 7]
    t.where[0, 0] = 9
    assert b.where[2, 0] == 4


def test_in_the_humans_seat_the_robot_partners_first_move_at_reset_sees_no_human_action() -> None:
    """The protocol: a robot partner's ``seen`` is -1 on every table (no human move to react
    to). At reset in the human's seat the robot moves first, so its first ``seen`` is all -1."""
    from hg_marl.core import Agent
    from hg_marl.envs.batched import BatchedTable

    world = World("paper2015")
    wait = world.n_actions(Agent.ROBOT) - 1

    class Recorder:
        name = "recorder"

        def __init__(self) -> None:
            self.seen: list[list[int]] = []

        def act(self, batch: object, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
            self.seen.append(seen.tolist())
            return np.full(len(seen), wait, dtype=np.int64)

    partner = Recorder()
    BatchedTable(partner, 3, world, seat=Agent.HUMAN).reset(seed=0)
    assert partner.seen == [[-1, -1, -1]]
