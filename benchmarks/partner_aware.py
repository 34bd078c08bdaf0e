"""Partner-aware robots beside the same robots with the fixed cooperative model.

10 seeds, 1100 simulated s, paper2015; prints tasks solved per robot and the paired
difference with its 95% bootstrap CI (the partner-aware table of docs/results.md):
``python benchmarks/partner_aware.py``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.training.regret import bootstrap_ci
from hg_marl.training.runner import RunConfig, run

SWITCHING = {"humans": ["cooperative", "lazy", "no_handover"], "at": [400.0, 750.0], "by": "time"}
HUMANS: dict[str, tuple[str, dict[str, Any]]] = {
    "cooperative": ("cooperative", {}),
    "lazy": ("lazy", {}),
    "no_handover": ("no_handover", {}),
    "noisy": ("noisy", {}),
    "switching": ("switching", SWITCHING),
}
ROBOTS: dict[str, tuple[str, dict[str, Any]]] = {
    "planner": ("planner", {}),
    "planner_pa": ("planner", {"partner_aware": True}),
    "hybrid": ("hybrid", {}),
    "hybrid_pa": ("hybrid", {"partner_aware": True}),
}


def tasks(robot: tuple[str, dict[str, Any]], human: tuple[str, dict[str, Any]], seeds: int = 10) -> np.ndarray:
    """Tasks solved in each seed's 1100 s run."""
    out = []
    for seed in range(seeds):
        result = run(
            make_robot(robot[0], **robot[1]), make_human(human[0], **human[1]), RunConfig(duration=1100.0, seed=seed)
        )
        out.append(result.summary["tasks_solved"])
    return np.array(out, dtype=float)


def main() -> None:
    for name, human in HUMANS.items():
        res = {label: tasks(robot, human) for label, robot in ROBOTS.items()}
        line = f"{name:12s} " + " ".join(f"{label}={v.mean():.1f}" for label, v in res.items())
        for a, b in (("planner_pa", "planner"), ("hybrid_pa", "hybrid")):
            mean, low, high = bootstrap_ci(res[a] - res[b])
            line += f" | {a}-{b}: {mean:+.2f} [{low:+.2f}, {high:+.2f}]"
        print(line, flush=True)


if __name__ == "__main__":
    main()
