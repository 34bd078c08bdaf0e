"""How fast the belief robot identifies its partner, and what its decisions cost.

For each held-out member T of a population (never in the robot's belief set) on a
scenario: the *neighbourhood* of T is the set of believed members A whose exact best
response is good enough for T (headroom matrix entry ``M[A, T] >= 0.95``: believing A
costs at most 5% against T; :mod:`hg_marl.agents.headroom`). *Time to identify* is the
first decision from which the posterior mass on that neighbourhood stays >= 0.9 for the
rest of the run, in simulated seconds and in telling human actions (observations that
moved the belief). Also printed: wall seconds per decision of the belief robot beside
the plain planner's in the same runs (the belief must not cost more than it gains).

    python benchmarks/belief_identify.py --population populations/forced_coordination.toml \
        --scenario forced_coordination --seeds 3 --duration 600
"""

from __future__ import annotations

import argparse
import statistics
import time
from typing import Any

import numpy as np

from hg_marl.agents.headroom import headroom
from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.population import load_population
from hg_marl.agents.robots import make_robot
from hg_marl.training.runner import RunConfig, run

NEIGHBOURHOOD = 0.95
MASS = 0.9


def _bootstrap_median(values: list[float], reps: int = 2000) -> tuple[float, float]:
    rng = np.random.default_rng(0)
    arr = np.asarray(values, dtype=float)
    meds = np.median(rng.choice(arr, size=(reps, arr.size)), axis=1)
    # no interpolation: a resample whose median is "never" (inf) gives inf, not NaN
    return float(np.percentile(meds, 2.5, method="lower")), float(np.percentile(meds, 97.5, method="higher"))


def identify(population: str, scenario: str, seeds: int, duration: float) -> dict[str, Any]:
    pop = load_population(population)
    believed = [*pop.train, *pop.validation]
    rows = []
    for target in pop.held_out:
        result = headroom(scenario, [(target.name, target.spec)], assumed=[(m.name, m.spec) for m in believed])
        column = result.ratio[:, 0]
        near = {
            m.spec
            for m in believed
            if m.name in result.assumed and column[result.assumed.index(m.name)] >= NEIGHBOURHOOD
        }
        for seed in range(seeds):
            robot: Any = make_robot("belief", population=population)
            trace: list[tuple[float, float, int]] = []
            inner = robot.act

            def act(turn: Any, robot: Any = robot, inner: Any = inner, trace: list = trace, near: set = near) -> int:
                action = inner(turn)
                post = robot.posterior.posterior()
                trace.append((turn.clock, sum(post[s] for s in near), robot.posterior.observations))
                return int(action)

            robot.act = act
            start = time.perf_counter()
            out = run(robot, make_human(target.spec), RunConfig(scenario=scenario, duration=duration, seed=seed))
            wall = (time.perf_counter() - start) / max(len(out.log), 1)
            start = time.perf_counter()
            config = RunConfig(scenario=scenario, duration=duration, seed=seed)
            plain = run(make_robot("planner"), make_human(target.spec), config)
            plain_wall = (time.perf_counter() - start) / max(len(plain.log), 1)
            when = next(
                (i for i in range(len(trace)) if all(mass >= MASS for _, mass, _ in trace[i:])),
                None,
            )
            rows.append(
                {
                    "member": target.name,
                    "seed": seed,
                    "neighbourhood": len(near),
                    "seconds": trace[when][0] if when is not None else float("inf"),
                    "actions": trace[when][2] if when is not None else -1,
                    "wall_ms": 1000 * wall,
                    "planner_wall_ms": 1000 * plain_wall,
                }
            )
    return {"rows": rows}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--population", required=True)
    parser.add_argument("--scenario", required=True)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--duration", type=float, default=600.0)
    args = parser.parse_args()
    rows = identify(args.population, args.scenario, args.seeds, args.duration)["rows"]
    head = ("member", "seed", "|nbhd|", "identified (s)", "(actions)", "ms/decision", "planner")
    print(f"{head[0]:8} {head[1]:>4} {head[2]:>6} {head[3]:>15} {head[4]:>9} {head[5]:>12} {head[6]:>8}")
    for r in rows:
        print(
            f"{r['member']:8} {r['seed']:>4} {r['neighbourhood']:>6} {r['seconds']:>15.1f} {r['actions']:>9} "
            f"{r['wall_ms']:>12.2f} {r['planner_wall_ms']:>8.2f}"
        )
    secs = [r["seconds"] for r in rows]
    lo, hi = _bootstrap_median(secs)
    print(f"time to identify: median {statistics.median(secs):.1f} s [95% CI {lo:.1f}, {hi:.1f}] over {len(rows)} runs")
    ratio = statistics.mean(r["wall_ms"] for r in rows) / statistics.mean(r["planner_wall_ms"] for r in rows)
    print(f"decision wall time: belief / planner = {ratio:.2f}x")


if __name__ == "__main__":
    main()
