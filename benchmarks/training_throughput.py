"""Training throughput: environment steps per wall second of each SB3 algorithm on the robot's view.

Usage::

    python benchmarks/training_throughput.py [--steps 4000] [--scenario paper2015] [--human cooperative]

Each algorithm trains for ``--steps`` steps with its packaged hyperparameters (one torch
thread, no evaluation, no checkpoints, no TensorBoard), so the figure is learning plus
environment stepping, the cost a user pays per step of budget. The bare view's speed
under a uniformly random feasible action is printed first as the ceiling.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

from hg_marl.agents.views import RobotView
from hg_marl.training.baselines.envs import EnvSpec
from hg_marl.training.baselines.hyperparams import ALGOS
from hg_marl.training.baselines.train import TrainConfig, train


def view_speed(scenario: str, human: str, steps: int) -> float:
    """Steps per second of the bare view with random feasible actions."""
    env = RobotView(scenario, human=human)
    rng = np.random.default_rng(0)
    env.reset(seed=0)
    t0 = time.perf_counter()
    for _ in range(steps):
        _, _, term, trunc, _ = env.step(int(rng.choice(np.flatnonzero(env.action_masks()))))
        if term or trunc:
            env.reset()
    return steps / (time.perf_counter() - t0)


def main() -> None:
    """Print steps per second per algorithm."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=4000)
    parser.add_argument("--scenario", default="paper2015")
    parser.add_argument("--human", default="cooperative")
    args = parser.parse_args()
    print(f"{args.scenario} vs {args.human}, {args.steps} steps each, 1 torch thread")
    print(f"{'view (random actions)':<24}{view_speed(args.scenario, args.human, args.steps):>8.0f} steps/s")
    for algo in ALGOS:
        with tempfile.TemporaryDirectory() as tmp:
            config = TrainConfig(
                algo=algo,
                env=EnvSpec(scenario=args.scenario, partners=(args.human,)),
                steps=args.steps,
                seed=0,
                out=Path(tmp),
                eval_freq=0,
                checkpoint_freq=0,
                tensorboard=False,
            )
            result = train(config)
        print(
            f"{algo:<24}{result.steps_per_second:>8.0f} steps/s  ({result.session_steps} steps, "
            f"{result.seconds:.1f} s, n_envs={result.hyperparams.n_envs})"
        )


if __name__ == "__main__":
    main()
