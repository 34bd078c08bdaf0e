"""SB3 ``VecEnv`` adapters: the batched table, and SuperSuit's vector env with masks in infos.

:class:`BatchedVecEnv` makes :class:`~hg_marl.envs.batched.BatchedTable` an SB3 ``VecEnv``
so ``PPO``, ``DQN`` and sb3-contrib's ``MaskablePPO`` train on ``num_envs`` tables stepped
at once. SB3 resets a finished sub-env inside ``step_wait`` and hands its last observation
in ``infos[i]["terminal_observation"]`` (with ``"TimeLimit.truncated"``), which is
Gymnasium's ``SAME_STEP`` autoreset, so the adapter needs the batched env built with
``autoreset_mode="same_step"`` (:func:`batched_vec_env` builds it). Masks:
``env_method("action_masks")`` returns the rows of ``action_masks()``; ``has_attr`` says
yes to it; ``seed(s)`` seeds the next reset.

:class:`InfoMasks` is the SuperSuit-to-SB3 bridge: SuperSuit's concatenated vector env of
``to_parallel(flatten_v0(homogenize_v0(env()), mask="info"))`` carries each agent's mask
in ``infos``; it serves them to sb3-contrib through ``env_method("action_masks")`` and
counts actions sent outside them (``outside_mask``).

:func:`quiet_logger` is the logger every SB3 model here trains with unless TensorBoard
is asked for: SB3's default creates an empty ``SB3-<date>`` folder in the system's
temporary folder at every ``learn()``, a write outside the folder the user named.

Needs ``pip install "hg-marl[sb3]"`` (imported on demand by ``hg_marl.wrappers``).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import Any

import numpy as np
from gymnasium.vector import AutoresetMode
from stable_baselines3.common.logger import HumanOutputFormat, KVWriter, Logger
from stable_baselines3.common.vec_env import VecEnv, VecEnvWrapper

from hg_marl.core.errors import ConfigError
from hg_marl.registration import ROBOT_VIEW_ID, register_envs


class BatchedVecEnv(VecEnv):
    """An SB3 ``VecEnv`` over a :class:`~hg_marl.envs.batched.BatchedTable` in ``same_step`` mode."""

    def __init__(self, env: Any) -> None:
        if env.autoreset_mode is not AutoresetMode.SAME_STEP:
            raise ConfigError(
                "autoreset_mode: SB3's VecEnv needs the batched env built with autoreset_mode='same_step'"
            )
        if env.device is not None:
            raise ConfigError("device: SB3's VecEnv needs numpy arrays; build the batched env with device=None")
        self.env = env
        super().__init__(env.num_envs, env.single_observation_space, env.single_action_space)
        self._seed: int | None = None
        self._actions = np.zeros(env.num_envs, dtype=np.int64)

    def reset(self) -> np.ndarray:
        obs, _ = self.env.reset(seed=self._seed)
        self._seed = None
        self.reset_infos = [{} for _ in range(self.num_envs)]
        return obs

    def seed(self, seed: int | None = None) -> Sequence[int | None]:
        """Seed the next reset (SB3's convention: one seed per sub-env, here one for the batch)."""
        self._seed = seed
        return [None if seed is None else seed + i for i in range(self.num_envs)]

    def step_async(self, actions: np.ndarray) -> None:
        self._actions = np.asarray(actions, dtype=np.int64).reshape(self.num_envs)

    def step_wait(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[dict[str, Any]]]:
        obs, reward, term, trunc, info = self.env.step(self._actions)
        done = term | trunc
        infos: list[dict[str, Any]] = [{} for _ in range(self.num_envs)]
        if done.any():
            final = info["final_obs"]
            for i in np.flatnonzero(done):
                infos[i]["terminal_observation"] = final[i]
                infos[i]["TimeLimit.truncated"] = bool(trunc[i] and not term[i])
        return obs, reward.astype(np.float32), done, infos

    def action_masks(self) -> np.ndarray:
        """(num_envs, n_actions) booleans."""
        return self.env.action_masks()

    def close(self) -> None:
        """Nothing to release."""

    def _indices(self, indices: Any) -> list[int]:
        if indices is None:
            return list(range(self.num_envs))
        return [indices] if isinstance(indices, int) else list(indices)

    def get_attr(self, attr_name: str, indices: Any = None) -> list[Any]:
        return [getattr(self.env, attr_name)] * len(self._indices(indices))

    def set_attr(self, attr_name: str, value: Any, indices: Any = None) -> None:
        setattr(self.env, attr_name, value)

    def env_method(self, method_name: str, *args: Any, indices: Any = None, **kwargs: Any) -> list[Any]:
        rows = self._indices(indices)
        if method_name == "action_masks":
            masks = self.env.action_masks()
            return [masks[i] for i in rows]
        result = getattr(self.env, method_name)(*args, **kwargs)
        return [result] * len(rows)

    def has_attr(self, attr_name: str) -> bool:
        return attr_name == "action_masks" or hasattr(self.env, attr_name)

    def env_is_wrapped(self, wrapper_class: Any, indices: Any = None) -> list[bool]:
        return [False] * len(self._indices(indices))


def batched_vec_env(num_envs: int, **kwargs: Any) -> BatchedVecEnv:
    """The robot's batched seat as an SB3 ``VecEnv``.

    The seat is reached through Gymnasium's registry (its vector entry point, the batched
    table with its partner compiled), as any user would, so this wrapper imports nothing
    from the agents' layer above it.
    """
    import gymnasium

    register_envs()
    env = gymnasium.make_vec(
        ROBOT_VIEW_ID, num_envs=num_envs, vectorization_mode="vector_entry_point", autoreset_mode="same_step", **kwargs
    )
    return BatchedVecEnv(env)


class InfoMasks(VecEnvWrapper):
    """Serves ``env_method("action_masks")`` (sb3-contrib's hook) from the masks in the last infos."""

    def __init__(self, venv: Any) -> None:
        super().__init__(venv)
        n_actions = int(self.action_space.n)  # type: ignore[attr-defined]
        self._masks: np.ndarray = np.ones((self.num_envs, n_actions), dtype=np.bool_)
        self.outside_mask = 0
        """Actions SB3 sent that the mask it was served ruled out (the check that it honours them)."""

    def step_async(self, actions: np.ndarray) -> None:
        self.outside_mask += int((~self._masks[np.arange(self.num_envs), actions]).sum())
        self.venv.step_async(actions)

    def _keep(self, infos: list[dict[str, Any]]) -> None:
        for i, info in enumerate(infos):
            if "action_mask" in info:
                self._masks[i] = np.asarray(info["action_mask"], dtype=bool)

    def reset(self) -> Any:
        obs = self.venv.reset()
        self._keep(self.venv.reset_infos)
        return obs

    def step_wait(self) -> Any:
        obs, rewards, dones, infos = self.venv.step_wait()
        self._keep(infos)
        return obs, rewards, dones, infos

    def seed(self, seed: int | None = None) -> list[int | None]:
        """SuperSuit's concatenated env has no ``seed``; seed the parallel env before wrapping."""
        return [None] * self.num_envs

    def has_attr(self, attr_name: str) -> bool:
        """sb3-contrib asks whether the envs have ``action_masks`` before training."""
        return attr_name == "action_masks"

    def env_method(self, method_name: str, *args: Any, indices: Any = None, **kwargs: Any) -> list[Any]:
        if method_name == "action_masks":  # the envs asked for, as ``BatchedVecEnv`` answers
            return [self._masks[i] for i in self._get_indices(indices)]
        return self.venv.env_method(method_name, *args, indices=indices, **kwargs)


def quiet_logger(model: Any, verbose: int = 0) -> Any:
    """Give ``model`` a logger that writes to no folder (stdout only when ``verbose``); return ``model``.

    SB3 builds its logger in ``learn()`` unless one was set, and that default makes a
    folder in the temporary directory even when it logs nothing; a set logger is kept.
    """
    formats: list[KVWriter] = [HumanOutputFormat(sys.stdout)] if verbose else []
    model.set_logger(Logger(folder=None, output_formats=formats))
    return model
