"""``ppo_recurrent`` throughput: env steps/s beside learner steps/s, and steps per CPU second.

Usage::

    python benchmarks/recurrent_throughput.py [--scenario forced_coordination] [--steps 262144]
        [--num-envs 256,1024] [--memory gru] [--threads 1]

Each configuration trains ``ppo_recurrent`` (recipe ``members``, the hard layouts' three
train members, no checkpoints, no held-out curve) for ``--steps`` steps and prints the
speeds the training command prints (env: time inside ``env.step``; learner: the rest,
forward passes while acting and the updates) and the steps per CPU second of this
process (``time.process_time``), the figure that does not depend on what else the
machine is running. The partners are compiled before the clock starts; the clock
includes building the tables and a one-second greedy evaluation at the end.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig, make_env, train_recurrent

TRAIN_MEMBERS = ("preference", "preference:handover=0.2,shared=0.8", "preference:handover=1.0,shared=-0.5")


def main() -> None:
    """Print one line of speeds per table count."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default="forced_coordination")
    parser.add_argument("--steps", type=int, default=262_144)
    parser.add_argument("--num-envs", default="256,1024")
    parser.add_argument("--memory", default="gru")
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    print(f"ppo_recurrent ({args.memory}) on {args.scenario}, {args.steps} steps, {args.threads} torch thread(s)")
    with tempfile.TemporaryDirectory() as tmp:
        for n in (int(x) for x in args.num_envs.split(",")):
            config = RecurrentConfig(
                humans=TRAIN_MEMBERS,
                scenario=args.scenario,
                memory=args.memory,
                steps=args.steps,
                num_envs=n,
                eval_envs=1,
                eval_seconds=1.0,
                threads=args.threads,
                out=Path(tmp) / str(n),
            )
            make_env(config, 1)  # compiles the partners into OUT/partners off the clock (training loads them)
            cpu, wall = time.process_time(), time.perf_counter()
            result = train_recurrent(config)
            cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
            speeds = (
                f"{result.env_steps_per_second:>9,.0f} env steps/s | {result.learner_steps_per_second:>7,.0f} "
                f"learner steps/s | {result.steps_per_second:>7,.0f} overall"
            )
            per_cpu = f"{result.num_timesteps / cpu:>7,.0f} steps per CPU s"
            size = f"({result.num_timesteps} steps, {wall:.0f} s wall, {cpu:.0f} s CPU)"
            print(f"num_envs={n:<6} {speeds} | {per_cpu} {size}")


if __name__ == "__main__":
    main()
