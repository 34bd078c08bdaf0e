"""SuperSuit vector env into SB3: MaskablePPO with one shared policy for robot and human.

The turn-based parallel env, homogenised (shared spaces, agent-id feature) and flattened
with the action mask in ``infos``, becomes an SB3 ``VecEnv`` through SuperSuit's
``pettingzoo_env_to_vec_env_v1`` + ``concat_vec_envs_v1``: each agent is one sub-env, so
both seats train one parameter-shared policy. sb3-contrib reads masks through
``env_method("action_masks")``; ``hg_marl.wrappers.sb3.InfoMasks`` answers it from the last infos and
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

import supersuit as ss
import torch
from sb3_contrib import MaskablePPO

import hg_marl
from hg_marl.wrappers import AUDITS, audit_totals, audit_v0, flatten_v0, homogenize_v0, to_parallel
from hg_marl.wrappers.sb3 import InfoMasks, quiet_logger


def main(steps: int = 2048, seed: int = 0) -> dict[str, Any]:
    """Train for ``steps`` agent-steps; return the audit of the actions sent."""
    torch.set_num_threads(1)
    AUDITS.clear()
    parallel = to_parallel(flatten_v0(homogenize_v0(audit_v0(hg_marl.env(max_cycles=200))), mask="info"))
    venv = ss.pettingzoo_env_to_vec_env_v1(parallel)
    venv = ss.concat_vec_envs_v1(venv, 1, num_cpus=0, base_class="stable_baselines3")
    venv = InfoMasks(venv)
    parallel.reset(seed=seed)  # seeds the table's generator; vector resets then continue it
    model = quiet_logger(MaskablePPO("MlpPolicy", venv, n_steps=128, batch_size=64, n_epochs=2, seed=seed, verbose=0))
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
