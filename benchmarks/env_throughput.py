"""Steps per second of TableCleaning-v0 and its robot's-eye view, beside CartPole-v1, in one run.

Two families of workloads, each measured in the same process and printed beside the
reference measured in the same run (the machine may be loaded: compare ratios):

- **AEC** (turns/s): ``hg_marl.env()`` (with its standard wrapper) on ``paper2015`` and
  ``roboergosum``, next to a do-nothing AEC env behind the same wrapper (the ceiling any
  PettingZoo env reaches here; target >= 80% of it) and the bare task core. At each turn
  the agent draws uniformly among the actions its mask allows, from pre-drawn uniform
  numbers of one seeded Generator.
- **Robot's-eye view** (steps/s, one step = one cycle with the human's reply):
  ``gymnasium.make("hg_marl/RobotTableCleaning-v0")`` with the cooperative and noisy
  humans (who call the planner), random robot actions among the feasible ones, next to
  ``CartPole-v1`` driven by the same loop. Targets: cooperative >= 5,000 steps/s on
  ``paper2015`` and >= 2,000 on ``roboergosum``; noisy >= 1,000 on ``roboergosum``.

Each workload prints a progress line when it starts and its rate when done.

Usage: ``python benchmarks/env_throughput.py [--turns N] [--steps N] [--repeats R]``.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable
from typing import Any, ClassVar

import gymnasium
import numpy as np
from pettingzoo import AECEnv
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


def drive_aec(make: Callable[[], Any], turns: int, seed: int = 0) -> float:
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


def drive_gym(make: Callable[[], Any], steps: int, seed: int = 0) -> float:
    """Steps per second of a Gymnasium env: random actions (among the feasible ones when the
    env has ``action_masks``), pre-drawn from one seeded Generator; resets when an episode ends."""
    env = make()
    env.reset(seed=seed)
    masks = getattr(env.unwrapped, "action_masks", None)
    n = env.action_space.n
    u = np.random.default_rng(seed).random(steps)
    start = time.perf_counter()
    for i in range(steps):
        if masks is not None:
            legal = np.flatnonzero(masks())
            action = int(legal[int(u[i] * len(legal))])
        else:
            action = int(u[i] * n)
        _, _, term, trunc, _ = env.step(action)
        if term or trunc:
            env.reset()
    return steps / (time.perf_counter() - start)


def robot_view(scenario: str, human: str) -> Callable[[], Any]:
    """A maker of the robot's-eye view with ``human``."""
    return lambda: gymnasium.make("hg_marl/RobotTableCleaning-v0", scenario=scenario, human=human)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--turns", type=int, default=100_000, help="AEC turns per repeat")
    parser.add_argument("--steps", type=int, default=20_000, help="robot's-eye view steps per repeat")
    parser.add_argument("--repeats", type=int, default=3, help="best of R repeats per workload")
    args = parser.parse_args()
    t, s = args.turns, args.steps
    aec: dict[str, Callable[[], float]] = {
        "null AEC env (ceiling)": lambda: drive_aec(lambda: wrappers.OrderEnforcingWrapper(_Null()), t),
        "TableCleaning-v0 paper2015": lambda: drive_aec(lambda: hg_marl.env(max_cycles=500), t),
        "TableCleaning-v0 roboergosum": lambda: drive_aec(lambda: hg_marl.env(scenario="roboergosum"), t),
        "task core only (World.step)": lambda: drive_core(t),
    }
    gym: dict[str, Callable[[], float]] = {
        "CartPole-v1 (reference)": lambda: drive_gym(lambda: gymnasium.make("CartPole-v1"), s),
        "robot view paper2015 cooperative": lambda: drive_gym(robot_view("paper2015", "cooperative"), s),
        "robot view roboergosum cooperative": lambda: drive_gym(robot_view("roboergosum", "cooperative"), s),
        "robot view roboergosum noisy": lambda: drive_gym(robot_view("roboergosum", "noisy"), s),
    }
    targets = {
        "TableCleaning-v0 paper2015": ">= 0.80 x ceiling",
        "TableCleaning-v0 roboergosum": ">= 0.80 x ceiling",
        "robot view paper2015 cooperative": ">= 5,000/s",
        "robot view roboergosum cooperative": ">= 2,000/s",
        "robot view roboergosum noisy": ">= 1,000/s",
    }
    results: dict[str, float] = {}
    for name, fn in {**aec, **gym}.items():
        print(f"... {name}", file=sys.stderr, flush=True)
        start = time.perf_counter()
        results[name] = max(fn() for _ in range(args.repeats))
        print(f"    {results[name]:,.0f}/s ({time.perf_counter() - start:.1f} s)", file=sys.stderr, flush=True)
    for title, group, ref in (
        ("AEC turns/s", aec, "null AEC env (ceiling)"),
        ("steps/s", gym, "CartPole-v1 (reference)"),
    ):
        print(f"{'workload':<38}{title:>14}{'x ' + ref.split(' ')[0]:>16}  target")
        for name in group:
            rate = results[name]
            print(f"{name:<38}{rate:>14,.0f}{rate / results[ref]:>16.3f}  {targets.get(name, '')}")
        print()


if __name__ == "__main__":
    main()
