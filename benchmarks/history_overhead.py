"""Steps per second of the batched robot seat with the history observation beside the same table without it.

Random masked actions, the compiled cooperative human, ``num_envs`` tables; both envs
measured in the same run, alternating, so the ratio holds on a loaded machine. The
history is recorded for every table with whole-array operations (``hg_marl/envs/history.py``)::

    python benchmarks/history_overhead.py [--num-envs 4096] [--seconds 3] [--history 4] [--scenario paper2015]
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import numpy as np

from hg_marl.agents.views import robot_vector_env


def rate(env: Any, seconds: float, rng: np.random.Generator) -> float:
    """Steps per second of ``env`` under random masked actions for about ``seconds``."""
    env.reset(seed=0)
    steps, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        mask = env.action_masks()
        env.step(np.argmax(rng.random(mask.shape) * mask, axis=1))
        steps += env.num_envs
    return steps / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--num-envs", type=int, default=4096)
    parser.add_argument("--seconds", type=float, default=3.0)
    parser.add_argument("--history", type=int, default=4)
    parser.add_argument("--scenario", default="paper2015")
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    common = {"num_envs": args.num_envs, "scenario": args.scenario, "continuing": True, "max_cycles": None}
    plain, with_history = robot_vector_env(**common), robot_vector_env(**common, history=args.history)
    rates: dict[str, list[float]] = {"plain": [], "history": []}
    for _ in range(3):
        rates["plain"].append(rate(plain, args.seconds / 3, rng))
        rates["history"].append(rate(with_history, args.seconds / 3, rng))
    p, h = max(rates["plain"]), max(rates["history"])
    head = f"{args.scenario}, {args.num_envs} tables"
    print(f"{head}: facts {p:,.0f} steps/s | facts + history({args.history}) {h:,.0f} steps/s")
    print(f"  history / facts = {h / p:.2f}x (measured in the same run)")


if __name__ == "__main__":
    main()
