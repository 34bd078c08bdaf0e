"""Answer time of the ``preference`` human, beside the rule-based ``lazy`` human measured in the same run.

The oracle asks a stationary human for its distribution at every mid-cycle state it
explores, so this is the figure that bounds its model build. States are drawn by a
random walk of both seats (each state asked once, cold: a fresh human, no memo), and
the mean and 95th percentile of ``distribution(world, state)`` are printed per human.
Run::

    python benchmarks/preference_latency.py [--scenario roboergosum] [--states 20000] [--seed 0]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.core import Agent, World

HUMANS = ("lazy", "preference", "preference:temperature=0.5,accept=0.5,p_idle=0.2")


def states(world: World, n: int, seed: int) -> list:
    rng = np.random.default_rng(seed)
    state = world.initial_state(rng)
    seen: dict = {}
    while len(seen) < n:
        for agent in (Agent.ROBOT, Agent.HUMAN):
            feasible = world.feasible_indices(state, agent)
            state = world.step(state, agent, int(feasible[rng.integers(len(feasible))])).state
            if agent is Agent.ROBOT:
                seen.setdefault(state, None)
        if world.is_clean(state):
            state = world.initial_state(rng)
    return list(seen)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default="roboergosum")
    parser.add_argument("--states", type=int, default=20_000)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    world = World(args.scenario)
    sample = states(world, args.states, args.seed)
    print(f"{args.scenario}: {len(sample)} distinct mid-cycle states from a random walk")
    for spec in HUMANS:
        human = make_human(spec)
        times = []
        for state in sample:
            start = time.perf_counter()
            human.distribution(world, state)  # type: ignore[attr-defined]
            times.append(time.perf_counter() - start)
        us = np.array(times) * 1e6
        print(f"{spec:<52} mean {us.mean():7.1f} us   p95 {np.percentile(us, 95):7.1f} us")


if __name__ == "__main__":
    main()
