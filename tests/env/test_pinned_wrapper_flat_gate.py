"""The flat observation wrapper's options and spaces, pinned for the mutation gate.

Expected values from the spec sheet of ``hg_marl/wrappers/flat.py``: the facts are a
``Box(0, 1)`` of the env's fact count (24 on paper2015), the mask a ``Box(0, 1)`` of the
agent's action count (18 for the robot, 31 for the human); the two keys must be two
different non-empty names, any two such names are accepted whatever their order; the
``mask`` option is compared by value, so ``"info"`` read from a settings file (a string
built at run time, not the interned literal) selects the same view as the literal.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from gymnasium import spaces

import hg_marl
from hg_marl.wrappers import flatten_v0

N_FACTS = 24  # paper2015's boolean facts
N_ACTIONS = {"robot": 18, "human": 31}  # paper2015's action counts


def _runtime(text: str) -> str:
    """``text`` as a new string object, as a value read from a settings file is (not the interned literal)."""
    value: str = json.loads(json.dumps({"v": text}))["v"]
    copy = "".join(list(value))
    assert copy == text
    return copy


@pytest.mark.parametrize("keys", [("a", "b"), ("b", "a"), ("observations", "z")])
def test_any_two_different_keys_are_accepted_in_either_order(keys: tuple[str, str]) -> None:
    obs_key, mask_key = keys
    env = flatten_v0(hg_marl.env(), obs_key=obs_key, mask_key=mask_key)
    env.reset(seed=0)
    assert set(env.observe("robot")) == {obs_key, mask_key}


@pytest.mark.parametrize("keys", [("", "mask"), ("obs", ""), ("", "")])
def test_an_empty_key_is_refused_even_when_the_other_is_set(keys: tuple[str, str]) -> None:
    obs_key, mask_key = keys
    with pytest.raises(ValueError, match="two different non-empty names"):
        flatten_v0(hg_marl.env(), obs_key=obs_key, mask_key=mask_key)


def test_the_spaces_are_zero_one_boxes_of_the_facts_and_the_mask() -> None:
    """Bounds 0 and 1 for both parts, the mask ``int8`` (the spec sheet)."""
    env = flatten_v0(hg_marl.env())
    for agent, n in N_ACTIONS.items():
        space = env.observation_space(agent)
        assert isinstance(space, spaces.Dict)
        assert space["observations"] == spaces.Box(0, 1, (N_FACTS,), np.float32)
        assert space["action_mask"] == spaces.Box(0, 1, (n,), np.int8)
    info = flatten_v0(hg_marl.env(), mask="info", dtype=np.int8)
    assert info.observation_space("human") == spaces.Box(0, 1, (N_FACTS,), np.int8)


def test_info_read_at_run_time_puts_the_mask_in_infos_like_the_literal() -> None:
    """``mask`` equal to ``"info"`` but a different string object: a Box space, array observations, masks in infos."""
    env = flatten_v0(hg_marl.env(), mask=_runtime("info"))
    raw = hg_marl.env()
    assert env.observation_space("human") == spaces.Box(0, 1, (N_FACTS,), np.float32)
    env.reset(seed=5)
    raw.reset(seed=5)
    observed = env.observe("robot")
    assert isinstance(observed, np.ndarray) and observed.shape == (N_FACTS,)
    np.testing.assert_array_equal(env.infos["robot"]["action_mask"], raw.observe("robot")["action_mask"])
    env.step(N_ACTIONS["robot"] - 1)  # the robot waits
    raw.step(N_ACTIONS["robot"] - 1)
    np.testing.assert_array_equal(env.infos["human"]["action_mask"], raw.observe("human")["action_mask"])
