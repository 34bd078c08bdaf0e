"""Planner latency: planning time and nodes expanded against the number of objects.

Run: ``python benchmarks/planner_latency.py [--seeds 5] [--budget 20000] [--repeats 5]``.
Prints one row per workload: median and 95th-percentile cold planning time (each case
planned cold ``--repeats`` times, each time on a fresh world: a single cold plan per case
varied by 20% from run to run on a busy machine) and the median CPU time
(less sensitive to a loaded machine) of a fresh ``Planner``, the median CPU time of
constructing it (its static tables: not part of the planning time)
(no plan, candidate or bound cached: each case gets its own ``World``, since planners of
one world share their search space's caches), the
warm time (the same query again: a cache hit), nodes expanded, and how many calls
proved the optimum within the node budget. Targets:
paper2015 initial state <= 1 ms median, roboergosum <= 10 ms, 20 objects <= 100 ms with
the optimum proven.

Beside each row, ``ref cpu`` is the median CPU time of the same cold plans with the
search as it was before its inner loop was compiled into tables (``planner_reference.py``:
edges by ``successor_feasible``, sums by ``math.fsum``, the old candidate and search
loops, run by the same :class:`Planner`), measured in the same run on fresh worlds, each
reference plan right after the plan it is compared with;
``x`` is the ratio and ``same`` says whether both found the same plans and costs. On a
loaded machine read the ratio, not the milliseconds.
"""

from __future__ import annotations

import argparse
import statistics
import time
from unittest.mock import patch

import numpy as np
from planner_reference import ReferenceSpace, reference_astar  # benchmarks/ is the script's folder

from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.agents.planner.domain import Domain
from hg_marl.core import State, World


def reference_plan(world: World, state: State, budget: int) -> tuple[float, tuple[object, float]]:
    """CPU seconds of one cold plan by a :class:`Planner` searching as it did before
    (:mod:`planner_reference`) on a fresh world, and the plan found (cycles, cost)."""
    fresh = World(world.scenario, world.durations)
    planner = Planner(fresh, PlannerConfig(node_budget=budget))
    planner.space = ReferenceSpace(Domain(fresh, planner.human_model), planner.config.weights)
    with patch("hg_marl.agents.planner.planner.astar", reference_astar):
        start_cpu = time.process_time()
        result = planner.plan(state)
        cpu = time.process_time() - start_cpu
    return cpu, (result.plan.cycles if result.plan else None, result.cost)


def same_plans(a: list[tuple[object, float]], b: list[tuple[object, float]]) -> bool:
    """Equal cycles and equal costs (both priced by the same plan replay)."""
    return a == b


def percentile(values: list[float], q: float) -> float:
    """The q-th percentile (nearest rank)."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, max(0, round(q / 100 * len(ordered) + 0.5) - 1))]


def measure(cases: list[tuple[World, State]], budget: int, repeats: int = 1) -> dict[str, float | int | str]:
    """Cold and warm planning statistics over ``(world, initial state)`` cases, each planned
    cold ``repeats`` times (on a fresh world each time: planners of one world share caches)."""
    cold, cpu, init, warm, nodes, proven, plans = [], [], [], [], [], 0, []
    ref: list[float] = []
    ref_plans: list[tuple[object, float]] = []
    for case, r in ((case, r) for case in cases for r in range(repeats)):
        world, state = case if r == 0 else (World(case[0].scenario, case[0].durations), case[1])
        start_cpu = time.process_time()
        planner = Planner(world, PlannerConfig(node_budget=budget))
        init.append(time.process_time() - start_cpu)
        start, start_cpu = time.perf_counter(), time.process_time()
        result = planner.plan(state)
        cold.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
        start = time.perf_counter()
        planner.plan(state)
        warm.append(time.perf_counter() - start)
        nodes.append(result.nodes)
        proven += result.success and result.optimal
        plans.append((result.plan.cycles if result.plan else None, result.cost))
        ref_cpu, ref_plan = reference_plan(world, state, budget)  # interleaved: the same load
        ref.append(ref_cpu)
        ref_plans.append(ref_plan)
    return {
        "median_ms": statistics.median(cold) * 1e3,
        "p95_ms": percentile(cold, 95) * 1e3,
        "cpu_ms": statistics.median(cpu) * 1e3,
        "init_ms": statistics.median(init) * 1e3,
        "warm_us": statistics.median(warm) * 1e6,
        "nodes_med": int(statistics.median(nodes)),
        "nodes_max": max(nodes),
        "proven": f"{proven}/{len(cold)}",
        "ref_ms": statistics.median(ref) * 1e3,
        "same": "yes" if same_plans(plans, ref_plans) else "NO",
    }


def workloads(seeds: int) -> list[tuple[str, list[tuple[World, State]]]]:
    """Built-in scenarios from several initial states; one state of each of several
    generated layouts per size (human_only=0.8: most objects need the human or a handover)."""
    out = []
    for name in ("paper2015", "roboergosum"):
        worlds = [World(name) for _ in range(seeds)]
        out.append((name, [(w, w.initial_state(np.random.default_rng(s))) for s, w in enumerate(worlds)]))
    for n in (3, 6, 10, 20):
        for human_only in (0.3, 0.8):
            worlds = [World(f"generated:objects={n},human_only={human_only},seed={s}") for s in range(seeds)]
            out.append(
                (f"N={n} human_only={human_only}", [(w, w.initial_state(np.random.default_rng(0))) for w in worlds])
            )
    return out


def main() -> None:
    """Print the latency table."""
    parser = argparse.ArgumentParser(description="Planner latency against the number of objects.")
    parser.add_argument("--seeds", type=int, default=5, help="initial states or layouts per workload")
    parser.add_argument("--budget", type=int, default=20_000, help="node budget per call")
    parser.add_argument(
        "--repeats", type=int, default=5, help="cold plans of each case, each on a fresh world (medians over all)"
    )
    args = parser.parse_args()
    header = (
        f"{'workload':<24}{'median ms':>10}{'p95 ms':>10}{'cpu ms':>9}{'init ms':>9}{'warm us':>9}"
        f"{'nodes med':>10}{'nodes max':>10}{'proven':>8}{'ref cpu':>9}{'x':>6}{'same':>6}"
    )
    print(header)
    print("-" * len(header))
    for label, cases in workloads(args.seeds):
        row = measure(cases, args.budget, args.repeats)
        print(
            f"{label:<24}{row['median_ms']:>10.2f}{row['p95_ms']:>10.2f}{row['cpu_ms']:>9.2f}{row['init_ms']:>9.2f}{row['warm_us']:>9.1f}"
            f"{row['nodes_med']:>10}{row['nodes_max']:>10}{row['proven']:>8}{row['ref_ms']:>9.2f}"
            f"{float(row['ref_ms']) / float(row['cpu_ms']):>6.2f}{row['same']:>6}",
            flush=True,
        )


if __name__ == "__main__":
    main()
