"""Round 39 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated by hand, from the documented rule (the batched table's
action space: ``single_action_space`` is ``Discrete(n)``, so the indices are ``0 .. n-1``
and ``step`` refuses any other one with a ``ValueError`` that names the range), not
computed with the code under test.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.core import World
from hg_marl.envs.batched import BatchedTable, BatchState

ROBOT_WAIT, HUMAN_WAIT = 17, 30
"""paper2015's wait indices (robot, human); wait is each seat's last action, so the robot has 18."""


class _Always:
    """A partner that plays one action index on every table."""

    def __init__(self, action: int) -> None:
        self.action = action

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.full(len(batch), self.action, dtype=np.int64)


@pytest.mark.parametrize("bad", [ROBOT_WAIT + 1, -1])
def test_an_action_one_past_either_end_of_the_space_is_refused_before_any_step(bad: int) -> None:
    """The robot seat of paper2015 has 18 actions (indices 0..17, wait the last): 18 is
    one past the end and -1 one before the start; each is refused with the range named
    ("[0, 18)"), the table left as it was (clock 0, no cycle), and the last index itself
    (the wait) is then played as usual (one cycle of 1 s: both seats wait)."""
    env = BatchedTable(_Always(HUMAN_WAIT), 2, World("paper2015"))  # type: ignore[arg-type]
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"expected 2 indices in \[0, 18\)"):
        env.step(np.array([ROBOT_WAIT, bad]))
    assert env.cycles.tolist() == [0, 0]
    assert env.clock.tolist() == [0.0, 0.0]
    env.step(np.array([ROBOT_WAIT, ROBOT_WAIT]))
    assert env.cycles.tolist() == [1, 1]
    assert env.clock.tolist() == [1.0, 1.0]
