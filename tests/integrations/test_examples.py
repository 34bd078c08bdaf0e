"""Each example in examples/ trains for a few hundred steps and never sends an action its mask rules out.

Marked ``integrations``: run by ``make test-integrations`` (nox, one session per library,
each installing that library). A session names its library in ``HG_MARL_INTEGRATION``;
there a missing library fails the test instead of skipping it.
"""

from __future__ import annotations

import importlib.util
import os
from pathlib import Path
from types import ModuleType

import pytest

pytestmark = pytest.mark.integrations

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def load(name: str, needs: str, session: str) -> ModuleType:
    """Import examples/<name>.py; skip if ``needs`` is missing, unless this nox session is ``session``."""
    if importlib.util.find_spec(needs) is None:
        if session in os.environ.get("HG_MARL_INTEGRATION", "").split(","):
            pytest.fail(f"{needs} is not installed in the {session!r} session that exists to test it")
        pytest.skip(f"{needs} not installed (run `make test-integrations`)")
    spec = importlib.util.spec_from_file_location(f"example_{name}", EXAMPLES / f"{name}.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_cleanrl_style_ppo_honours_the_mask() -> None:
    out = load("cleanrl_ppo", "torch", "cleanrl").main(steps=256, rollout=64)
    assert out["steps"] >= 256
    assert out["outside_mask"] == 0
    assert out["sent"] == {"robot": out["steps"] // 2, "human": out["steps"] // 2}
    assert out["infeasible_when_executed"]["robot"] == 0  # the robot moves first: its mask is current


def test_supersuit_vector_env_into_sb3_maskable_ppo() -> None:
    out = load("supersuit_sb3", "supersuit", "supersuit").main(steps=256)
    assert out["steps"] >= 256
    assert out["outside_mask"] == 0
    assert out["sent"]["robot"] == out["sent"]["human"] >= 128
    assert out["infeasible_when_executed"]["robot"] == 0


def test_gymnasium_make_vec_async_into_maskable_ppo() -> None:
    out = load("make_vec_maskable_ppo", "sb3_contrib", "cleanrl").main(steps=256)
    assert out["steps"] >= 256
    assert out["outside_mask"] == 0
    assert out["mask_shape"] == (2, 18)


def test_tianshou_masked_dqn_with_a_scripted_human() -> None:
    out = load("tianshou_dqn", "tianshou", "tianshou").main(steps=200)
    assert out["sent"]["robot"] >= 100 and out["sent"]["human"] >= 100
    assert out["infeasible"] == {"robot": 0, "human": 0}


@pytest.mark.parametrize("mode", ["fixed", "both"])
def test_rllib_ppo_new_api_stack_with_action_masking(mode: str) -> None:
    out = load("rllib_ppo", "ray", "rllib").main(mode=mode, iterations=1, batch=128)
    assert out["sent"]["robot"] >= 64 and out["sent"]["human"] >= 64
    assert out["infeasible"]["robot"] == 0
    if mode == "both":
        assert out["infeasible"]["human"] == 0
