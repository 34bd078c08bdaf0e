"""Registered ids work the way the README and docs/using.md show, including from a fresh interpreter."""

from __future__ import annotations

import subprocess
import sys

import gymnasium
import numpy as np
import pettingzoo
import pytest

import hg_marl  # noqa: F401  (registers the ids for the in-process tests)

FRESH = """
import sys
import gymnasium
assert "hg_marl" not in sys.modules
env = gymnasium.make("hg_marl:hg_marl/RobotTableCleaning-v0", human="lazy")
obs, info = env.reset(seed=0)
mask = env.get_wrapper_attr("action_masks")()
obs, reward, terminated, truncated, info = env.step(int(mask.nonzero()[0][0]))
print(type(env.unwrapped).__name__, obs.shape, mask.dtype)
"""


def test_gymnasium_make_needs_no_import_with_the_module_form() -> None:
    out = subprocess.run([sys.executable, "-c", FRESH], capture_output=True, text=True, timeout=600, check=False)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["RobotView", "(24,)", "bool"]


def test_pettingzoo_make_after_import() -> None:
    aec = pettingzoo.make("aec", "hg_marl/TableCleaning-v0")
    par = pettingzoo.make("parallel", "hg_marl/TableCleaning-v0")
    aec.reset(seed=0)
    par.reset(seed=0)
    assert aec.possible_agents == par.possible_agents == ["robot", "human"]


def test_action_masks_reachable_through_gymnasium_wrappers_as_sb3_contrib_calls_it() -> None:
    env = gymnasium.make("hg_marl/RobotTableCleaning-v0", human="cooperative")
    env.reset(seed=2)
    masks = env.get_wrapper_attr("action_masks")()
    np.testing.assert_array_equal(masks, env.unwrapped.action_masks())
    np.testing.assert_array_equal(masks, env.unwrapped.env.observe("robot")["action_mask"].astype(bool))


def test_sb3_contrib_get_action_masks_on_vec_envs() -> None:
    pytest.importorskip("sb3_contrib")
    from sb3_contrib.common.maskable.utils import get_action_masks
    from stable_baselines3.common.env_util import make_vec_env

    venv = make_vec_env("hg_marl/RobotTableCleaning-v0", n_envs=2, seed=0)
    venv.reset()
    masks = get_action_masks(venv)
    assert masks.shape == (2, 18) and masks.dtype == bool
    expected = np.stack([e.unwrapped.action_masks() for e in venv.envs])
    np.testing.assert_array_equal(masks, expected)
