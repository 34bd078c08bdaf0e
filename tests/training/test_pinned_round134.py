"""Values that round 134's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.model_format import write_header
from hg_marl.agents.vector_envs import human_vector_env
from hg_marl.core import Agent, Durations, World
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.training.outputs import check_output
from hg_marl.training.store import Store
from tests.training.test_pinned_round44 import _Waiter


def test_a_header_holding_nan_is_refused_and_nothing_is_written(tmp_path: Path) -> None:
    # write_header promises "strict JSON: no NaN": NaN is not JSON (RFC 8259 has no such
    # number), so a header holding one is refused in one line and no file is left behind.
    path = tmp_path / "policy.json"
    with pytest.raises(ModelFileError, match="header holds a value JSON cannot store"):
        write_header(path, {"format": "hg_marl.model", "loss": float("nan")})
    assert not path.exists()
    assert list(tmp_path.iterdir()) == []


def test_a_wrong_ending_is_refused_naming_the_endings_joined_by_or(tmp_path: Path) -> None:
    # Two accepted endings, ".png" and ".svg": the refusal reads them as alternatives,
    # "ending in .png or .svg", and names the option and the path the user gave.
    path = tmp_path / "plot.pdf"
    with pytest.raises(ConfigError) as info:
        check_output(path, "--png", suffixes=(".png", ".svg"))
    assert str(info.value) == f"--png {path}: expected a file name ending in .png or .svg"


def test_a_claim_file_records_the_holders_own_pid(tmp_path: Path) -> None:
    # The claim file "records the holder's pid for people": the holder is this process,
    # so while the claim is held the file reads this process's pid and a newline.
    key = "c" * 64
    with Store(tmp_path).claim(key) as held:
        assert held
        assert (tmp_path / "claims" / f"{key}.lock").read_text() == f"{os.getpid()}\n"


def test_the_human_seat_plays_the_durations_it_is_given() -> None:
    # human_vector_env takes ``durations``. With wait lasting 2.5 s, not the default 1 s, and
    # both agents waiting (a live robot that only waits), each cycle lasts max(2.5, 2.5) = 2.5
    # simulated seconds, so after three cycles each table's clock reads 7.5 (default: 3.0).
    durations = Durations(wait=2.5)
    env = human_vector_env(num_envs=2, robot=_Waiter(), durations=durations, cache=False)
    assert env.world.durations == durations
    _, info = env.reset(seed=0)
    np.testing.assert_array_equal(info["clock"], [0.0, 0.0])
    wait = World("paper2015").action_names[Agent.HUMAN].index("wait")
    for _ in range(3):
        _, _, terminated, truncated, info = env.step(np.full(2, wait))
        assert not terminated.any() and not truncated.any()
    np.testing.assert_allclose(info["clock"], [7.5, 7.5])
