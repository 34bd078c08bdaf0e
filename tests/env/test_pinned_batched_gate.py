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
