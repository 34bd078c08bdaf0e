"""The homogenising wrapper's checks, padding and stand-ins, pinned for the mutation gate.

Expected values from the spec sheet of ``hg_marl/wrappers/homogenize.py``: it wraps any
AEC env whose agents have ``Discrete`` actions and exactly ``Dict(observation,
action_mask)`` observations with fact vectors of one shape, and refuses any other with a
``ValueError`` naming the problem; the shared spaces are ``Box(0, 1)``; a padded index
``A_i <= k < A`` is replaced by the agent's first real action the mask rules out (and
refused, naming the agent's real range ``0..A_i-1``, when every real action is feasible);
anything else (an index at or past ``A``, a value that is not an index, a finished
agent's step) is handed to the env unchanged, for its own message. A dtype equal to
``int8`` or ``float32`` is accepted whatever object it is (one that went through pickle,
as a vector env's worker receives it, is equal but not the same object).

``_Stub`` is a hand-made AEC env whose masks the test sets, and which records the actions
it is given, so the expected stand-ins are read off the masks by hand.
"""

from __future__ import annotations

import pickle
from typing import Any

import numpy as np
import pytest
from gymnasium import spaces
from pettingzoo import AECEnv
from pettingzoo.utils import BaseWrapper

import hg_marl
from hg_marl.envs import InvalidActionError
from hg_marl.wrappers import homogenize_v0
from hg_marl.wrappers.homogenize import HomogenizeWrapper, check_dtype, dict_parts

N_FACTS = 24  # paper2015's boolean facts
N_ROBOT, N_HUMAN = 18, 31  # paper2015's action counts
ROBOT_WAIT = N_ROBOT - 1


class _Stub(AECEnv):
    """Agents ``a`` and ``b`` taking turns; facts of the given sizes, masks set by the test, actions recorded."""

    metadata = {"render_modes": [], "name": "stub"}  # noqa: RUF012 (as AECEnv)

    def __init__(self, n_actions: dict[str, int], n_facts: dict[str, int], extra_key: bool = False) -> None:
        super().__init__()
        self.possible_agents = ["a", "b"]
        self.n_actions, self.n_facts = n_actions, n_facts
        self.extra_key = extra_key
        self.masks = {a: np.ones(n, np.int8) for a, n in n_actions.items()}
        self.received: list[Any] = []
        self.reset()

    def observation_space(self, agent: str) -> spaces.Space:
        parts: dict[str, spaces.Space] = {
            "observation": spaces.Box(0, 1, (self.n_facts[agent],), np.int8),
            "action_mask": spaces.Box(0, 1, (self.n_actions[agent],), np.int8),
        }
        if self.extra_key:
            parts["extra"] = spaces.Discrete(2)
        return spaces.Dict(parts)

    def action_space(self, agent: str) -> spaces.Space:
        return spaces.Discrete(self.n_actions[agent])

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None) -> None:
        self.agents = list(self.possible_agents)
        self.agent_selection = "a"
        self.rewards = dict.fromkeys(self.agents, 0.0)
        self._cumulative_rewards = dict.fromkeys(self.agents, 0.0)
        self.terminations = dict.fromkeys(self.agents, False)
        self.truncations = dict.fromkeys(self.agents, False)
        self.infos: dict[str, dict[str, Any]] = {a: {} for a in self.agents}

    def observe(self, agent: str) -> dict[str, np.ndarray]:
        return {"observation": np.zeros(self.n_facts[agent], np.int8), "action_mask": self.masks[agent].copy()}

    def step(self, action: Any) -> None:
        self.received.append(action)
        self.agent_selection = "b" if self.agent_selection == "a" else "a"


class _Recorder(BaseWrapper):
    """Passes everything through, recording the actions the wrapper above hands down."""

    def __init__(self, env: AECEnv) -> None:
        super().__init__(env)
        self.received: list[Any] = []

    def step(self, action: Any) -> None:
        self.received.append(action)
        super().step(action)


@pytest.mark.parametrize("dtype", [np.float32, np.int8])
def test_a_dtype_equal_to_a_supported_one_is_accepted_after_pickling(dtype: type) -> None:
    copied = pickle.loads(pickle.dumps(np.dtype(dtype)))
    assert copied == np.dtype(dtype)
    assert check_dtype(copied) is dtype


def test_an_observation_dict_with_an_extra_key_is_refused() -> None:
    with pytest.raises(ValueError, match=r"expected a Dict\(observation, action_mask\)"):
        dict_parts(_Stub({"a": 2, "b": 2}, {"a": 3, "b": 3}, extra_key=True), "a")


def test_agents_with_fact_vectors_of_different_shapes_are_refused() -> None:
    with pytest.raises(ValueError, match="different shapes"):
        HomogenizeWrapper(_Stub({"a": 2, "b": 2}, {"a": 3, "b": 4}))


def test_the_shared_spaces_are_zero_one_boxes() -> None:
    """paper2015: facts plus a one-hot of 2 agents, and the larger action count (the human's 31)."""
    env = homogenize_v0(hg_marl.env())
    space = env.observation_space("robot")
    assert isinstance(space, spaces.Dict)
    assert space["observation"] == spaces.Box(0, 1, (N_FACTS + 2,), np.int8)
    assert space["action_mask"] == spaces.Box(0, 1, (N_HUMAN,), np.int8)


def test_a_padded_index_stands_in_for_the_first_ruled_out_action_not_a_feasible_one() -> None:
    """Agent ``a`` has 2 real actions of the shared 5; with mask [1, 0] the only ruled-out action is 1."""
    stub = _Stub({"a": 2, "b": 5}, {"a": 3, "b": 3})
    stub.masks["a"] = np.array([1, 0], np.int8)
    env = HomogenizeWrapper(stub)
    env.reset()
    env.step(3)
    assert stub.received == [1]


def test_a_padded_index_when_every_real_action_is_feasible_is_refused_naming_the_real_range() -> None:
    stub = _Stub({"a": 3, "b": 5}, {"a": 3, "b": 3})
    env = HomogenizeWrapper(stub)
    env.reset()
    with pytest.raises(InvalidActionError) as info:
        env.step(4)
    assert str(info.value) == (
        "action 4 is padding for agent 'a' (real actions 0..2) "
        "and every real action is feasible now, so none can stand in for it"
    )
    assert stub.received == []


def test_a_value_that_is_not_an_index_goes_to_the_env_even_for_a_one_action_agent() -> None:
    """Agent ``a`` has one real action (index 0): no stand-in for a non-index, the env gets it as sent."""
    stub = _Stub({"a": 1, "b": 3}, {"a": 3, "b": 3})
    stub.masks["a"] = np.array([0], np.int8)  # action 0 ruled out: a stand-in would be 0
    env = HomogenizeWrapper(stub)
    env.reset()
    env.step("x")
    assert stub.received == ["x"]


def test_an_action_that_cannot_be_made_an_int_is_the_envs_error() -> None:
    env = homogenize_v0(hg_marl.env())
    env.reset(seed=0)
    with pytest.raises(InvalidActionError, match="is not an integer"):
        env.step([1, 2])


@pytest.mark.parametrize("index", [N_HUMAN + 1, 100])
def test_an_index_past_the_shared_space_is_not_padding_and_the_env_refuses_it(index: int) -> None:
    env = homogenize_v0(hg_marl.env())
    env.reset(seed=0)
    before = env.unwrapped.world_state
    with pytest.raises(InvalidActionError, match="out of range"):
        env.step(index)  # the robot's turn: its real actions are 0..17
    assert env.unwrapped.world_state == before


def test_a_finished_agents_step_goes_to_the_env_unchanged() -> None:
    """After one cycle of ``max_cycles=1`` both agents are truncated; a padded index reaches the env as sent."""
    recorder = _Recorder(hg_marl.env(max_cycles=1))
    env = homogenize_v0(recorder)
    env.reset(seed=0)
    env.step(ROBOT_WAIT)
    observed = env.observe("human")
    assert observed is not None
    env.step(int(np.flatnonzero(observed["action_mask"])[-1]))
    assert env.truncations["robot"]
    with pytest.raises(ValueError, match="only valid action is None"):
        env.step(N_ROBOT + 2)
    assert recorder.received[-1] == N_ROBOT + 2
