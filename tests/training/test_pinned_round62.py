"""The values round 62's missed planted bugs changed (``mutation/planted.py``, FRESH62), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.core.world import World
from hg_marl.training.baselines.recipes import FCP_LEVELS, NoisyPartner


class _Inner:
    """A stand-in member: the noisy partner only reads its name here (no act is called)."""

    name = "stub"

    def act(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.zeros(len(batch), dtype=np.int64)


@pytest.mark.parametrize("resets", [[[0]], [[0, 1, 2], [3]], [[0, 1], [1], [2]]], ids=["one-table", "added", "next"])
def test_every_table_reset_draws_one_of_the_noise_levels(resets: list[list[int]]) -> None:
    # The docstring: "levels are the eps a table may draw at its reset". So after the resets,
    # each table reset so far (0 .. the largest row) holds one of FCP_LEVELS, whichever table
    # is new (a one-table run's first reset: table 0, the fcp recipe with num_envs=1).
    partner = NoisyPartner(World("paper2015"), _Inner(), FCP_LEVELS)
    rng = np.random.default_rng(0)
    for rows in resets:
        partner.reset_rows(np.asarray(rows, dtype=np.int64), rng)
    tables = max(max(rows) for rows in resets) + 1
    assert len(partner.eps) >= tables
    assert all(float(partner.eps[t]) in FCP_LEVELS for t in range(tables))
