"""Values that round 248's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import hg_marl
from hg_marl.training.io import write_json
from hg_marl.wrappers import flatten_v0
from tests.env.test_pinned_wrapper_flat_gate import N_FACTS


def test_write_json_writes_a_numpy_float32_at_its_full_value_not_rounded(tmp_path: Path) -> None:
    # A float32 holds a 24-bit significand: the float32 nearest 1e-7 lies within 2**-24 (6e-8)
    # relative of it, so it reads back as 1e-7 to 7 digits (rounded to 6 decimals it would be 0.0).
    # Near 123 (in [64, 128)) float32s are 2**-17 apart: 123.4567891 * 2**17 = 16181817.4, so its
    # float32 is 16181817 / 2**17 = 123.456787109375; written whole it reads back to every digit,
    # not cut to 123.456787.
    path = write_json(tmp_path / "r.json", {"small": np.float32(1e-7), "big": np.float32(123.4567891)})
    data = json.loads(path.read_text())
    assert data["small"] != 0.0
    assert data["small"] == pytest.approx(1e-7, rel=6e-8)
    assert data["big"] == 123.456787109375


@pytest.mark.parametrize("mask", ["obs", "info"])
def test_the_flat_wrapper_observes_its_facts_in_the_dtype_asked(mask: str) -> None:
    # The spec sheet: ``dtype`` is the facts' dtype (float32 by default, or int8), in the space
    # and in every observation, so an observation lies in its own space.
    for dtype in (np.int8, np.float32):
        env = flatten_v0(hg_marl.env(), mask=mask, dtype=dtype)
        env.reset(seed=0)
        for agent in env.possible_agents:
            obs = env.observe(agent)
            facts = obs if mask == "info" else obs["observations"]
            assert facts.dtype == np.dtype(dtype)
            assert facts.shape == (N_FACTS,)
            assert env.observation_space(agent).contains(obs)
