"""The values round 60's missed planted bugs changed (``mutation/planted.py``, FRESH60), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("stable_baselines3")

from gymnasium import spaces
from stable_baselines3.common.vec_env import VecEnv

from hg_marl.wrappers.sb3 import InfoMasks

A = 3


class _Vec(VecEnv):
    """Two sub-envs of three actions whose reset infos carry the masks the test sets."""

    def __init__(self) -> None:
        super().__init__(2, spaces.Box(0, 1, (1,)), spaces.Discrete(A))
        self.reset_infos = [{}, {}]

    def reset(self) -> np.ndarray:
        return np.zeros((2, 1))

    def step_async(self, actions: np.ndarray) -> None:
        pass

    def step_wait(self) -> tuple[Any, ...]:
        return np.zeros((2, 1)), np.zeros(2), np.zeros(2, dtype=bool), [{}, {}]

    def close(self) -> None:
        pass

    def get_attr(self, attr_name: str, indices: Any = None) -> list[Any]:
        return [None, None]

    def set_attr(self, attr_name: str, value: Any, indices: Any = None) -> None:
        pass

    def env_method(self, method_name: str, *args: Any, indices: Any = None, **kwargs: Any) -> list[Any]:
        return [None, None]

    def env_is_wrapped(self, wrapper_class: Any, indices: Any = None) -> list[bool]:
        return [False, False]


def test_info_masks_count_only_the_actions_outside_the_mask_not_those_inside() -> None:
    """Masks [1,0,1] and [1,1,1]: actions (1, 0) send one outside (env 0's action 1), (0, 2) none.

    Worked by hand: of the four actions sent, one is ruled out by its mask and three are
    allowed, so the count is 1 (counting the allowed ones instead would give 3).
    """
    inner = _Vec()
    venv = InfoMasks(inner)
    inner.reset_infos = [{"action_mask": [1, 0, 1]}, {"action_mask": [1, 1, 1]}]
    venv.reset()
    venv.step_async(np.array([1, 0]))
    venv.step_async(np.array([0, 2]))
    assert venv.outside_mask == 1


def test_recurrent_ppo_sb3_trains_against_every_partner_of_a_population(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``humans=(cooperative, lazy)`` is a population (the module docstring: a partner drawn from
    ``humans`` per episode), so the batched env is built with both partners; one human is one partner."""
    import hg_marl.wrappers.sb3 as sb3_wrapper
    from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config, make_vec

    built: list[dict[str, Any]] = []

    def record(num_envs: int, **kwargs: Any) -> str:
        built.append(kwargs)
        return "venv"

    monkeypatch.setattr(sb3_wrapper, "batched_vec_env", record)
    for humans in (("cooperative", "lazy"), ("cooperative",)):
        config = RecurrentSb3Config(humans=humans, scenario="forced_coordination", history=0, out=tmp_path)
        assert make_vec(config, 2) == "venv"
    population, single = (b["human"] for b in built)
    assert not isinstance(population, str) and list(population) == ["cooperative", "lazy"]
    assert single == "cooperative"
