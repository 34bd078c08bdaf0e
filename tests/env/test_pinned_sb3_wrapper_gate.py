"""The SB3 ``VecEnv`` adapters and the quiet logger, pinned for the mutation gate.

Each adapter is driven by a scripted stand-in env whose answers are written out here, so
every expected value follows from the module's documented rules, by hand: SB3's ``done``
is ``terminated or truncated``; a finished sub-env hands its last observation in
``terminal_observation`` and ``TimeLimit.truncated`` is true only for a truncation that
is not also a termination; ``seed(s)`` names ``s + i`` for sub-env ``i``; ``InfoMasks``
serves the masks of the latest infos (all ones before any) and counts each action sent
outside the mask it served.
"""

from __future__ import annotations

import sys
from typing import Any

import gymnasium
import numpy as np
import pytest
from gymnasium.vector import AutoresetMode

pytest.importorskip("stable_baselines3")

from stable_baselines3.common.logger import HumanOutputFormat
from stable_baselines3.common.vec_env import VecEnv

from hg_marl.core.errors import ConfigError
from hg_marl.wrappers.sb3 import BatchedVecEnv, InfoMasks, quiet_logger

N, A = 4, 3


class ScriptedBatch:
    """A batched env stand-in: fixed spaces, and the step answers it is given."""

    def __init__(self, autoreset_mode: Any = AutoresetMode.SAME_STEP, device: Any = None) -> None:
        self.autoreset_mode, self.device, self.num_envs = autoreset_mode, device, N
        self.render_mode = None
        self.single_observation_space = gymnasium.spaces.Box(0, 1, (2,), dtype=np.int8)
        self.single_action_space = gymnasium.spaces.Discrete(A)
        self.seeds: list[int | None] = []
        self.sent: list[np.ndarray] = []
        self.answer: tuple[Any, ...] = ()
        self.masks = np.array([[1, 0, 1], [0, 1, 1], [1, 1, 1], [0, 0, 1]], dtype=bool)

    def reset(self, seed: int | None = None) -> tuple[np.ndarray, dict[str, Any]]:
        self.seeds.append(seed)
        return np.zeros((N, 2), dtype=np.int8), {}

    def step(self, actions: np.ndarray) -> tuple[Any, ...]:
        self.sent.append(actions)
        return self.answer

    def action_masks(self) -> np.ndarray:
        return self.masks


def test_the_adapter_needs_a_same_step_numpy_batch() -> None:
    with pytest.raises(ConfigError, match=r"^autoreset_mode: "):
        BatchedVecEnv(ScriptedBatch(autoreset_mode=AutoresetMode.NEXT_STEP))
    with pytest.raises(ConfigError, match=r"^device: "):
        BatchedVecEnv(ScriptedBatch(device="cpu"))


def test_seed_names_one_seed_per_sub_env_and_seeds_only_the_next_reset() -> None:
    env = ScriptedBatch()
    venv = BatchedVecEnv(env)
    assert venv.seed(10) == [10, 11, 12, 13]
    venv.reset()
    venv.reset()
    assert venv.seed() == [None] * N
    venv.reset()
    assert env.seeds == [10, None, None]
    assert venv.reset_infos == [{}] * N


def test_a_step_is_done_when_terminated_or_truncated_and_a_time_limit_only_when_not_terminated() -> None:
    """Sub-env 0 terminates, 1 is truncated, 2 both (a termination), 3 goes on."""
    env = ScriptedBatch()
    venv = BatchedVecEnv(env)
    obs = np.arange(N * 2, dtype=np.int8).reshape(N, 2)
    final = [np.full(2, 10 + i, dtype=np.int8) for i in range(N)]
    term = np.array([True, False, True, False])
    trunc = np.array([False, True, True, False])
    reward = np.array([1.0, 0.5, -2.0, 0.0])
    env.answer = (obs, reward, term, trunc, {"final_obs": final})
    venv.step_async(np.array([[2], [1], [0], [2]]))
    got_obs, got_reward, done, infos = venv.step_wait()
    np.testing.assert_array_equal(env.sent[0], [2, 1, 0, 2])
    assert env.sent[0].dtype == np.int64
    assert got_obs is obs
    assert got_reward.dtype == np.float32
    np.testing.assert_array_equal(got_reward, reward.astype(np.float32))
    np.testing.assert_array_equal(done, [True, True, True, False])
    assert [info.get("TimeLimit.truncated") for info in infos] == [False, True, False, None]
    for i in range(3):
        np.testing.assert_array_equal(infos[i]["terminal_observation"], final[i])
    assert infos[3] == {}


def test_a_step_with_no_sub_env_done_reads_no_final_observation() -> None:
    env = ScriptedBatch()
    venv = BatchedVecEnv(env)
    falses = np.zeros(N, dtype=bool)
    env.answer = (np.zeros((N, 2)), np.zeros(N), falses, falses, {})  # no "final_obs": read would fail
    venv.step_async(np.zeros(N, dtype=np.int64))
    _, _, done, infos = venv.step_wait()
    assert not done.any() and infos == [{}] * N


def test_attributes_and_methods_answer_one_value_per_requested_sub_env() -> None:
    env = ScriptedBatch()
    venv = BatchedVecEnv(env)
    assert venv.get_attr("num_envs") == [N] * N
    assert venv.get_attr("num_envs", indices=2) == [N]
    assert venv.get_attr("num_envs", indices=[0, 3]) == [N, N]
    for name in ("probe", "aardvark"):  # names after and before "action_masks": any other method is the env's
        venv.set_attr(name, lambda *a, **k: (a, k))
        assert venv.env_method(name, 1, x=2, indices=[0, 1]) == [((1,), {"x": 2})] * 2
    rows = venv.env_method("".join(["action_", "masks"]), indices=[1, 3])  # built at run time, not interned
    np.testing.assert_array_equal(np.stack(rows), env.masks[[1, 3]])
    assert len(venv.env_method("action_masks")) == N
    np.testing.assert_array_equal(venv.action_masks(), env.masks)
    assert venv.has_attr("action_masks") and venv.has_attr("num_envs")
    assert not venv.has_attr("nothing_here") and not venv.has_attr("aa_missing")  # after and before "action_masks"
    assert venv.env_is_wrapped(object) == [False] * N
    assert venv.env_is_wrapped(object, indices=[2]) == [False]
    venv.close()  # nothing to release, nothing raised


class ScriptedVec(VecEnv):
    """A 2-env SB3 VecEnv stand-in whose reset and step infos are given."""

    def __init__(self) -> None:
        super().__init__(2, gymnasium.spaces.Box(0, 1, (1,)), gymnasium.spaces.Discrete(A))
        self.infos: list[dict[str, Any]] = [{}, {}]
        self.sent: list[np.ndarray] = []
        self.calls: list[tuple[Any, ...]] = []

    def reset(self) -> np.ndarray:
        return np.zeros((2, 1))

    def step_async(self, actions: np.ndarray) -> None:
        self.sent.append(actions)

    def step_wait(self) -> tuple[Any, ...]:
        return np.zeros((2, 1)), np.zeros(2), np.zeros(2, dtype=bool), self.infos

    def close(self) -> None:
        pass

    def get_attr(self, attr_name: str, indices: Any = None) -> list[Any]:
        return [None, None]  # SB3 reads each env's render_mode

    def set_attr(self, attr_name: str, value: Any, indices: Any = None) -> None:
        pass

    def env_method(self, method_name: str, *args: Any, indices: Any = None, **kwargs: Any) -> list[Any]:
        self.calls.append((method_name, args, indices, kwargs))
        return ["inner"]

    def env_is_wrapped(self, wrapper_class: Any, indices: Any = None) -> list[bool]:
        return [False, False]


def test_info_masks_serve_all_actions_until_infos_carry_masks_then_the_latest() -> None:
    inner = ScriptedVec()
    venv = InfoMasks(inner)
    np.testing.assert_array_equal(np.stack(venv.env_method("action_masks")), np.ones((2, A), dtype=bool))
    inner.reset_infos = [{"action_mask": [1, 0, 1]}, {}]
    venv.reset()
    np.testing.assert_array_equal(np.stack(venv.env_method("action_masks")), [[1, 0, 1], [1, 1, 1]])
    inner.infos = [{}, {"action_mask": np.array([0, 0, 1])}]
    venv.step_async(np.array([0, 2]))
    venv.step_wait()
    masks = venv.env_method("action_masks")
    assert all(m.dtype == np.bool_ for m in masks)
    built = "".join(["action_", "masks"])  # a name built at run time: equal to the literal, not the same object
    np.testing.assert_array_equal(np.stack(venv.env_method(built)), np.stack(masks))
    np.testing.assert_array_equal(np.stack(masks), [[1, 0, 1], [0, 0, 1]])


def test_info_masks_serve_only_the_envs_asked_for() -> None:
    """SB3's ``indices``: None is every env, an int one env, a list those envs, in its order."""
    inner = ScriptedVec()
    venv = InfoMasks(inner)
    inner.reset_infos = [{"action_mask": [1, 0, 1]}, {"action_mask": [0, 0, 1]}]
    venv.reset()
    assert [m.tolist() for m in venv.env_method("action_masks", indices=1)] == [[False, False, True]]
    assert [m.tolist() for m in venv.env_method("action_masks", indices=[1, 0])] == [
        [False, False, True],
        [True, False, True],
    ]
    assert len(venv.env_method("action_masks", indices=None)) == 2


def test_info_masks_count_each_action_sent_outside_the_served_mask() -> None:
    """Masks [1,0,1] and [0,0,1]: actions (1, 0) are both outside (2), (2, 2) neither, (0, 1) one."""
    inner = ScriptedVec()
    venv = InfoMasks(inner)
    inner.reset_infos = [{"action_mask": [1, 0, 1]}, {"action_mask": [0, 0, 1]}]
    venv.reset()
    assert venv.outside_mask == 0
    for actions in ([1, 0], [2, 2], [0, 1]):
        venv.step_async(np.array(actions))
    assert venv.outside_mask == 3
    assert [a.tolist() for a in inner.sent] == [[1, 0], [2, 2], [0, 1]]


def test_info_masks_answer_the_mask_hook_and_pass_other_methods_on() -> None:
    inner = ScriptedVec()
    venv = InfoMasks(inner)
    assert venv.seed(5) == [None, None]
    assert venv.has_attr("action_masks") and not venv.has_attr("num_envs") and not venv.has_attr("aardvark")
    assert venv.env_method("render", 1, indices=[1], mode="x") == ["inner"]
    assert venv.env_method("aardvark") == ["inner"]  # a name sorting before "action_masks" is passed on too
    assert inner.calls == [("render", (1,), [1], {"mode": "x"}), ("aardvark", (), None, {})]


class LoggedModel:
    """Records the logger set on it."""

    logger: Any = None

    def set_logger(self, logger: Any) -> None:
        self.logger = logger


def test_the_quiet_logger_writes_to_no_folder_and_to_stdout_only_when_verbose() -> None:
    model = LoggedModel()
    assert quiet_logger(model) is model
    assert model.logger.get_dir() is None and model.logger.output_formats == []
    quiet_logger(model, verbose=1)
    (only,) = model.logger.output_formats
    assert isinstance(only, HumanOutputFormat) and only.file is sys.stdout
    assert model.logger.get_dir() is None
