"""Turns per second of TableCleaning-v0 next to PettingZoo's tictactoe_v3, in one run.

Both environments are built by their ``env()`` (so with their standard wrappers) and
driven the same way: at each turn the agent draws uniformly among the actions its
mask allows, from pre-drawn uniform numbers of one seeded Generator (so the driver's
own cost is the same small constant for both). Episodes restart when they end.
Also printed, for context: the same driver on a do-nothing AEC env behind the same
wrapper (the ceiling any PettingZoo env can reach here) and the bare task core.

Usage: ``python benchmarks/env_throughput.py [--turns N] [--repeats R]``.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from typing import Any, ClassVar

import numpy as np
from pettingzoo import AECEnv
from pettingzoo.classic import tictactoe_v3
from pettingzoo.utils import wrappers

import hg_marl
from hg_marl.core import Agent, World


class _Null(AECEnv):
    """Does nothing; measures the AEC API + OrderEnforcingWrapper floor."""

    metadata: ClassVar[dict[str, Any]] = {"name": "null", "render_modes": []}

    def __init__(self) -> None:
        self.possible_agents = ["a", "b"]
        self._obs = {"observation": np.zeros(24, np.int8), "action_mask": np.ones(18, np.int8)}

    def observe(self, agent: str) -> Any:
        return dict(self._obs)

    def reset(self, seed: int | None = None, options: dict | None = None) -> None:
        self.agents = list(self.possible_agents)
        self.rewards = dict.fromkeys(self.agents, 0.0)
        self._cumulative_rewards = dict.fromkeys(self.agents, 0.0)
        self.terminations = dict.fromkeys(self.agents, False)
        self.truncations = dict.fromkeys(self.agents, False)
        self.infos = {a: {} for a in self.agents}
        self.agent_selection = "a"

    def step(self, action: Any) -> None:
        self._cumulative_rewards[self.agent_selection] = 0.0
        self.agent_selection = "b" if self.agent_selection == "a" else "a"


def drive(make: Callable[[], Any], turns: int, seed: int = 0) -> float:
    """Turns per second of ``make()`` under the masked-uniform driver."""
    env = make()
    env.reset(seed=seed)
    u = np.random.default_rng(seed).random(turns)
    start = time.perf_counter()
    for i in range(turns):
        obs, _, term, trunc, _ = env.last()
        if term or trunc:
            env.step(None)
            if not env.agents:
                env.reset()
            continue
        legal = np.flatnonzero(obs["action_mask"])
        env.step(int(legal[int(u[i] * len(legal))]))
    return turns / (time.perf_counter() - start)


def drive_core(turns: int, seed: int = 0) -> float:
    """Turns per second of the bare task core (World.step), same driver."""
    world = World("paper2015")
    rng = np.random.default_rng(seed)
    u = rng.random(turns)
    state = world.initial_state(rng)
    start = time.perf_counter()
    for i in range(turns):
        agent = Agent(i % 2)
        legal = np.flatnonzero(world.mask(state, agent))
        out = world.step(state, agent, int(legal[int(u[i] * len(legal))]))
        state = world.initial_state(rng) if out.reward else out.state
    return turns / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--turns", type=int, default=100_000)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    cases: dict[str, Callable[[], float]] = {
        "tictactoe_v3 (reference)": lambda: drive(tictactoe_v3.env, args.turns),
        "TableCleaning-v0 paper2015": lambda: drive(lambda: hg_marl.env(max_cycles=500), args.turns),
        "TableCleaning-v0 roboergosum": lambda: drive(lambda: hg_marl.env(scenario="roboergosum"), args.turns),
        "null AEC env (wrapper floor)": lambda: drive(lambda: wrappers.OrderEnforcingWrapper(_Null()), args.turns),
        "task core only (World.step)": lambda: drive_core(args.turns),
    }
    best = {name: max(fn() for _ in range(args.repeats)) for name, fn in cases.items()}
    ref = best["tictactoe_v3 (reference)"]
    print(f"{'environment':<32}{'turns/s':>12}{'x tictactoe':>14}")
    for name, rate in best.items():
        print(f"{name:<32}{rate:>12,.0f}{rate / ref:>14.2f}")
    print("target: TableCleaning-v0 >= 10x tictactoe_v3")


if __name__ == "__main__":
    main()
