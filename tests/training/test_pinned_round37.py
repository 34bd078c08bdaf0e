"""Round 37 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated by hand, from the documented rule (the protocol's list of
members, the weight's documented bound, the module's docstring on corrupt entries) or
worked out step by step from the run's sizes, not computed with the code under test.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
import torch  # noqa: F401  (imported at collection, as test_ppo_recurrent.py does: the run below times itself)
from gymnasium import spaces

from hg_marl.core import World


def test_a_partner_with_the_four_tabled_members_is_a_tabled_human() -> None:
    """``ArrayPartner``'s docstring: a compiled human offers ``actions``, ``outcome``,
    ``answer`` and ``fall_back`` (:class:`TabledHuman`), which the batched table detects
    with ``isinstance``; a partner with exactly those is one, and without ``answer`` it is not."""
    from hg_marl.envs.array_partner import TabledHuman

    class Tabled:
        name = "tabled"

        def __init__(self) -> None:
            self.actions = np.zeros(1, dtype=np.int64)
            self.outcome: dict[str, np.ndarray] = {}

        def act(self, batch: Any, seen: Any, rng: Any) -> Any:
            raise AssertionError("not called")

        def answer(self, batch: Any, seen: Any, rng: Any) -> Any:
            raise AssertionError("not called")

        def fall_back(self, batch: Any, seen: Any, rng: Any, out: Any, found: Any) -> Any:
            raise AssertionError("not called")

    class Untabled:
        name = "untabled"

        def __init__(self) -> None:
            self.actions = np.zeros(1, dtype=np.int64)
            self.outcome: dict[str, np.ndarray] = {}

        def fall_back(self, batch: Any, seen: Any, rng: Any, out: Any, found: Any) -> Any:
            raise AssertionError("not called")

    assert isinstance(Tabled(), TabledHuman)
    assert not isinstance(Untabled(), TabledHuman)


def test_a_time_weight_of_zero_is_refused() -> None:
    """``CostWeights.time`` "must be > 0 (plans must not be free to lengthen)": 0 is refused,
    as a negative weight is; a tiny positive one is accepted."""
    from hg_marl.agents.planner.costs import CostWeights

    with pytest.raises(ValueError, match="time"):
        CostWeights(time=0.0)
    with pytest.raises(ValueError, match="time"):
        CostWeights(time=-1.0)
    assert CostWeights(time=1e-6).time == 1e-6


class _Clocked:
    """A toy table: 3-step episodes of 1 s each, no reward (only the step counts matter)."""

    def __init__(self, num_envs: int) -> None:
        self.num_envs = num_envs
        self.single_observation_space = spaces.Box(0, 1, (2,), np.int8)
        self.single_action_space = spaces.Discrete(2)
        self.world = World("paper2015")  # only for the model header's names
        self.clock = np.zeros(num_envs)
        self.t = np.zeros(num_envs, dtype=np.int64)

    def action_masks(self) -> np.ndarray:
        return np.ones((self.num_envs, 2), dtype=bool)

    def reset(self, *, seed: int | None = None, options: Any = None) -> tuple[np.ndarray, dict[str, Any]]:
        self.t[:] = 0
        self.clock[:] = 0.0
        return np.zeros((self.num_envs, 2), dtype=np.int8), {}

    def step(self, actions: np.ndarray) -> tuple[Any, Any, Any, Any, dict[str, Any]]:
        term = self.t == 2
        self.t += 1
        self.clock += 1.0
        info = {"clock": self.clock.copy()}
        self.t[term], self.clock[term] = 0, 0.0
        obs = np.zeros((self.num_envs, 2), dtype=np.int8)
        return obs, np.zeros(self.num_envs), term, np.zeros(self.num_envs, dtype=bool), info


def train_clocked(out: Path, steps: int = 24, **overrides: Any) -> Any:
    """A tiny mlp recurrent run on the clocked toy (8 tables x 3 cycles: an update every 24 steps)."""
    from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig, train_recurrent

    fields: dict[str, Any] = {
        "memory": "mlp",
        "history": 0,
        "hidden": 8,
        "num_envs": 8,
        "n_steps": 3,
        "steps": steps,
        "epochs": 1,
        "minibatches": 1,
        "eval_seconds": 3.0,
        "out": out,
    }
    return train_recurrent(RecurrentConfig(**(fields | overrides)), env=_Clocked(8))


def test_recurrent_checkpoints_fall_at_the_first_update_past_each_multiple(tmp_path: Path) -> None:
    """8 tables x 3 cycles: an update every 24 steps (24, 48, 72, 96, 120). With
    ``checkpoint_freq=50`` a checkpoint is due at each multiple of 50 and written at the
    first update at or past it: 50 -> 72, 100 -> 120 (a period counted from 72 would be
    due at 122 and miss the run's end)."""
    result = train_clocked(tmp_path, steps=120, checkpoint_freq=50)
    assert result.num_timesteps == 120
    assert [p.name for p in result.checkpoints] == ["ckpt_72_steps.json", "ckpt_120_steps.json"]


def test_a_foreign_npz_in_the_cache_folder_is_an_entry_to_rebuild(tmp_path: Path) -> None:
    """The cache's docstring: "a corrupt entry is rebuilt". An ``.npz`` that holds
    arrays but no ``key`` is not an entry, so loading it answers None, as for a missing file."""
    from hg_marl.agents.models.cache import load_entry

    path = tmp_path / "paper2015-0123456789abcdef01234567.npz"
    np.savez(path, policy=np.zeros(3, dtype=np.int64))
    assert load_entry(path, "0123456789abcdef01234567") is None
    assert load_entry(tmp_path / "absent.npz", "0123456789abcdef01234567") is None
