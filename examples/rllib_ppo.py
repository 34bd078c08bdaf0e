"""RLlib PPO on the new API stack with action masking: robot trained against a fixed project human, or both trained.

RLlib's ``PettingZooEnv`` takes the AEC env; :func:`flatten_v0` gives each agent
``{"observations": float32 facts, "action_mask": int8}``, the form RLlib's
``ActionMaskingTorchRLModule`` reads (infeasible logits set to the float minimum, so
they are never sampled). Each seat keeps its own spaces and its own module.

- ``--mode fixed``: the human is ``scripted_v0(..., human="cooperative")`` played by
  :func:`~hg_marl.agents.adapters.rllib_fixed_module_class`, not in ``policies_to_train``.
- ``--mode both``: both seats are ``ActionMaskingTorchRLModule`` and both train.

``audit_v0`` counts infeasible actions against the real state (0 for trained seats).
The env runs in the driver process (``num_env_runners=0``) so the audit can be read.

Run: ``python examples/rllib_ppo.py --mode fixed --iterations 1``. Needs ``pip install "hg-marl[rllib]"``.
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import ray
from ray.rllib.algorithms.ppo import PPOConfig
from ray.rllib.core.rl_module.multi_rl_module import MultiRLModuleSpec
from ray.rllib.core.rl_module.rl_module import RLModuleSpec
from ray.rllib.env.wrappers.pettingzoo_env import PettingZooEnv
from ray.rllib.examples.rl_modules.classes.action_masking_rlm import ActionMaskingTorchRLModule
from ray.tune.registry import register_env

import hg_marl
from hg_marl.agents.adapters import rllib_fixed_module_class, scripted_v0
from hg_marl.wrappers import AUDITS, audit_totals, audit_v0, flatten_v0

MODES = ("fixed", "both")


def make_env(config: dict[str, Any]) -> PettingZooEnv:
    """RLlib's env creator: the flat, masked AEC env (the human scripted in ``fixed`` mode)."""
    env = audit_v0(hg_marl.env(max_cycles=int(config.get("max_cycles", 100))))
    if config.get("human"):
        env = scripted_v0(env, human=config["human"])
    return PettingZooEnv(flatten_v0(env))


def main(mode: str = "fixed", iterations: int = 1, batch: int = 256, seed: int = 0) -> dict[str, Any]:
    """Train ``iterations`` PPO iterations of ``batch`` env steps; return throughput and the audit."""
    if mode not in MODES:
        raise ValueError(f"mode must be one of {MODES}, got {mode!r}")
    # address="local": always a private instance, never a cluster some other process started.
    ray.init(address="local", num_cpus=1, include_dashboard=False, ignore_reinit_error=True, log_to_driver=False)
    register_env("hg_marl_table_cleaning", make_env)
    masked = RLModuleSpec(module_class=ActionMaskingTorchRLModule, model_config={"head_fcnet_hiddens": [64]})
    specs = {
        "robot": masked,
        "human": masked if mode == "both" else RLModuleSpec(module_class=rllib_fixed_module_class()),
    }
    config = (
        PPOConfig()
        # RLlib's env checker steps with unmasked random actions; the tests of this project check the env.
        .environment(
            "hg_marl_table_cleaning",
            env_config={"human": "cooperative" if mode == "fixed" else ""},
            disable_env_checking=True,
        )
        .env_runners(num_env_runners=0, rollout_fragment_length=batch)
        .learners(num_learners=0)
        .multi_agent(
            policies={"robot", "human"},
            policy_mapping_fn=lambda agent_id, *args, **kwargs: agent_id,
            policies_to_train=["robot", "human"] if mode == "both" else ["robot"],
        )
        .rl_module(rl_module_spec=MultiRLModuleSpec(rl_module_specs=specs))
        .training(train_batch_size_per_learner=batch, minibatch_size=64, num_epochs=1)
        .debugging(seed=seed)
    )
    AUDITS.clear()
    algo = config.build_algo()
    start = time.perf_counter()
    try:
        for _ in range(iterations):
            algo.train()
        seconds = time.perf_counter() - start
        sent, infeasible = audit_totals()  # before stop(): the env runner's envs are still alive
    finally:
        algo.stop()
        ray.shutdown()
    return {
        "library": f"rllib ({mode})",
        "steps": sent["robot"] + sent["human"],
        "steps_per_s": (sent["robot"] + sent["human"]) / seconds,
        "sent": sent,
        "infeasible": infeasible,
    }


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", choices=MODES, default="fixed")
    parser.add_argument("--iterations", type=int, default=1)
    parser.add_argument("--batch", type=int, default=256)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    print(main(args.mode, args.iterations, args.batch, args.seed))
