"""Partner-aware robots beside the same robots with the fixed cooperative model.

10 seeds, 1100 simulated s, paper2015; prints tasks solved per robot and the paired
difference with its 95% bootstrap CI (the README's partner-aware table):
``python benchmarks/partner_aware.py``.
"""

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.training.regret import bootstrap_ci
from hg_marl.training.runner import RunConfig, run

HUMANS = {
    "cooperative": ("cooperative", {}),
    "lazy": ("lazy", {}),
    "no_handover": ("no_handover", {}),
    "noisy": ("noisy", {}),
    "switching": ("switching", {"humans": ["cooperative", "lazy", "no_handover"], "at": [400.0, 750.0], "by": "time"}),
}
ROBOTS = {
    "planner": ("planner", {}),
    "planner_pa": ("planner", {"partner_aware": True}),
    "hybrid": ("hybrid", {}),
    "hybrid_pa": ("hybrid", {"partner_aware": True}),
}
for h, (hn, hp) in HUMANS.items():
    res = {}
    for r, (rn, rp) in ROBOTS.items():
        res[r] = np.array(
            [
                run(make_robot(rn, **rp), make_human(hn, **hp), RunConfig(duration=1100, seed=s)).summary[
                    "tasks_solved"
                ]
                for s in range(10)
            ],
            float,
        )
    line = f"{h:12s} " + " ".join(f"{r}={v.mean():.1f}" for r, v in res.items())
    for a, b in (("planner_pa", "planner"), ("hybrid_pa", "hybrid")):
        m, lo, hi = bootstrap_ci(res[a] - res[b])
        line += f" | {a}-{b}: {m:+.2f} [{lo:+.2f}, {hi:+.2f}]"
    print(line, flush=True)
