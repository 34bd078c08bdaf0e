"""Steps per second of the batched table beside Gymnasium's CartPoleVectorEnv and the single-table view.

Random masked actions (uniform over each table's feasible actions), the compiled
cooperative human inside, ``num_envs`` tables in one process. Printed for each scenario:
batched steps/s (numpy, and the torch CPU backend), CartPoleVectorEnv's steps/s at the
same ``num_envs`` measured in the same run, the single-table ``RobotView`` with the same
(live) human, the ratios against the goals (paper2015 >= 0.10x CartPole, roboergosum >=
0.03x, >= 100x the single view), the compile (or cache load) time and the peak memory
of the process (batched env + compiled partner; <= 2 GB for roboergosum). Run::

    python benchmarks/batched_throughput.py [--num-envs 4096] [--seconds 5] [--scenario paper2015 roboergosum]

``--learned FOLDER`` (a human-seat SB3 policy, e.g. from ``hg-marl train --seat human``)
adds, per scenario, the batched env with that learned human (one forward pass of its
policy per step over all tables) beside the single ``RobotView`` with the same live
learned human, both measured in the same run; torch runs on one thread.
"""

from __future__ import annotations

import argparse
import resource
import time
from typing import Any

import numpy as np
from gymnasium.envs.classic_control.cartpole import CartPoleVectorEnv

from hg_marl.agents.compiled import compile_human
from hg_marl.agents.views import RobotView
from hg_marl.core import World
from hg_marl.envs.batched import BatchedTable

GOALS = {"paper2015": 0.10, "roboergosum": 0.03}


def peak_mb() -> float:
    """The process's peak resident memory (Linux reports kilobytes)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def timed(step: Any, seconds: float, per_call: int) -> float:
    """Steps per second of ``step()`` called for about ``seconds``."""
    step()
    calls, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        step()
        calls += 1
    return calls * per_call / (time.perf_counter() - start)


def cartpole(num_envs: int, seconds: float) -> float:
    env = CartPoleVectorEnv(num_envs=num_envs)
    env.reset(seed=0)
    rng = np.random.default_rng(0)
    return timed(lambda: env.step(rng.integers(0, 2, num_envs)), seconds, num_envs)


def batched(world: World, partner: Any, num_envs: int, seconds: float, device: Any = None) -> float:
    env = BatchedTable(partner, num_envs, world, device=device)
    env.reset(seed=0)
    rng = np.random.default_rng(0)

    def step() -> None:
        masks = env.action_masks()
        env.step((rng.random(masks.shape) * masks).argmax(1))

    return timed(step, seconds, num_envs)


def single(scenario: str, seconds: float, human: str = "cooperative") -> float:
    env = RobotView(scenario=scenario, human=human)
    env.reset(seed=0)
    rng = np.random.default_rng(0)

    def step() -> None:
        mask = env.action_masks()
        _, _, term, trunc, _ = env.step(int((rng.random(mask.shape) * mask).argmax()))
        if term or trunc:
            env.reset()

    return timed(step, seconds, 1)


def learned(world: World, spec: str, num_envs: int, seconds: float) -> None:
    """Batched env with a learned SB3 human beside the single view with the same live human."""
    from hg_marl.agents.views import compiled_humans

    partner = compiled_humans(world, spec, cache=None)
    name = world.scenario.name
    fast = batched(world, partner, num_envs, seconds)
    one = single(name, seconds, spec)
    print(
        f"{name:12s} batched learned-sb3 num_envs={num_envs}: {fast:12,.0f} steps/s "
        f"({type(partner).__name__}: one forward pass per step)"
    )
    print(f"{name:12s} single RobotView learned-sb3: {one:12,.0f} steps/s; batched = {fast / one:,.0f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--num-envs", type=int, default=4096)
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--scenario", nargs="+", default=["paper2015", "roboergosum"])
    parser.add_argument("--no-torch", action="store_true", help="skip the torch CPU backend")
    parser.add_argument("--learned", metavar="FOLDER", help="also measure this human-seat SB3 policy as the partner")
    parser.add_argument("--no-compiled", action="store_true", help="skip CartPole and the compiled cooperative rows")
    args = parser.parse_args()
    n = args.num_envs
    if args.learned is not None:
        import torch

        torch.set_num_threads(1)
        for scenario in args.scenario:
            learned(World(scenario), f"learned:path={args.learned}", n, args.seconds)
    if args.no_compiled:
        return
    ref = cartpole(n, args.seconds)
    print(f"CartPoleVectorEnv            num_envs={n}: {ref:12,.0f} steps/s (reference)")
    for scenario in args.scenario:
        world = World(scenario)
        start = time.perf_counter()
        partner = compile_human(world, "cooperative", progress=True)
        built = time.perf_counter() - start
        fast = batched(world, partner, n, args.seconds)
        one = single(scenario, args.seconds)
        goal = GOALS.get(scenario)
        print(
            f"{scenario:12s} batched numpy  num_envs={n}: {fast:12,.0f} steps/s = {fast / ref:.3f}x CartPole"
            + (f" (goal >= {goal:.2f}x: {'met' if fast / ref >= goal else 'NOT met'})" if goal else "")
        )
        if not args.no_torch:
            torch_sps = batched(world, partner, n, args.seconds, device="cpu")
            ratio = torch_sps / fast
            print(f"{scenario:12s} batched torch-cpu         : {torch_sps:12,.0f} steps/s = {ratio:.2f}x numpy")
        print(
            f"{scenario:12s} single RobotView          : {one:12,.0f} steps/s; batched = {fast / one:,.0f}x "
            f"(goal >= 100x: {'met' if fast / one >= 100 else 'NOT met'})"
        )
        print(
            f"{scenario:12s} compiled cooperative: {len(partner):,} keys in {built:.1f} s; "
            f"fallbacks {partner.fallbacks}; peak memory so far {peak_mb():,.0f} MB"
        )


if __name__ == "__main__":
    main()
