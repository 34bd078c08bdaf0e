"""SuperSuit vector env into SB3: MaskablePPO with one shared policy for robot and human.

The turn-based parallel env, homogenised (shared spaces, agent-id feature) and flattened
with the action mask in ``infos``, becomes an SB3 ``VecEnv`` through SuperSuit's
``pettingzoo_env_to_vec_env_v1`` + ``concat_vec_envs_v1``: each agent is one sub-env, so
both seats train one parameter-shared policy. sb3-contrib reads masks through
``env_method("action_masks")``; :class:`InfoMasks` answers it from the last infos and
counts any action sent outside the mask it served (``outside_mask``, 0 when honoured).

In the parallel view the human's mask is the one at the start of the cycle: the robot
moves first, so a human action that was feasible when chosen can fail when executed
(``infeasible_when_executed["human"]``, counted against the real state by ``audit_v0``).
That is the parallel view's semantics, not the mask being ignored; the AEC examples
(Tianshou, RLlib) have no such gap.

Run: ``python examples/supersuit_sb3.py --steps 2048``. Needs ``pip install "hg-marl[supersuit]"``.
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import numpy as np
import supersuit as ss
import torch
from sb3_contrib import MaskablePPO
from stable_baselines3.common.vec_env import VecEnvWrapper

import hg_marl
from hg_marl.wrappers import AUDITS, audit_totals, audit_v0, flatten_v0, homogenize_v0, to_parallel


class InfoMasks(VecEnvWrapper):
    """Serves ``env_method("action_masks")`` (sb3-contrib's hook) from the masks in the last infos."""

    def __init__(self, venv: Any) -> None:
        super().__init__(venv)
        self._masks = np.ones((self.num_envs, int(self.action_space.n)), dtype=bool)
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
        """SuperSuit's concatenated env has no ``seed``; the parallel env is seeded by ``main``."""
        return [None] * self.num_envs

    def has_attr(self, attr_name: str) -> bool:
        """sb3-contrib asks whether the envs have ``action_masks`` before training."""
        return attr_name == "action_masks"

    def env_method(self, method_name: str, *args: Any, indices: Any = None, **kwargs: Any) -> list[Any]:
        if method_name == "action_masks":
            return list(self._masks)
        return self.venv.env_method(method_name, *args, indices=indices, **kwargs)


def main(steps: int = 2048, seed: int = 0) -> dict[str, Any]:
    """Train for ``steps`` agent-steps; return the audit of the actions sent."""
    torch.set_num_threads(1)
    AUDITS.clear()
    parallel = to_parallel(flatten_v0(homogenize_v0(audit_v0(hg_marl.env(max_cycles=200))), mask="info"))
    venv = ss.pettingzoo_env_to_vec_env_v1(parallel)
    venv = ss.concat_vec_envs_v1(venv, 1, num_cpus=0, base_class="stable_baselines3")
    venv = InfoMasks(venv)
    parallel.reset(seed=seed)  # seeds the table's generator; vector resets then continue it
    model = MaskablePPO("MlpPolicy", venv, n_steps=128, batch_size=64, n_epochs=2, seed=seed, verbose=0)
    start = time.perf_counter()
    model.learn(total_timesteps=steps)
    seconds = time.perf_counter() - start
    sent, infeasible = audit_totals()  # concat_vec_envs_v1 may copy the env: count every copy
    return {
        "library": "supersuit+sb3",
        "steps": model.num_timesteps,
        "steps_per_s": model.num_timesteps / seconds,
        "outside_mask": venv.outside_mask,
        "sent": sent,
        "infeasible_when_executed": infeasible,
    }


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=2048)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    print(main(args.steps, args.seed))
