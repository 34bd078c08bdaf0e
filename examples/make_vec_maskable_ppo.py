"""``gymnasium.make_vec(..., vectorization_mode="async")`` into sb3-contrib's MaskablePPO (the robot's seat).

Gymnasium's vector envs are not SB3 ``VecEnv``s; :class:`GymnasiumVecEnv` is the small
bridge: it asks for same-step autoreset (SB3's convention: the final observation in
``infos[i]["terminal_observation"]``), splits Gymnasium's dict-of-arrays infos into SB3's
list of dicts, and forwards ``env_method("action_masks")`` to ``VectorEnv.call``, which
reaches ``RobotView.action_masks`` through Gymnasium's wrappers in each worker process.
The id uses Gymnasium's ``"module:id"`` form, so each worker imports ``hg_marl`` itself.

Run: ``python examples/make_vec_maskable_ppo.py --steps 1024``. Needs ``hg-marl[sb3]``.
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import gymnasium
import numpy as np
import torch
from gymnasium.vector import AutoresetMode
from sb3_contrib import MaskablePPO
from sb3_contrib.common.maskable.utils import get_action_masks
from stable_baselines3.common.vec_env import VecEnv

from hg_marl.wrappers.sb3 import quiet_logger

ENV_ID = "hg_marl:hg_marl/RobotTableCleaning-v0"


class GymnasiumVecEnv(VecEnv):
    """SB3's ``VecEnv`` interface over a Gymnasium ``VectorEnv`` in same-step autoreset mode."""

    def __init__(self, venv: gymnasium.vector.VectorEnv) -> None:
        if venv.metadata.get("autoreset_mode") != AutoresetMode.SAME_STEP:
            raise ValueError("the Gymnasium vector env must use autoreset_mode=AutoresetMode.SAME_STEP")
        self.vec = venv
        super().__init__(venv.num_envs, venv.single_observation_space, venv.single_action_space)
        self._actions: np.ndarray | None = None
        self.sent_masks: list[np.ndarray] = []
        self.outside_mask = 0
        """Actions SB3 sent that the env's own mask ruled out at that moment (0 when honoured)."""

    def _split(self, info: dict[str, Any]) -> list[dict[str, Any]]:
        out: list[dict[str, Any]] = [{} for _ in range(self.num_envs)]
        for key, values in info.items():
            if key.startswith("_"):
                continue
            present = info.get(f"_{key}", np.ones(self.num_envs, bool))
            parts = self._split(values) if isinstance(values, dict) else values
            for i in np.flatnonzero(present):
                out[i][key] = parts[i]
        return out

    def reset(self) -> np.ndarray:
        seed = self._seeds[0] if self._seeds and self._seeds[0] is not None else None
        obs, info = self.vec.reset(seed=seed)
        self._reset_seeds()
        self.reset_infos = self._split(info)
        return obs

    def step_async(self, actions: np.ndarray) -> None:
        masks = np.stack(self.env_method("action_masks"))
        self.outside_mask += int((~masks[np.arange(self.num_envs), actions]).sum())
        self._actions = actions

    def step_wait(self) -> Any:
        obs, rewards, terminated, truncated, info = self.vec.step(self._actions)
        dones = terminated | truncated
        infos = self._split(info)
        for i in np.flatnonzero(dones):
            infos[i]["terminal_observation"] = info["final_obs"][i]
            infos[i]["TimeLimit.truncated"] = bool(truncated[i] and not terminated[i])
        return obs, rewards.astype(np.float32), dones, infos

    def close(self) -> None:
        self.vec.close()

    def get_attr(self, attr_name: str, indices: Any = None) -> list[Any]:
        if attr_name == "render_mode":
            return [None] * self.num_envs
        return list(self.vec.get_attr(attr_name))

    def set_attr(self, attr_name: str, value: Any, indices: Any = None) -> None:
        self.vec.set_attr(attr_name, value)

    def env_method(self, method_name: str, *args: Any, indices: Any = None, **kwargs: Any) -> list[Any]:
        return list(self.vec.call(method_name, *args, **kwargs))

    def env_is_wrapped(self, wrapper_class: type, indices: Any = None) -> list[bool]:
        return [False] * self.num_envs

    def has_attr(self, attr_name: str) -> bool:
        return attr_name == "action_masks" or bool(self.vec.get_attr(attr_name))


def main(steps: int = 1024, seed: int = 0, n_envs: int = 2, human: str = "cooperative") -> dict[str, Any]:
    """Train the robot's seat for ``steps`` steps across ``n_envs`` worker processes."""
    torch.set_num_threads(1)
    vec = gymnasium.make_vec(
        ENV_ID,
        num_envs=n_envs,
        vectorization_mode="async",
        vector_kwargs={"autoreset_mode": AutoresetMode.SAME_STEP},
        human=human,
        max_cycles=200,
    )
    venv = GymnasiumVecEnv(vec)
    try:
        model = MaskablePPO("MlpPolicy", venv, n_steps=128, batch_size=64, n_epochs=2, seed=seed, verbose=0)
        quiet_logger(model)
        start = time.perf_counter()
        model.learn(total_timesteps=steps)
        seconds = time.perf_counter() - start
        masks = get_action_masks(venv)  # the call sb3-contrib makes, through the vector env
    finally:
        venv.close()
    return {
        "library": "gymnasium.make_vec+sb3-contrib",
        "steps": model.num_timesteps,
        "steps_per_s": model.num_timesteps / seconds,
        "outside_mask": venv.outside_mask,
        "mask_shape": tuple(masks.shape),
    }


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=1024)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--envs", type=int, default=2)
    args = parser.parse_args()
    print(main(args.steps, args.seed, args.envs))
