"""Greedy play of a recurrent SB3 policy: LSTM state reset at each table's new episode; nothing played, rate 0."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("stable_baselines3")

from hg_marl.training.baselines.recurrent_ppo_sb3 import Play, RecurrentSb3Config, greedy_play


class _Recorder:
    """A stand-in model: always action 0, remembering the ``episode_start`` of every call."""

    def __init__(self) -> None:
        self.starts: list[np.ndarray] = []

    def predict(self, obs: Any, state: Any, episode_start: Any, deterministic: bool) -> tuple[Any, Any]:
        assert deterministic
        self.starts.append(np.array(episode_start, dtype=bool))
        return np.zeros(len(obs), dtype=np.int64), state


def _config(tmp_path: Path) -> RecurrentSb3Config:
    return RecurrentSb3Config(
        humans=("cooperative",), scenario="forced_coordination", history=0, episode_seconds=60.0, out=tmp_path
    ).check()


def test_each_table_restarts_its_lstm_state_after_its_episode_ends(tmp_path: Path) -> None:
    # Episodes (continuing mode) last 60 s and end truncated, never terminated; 180 s of play
    # ends the first episode of every table well before play stops, so each table's next call
    # after the first must say its episode starts (the first call says so for all).
    model = _Recorder()
    greedy_play(model, _config(tmp_path), num_envs=2, seconds=180.0, seed=0)
    assert model.starts[0].tolist() == [True, True]
    later = np.array(model.starts[1:])
    assert later.any(axis=0).tolist() == [True, True], "every table saw a new episode"
    assert not later.all(axis=0).any(), "and not at every step"


def test_no_play_is_a_zero_rate_not_a_division_by_zero(tmp_path: Path) -> None:
    model = _Recorder()
    assert greedy_play(model, _config(tmp_path), num_envs=1, seconds=0.0, seed=0) == Play(0.0, 0.0)
    assert model.starts == [], "no step was asked for"
