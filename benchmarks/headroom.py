"""Adaptation headroom of the bundled scenarios, beside its goal, and the wall time of each solve.

    python benchmarks/headroom.py [--population populations/hard_layouts.toml] [--scenarios a;b] [--max-seconds 600]

For each scenario: the exact headroom (1 - IQM over the population's held-out members of
the cooperative model's optimal policy played with them, ``hg_marl.agents.headroom``),
the goal (>= 0.25 on the hard layouts; measured only on roboergosum and paper2015, whose
optimal policy hardly depends on the partner), the model's size and the wall time. A
scenario over its budget prints the budget's message instead of a number.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from hg_marl.agents.headroom import headroom
from hg_marl.agents.humans.population import load_population
from hg_marl.agents.oracle import OracleTooLarge

GOALS = {"forced_coordination": 0.25, "asymmetric_advantages": 0.25}
ROOT = Path(__file__).parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--population", default=str(ROOT / "populations" / "hard_layouts.toml"))
    parser.add_argument("--scenarios", default="forced_coordination;asymmetric_advantages;paper2015;roboergosum")
    parser.add_argument("--max-seconds", type=float, default=600.0)
    args = parser.parse_args()
    pop = load_population(args.population)
    members = [(m.name, m.spec) for m in pop.members()]
    held = [m.name for m in pop.held_out]
    print(f"population {pop.name}: {len(members)} members, held out: {', '.join(held)}")
    print(f"{'scenario':<24} {'headroom':>9} {'goal':>8} {'states':>8} {'seconds':>8}")
    for scenario in args.scenarios.split(";"):
        start = time.perf_counter()
        try:
            result = headroom(scenario, members, held, max_seconds=args.max_seconds, progress=True)
        except OracleTooLarge as exc:
            print(f"{scenario:<24} not measured: {exc} ({time.perf_counter() - start:.0f} s)")
            continue
        goal = GOALS.get(scenario)
        verdict = "-" if goal is None else (f">={goal} met" if result.headroom >= goal else f">={goal} MISSED")
        print(f"{scenario:<24} {result.headroom:>9.3f} {verdict:>8} {result.n_states:>8} {result.seconds:>8.1f}")


if __name__ == "__main__":
    main()
