"""Planner latency: planning time and nodes expanded against the number of objects.

Run: ``python benchmarks/planner_latency.py [--seeds 5] [--budget 20000]``. Prints one
row per workload: median and 95th-percentile cold planning time and the median CPU time
(less sensitive to a loaded machine) of a fresh ``Planner``, the median CPU time of
constructing it (its static tables: not part of the planning time)
(no plan, candidate or bound cached: each case gets its own ``World``, since planners of
one world share their search space's caches), the
warm time (the same query again: a cache hit), nodes expanded, and how many calls
proved the optimum within the node budget. Targets:
paper2015 initial state <= 1 ms median, roboergosum <= 10 ms, 20 objects <= 100 ms with
the optimum proven.

Beside each row, ``ref cpu`` is the same cold plans' median CPU time with the search
space's edges computed as they were before they were compiled into tables
(:class:`ReferenceSpace`: ``successor_feasible`` per edge, the bound's sums by
``math.fsum``), measured in the same run on fresh worlds; ``x`` is the ratio and ``same``
says whether both found the same plans and costs. On a loaded machine read the ratio, not
the milliseconds.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig
from hg_marl.agents.planner.domain import Domain
from hg_marl.agents.planner.space import HumanEdge, RobotEdge, Space
from hg_marl.core import Agent, State, World


class ReferenceSpace(Space):
    """The search space's edges as computed before the transitions were compiled (a reference)."""

    def __init__(self, domain: Domain, weights: CostWeights) -> None:
        super().__init__(domain, weights)
        self._exact.packed = None  # the bound's sums by ``fsum``

    def robot_edges(self, state: State) -> tuple[RobotEdge, ...]:
        out = self._robot_edges.get(state)
        if out is None:
            apply, key_of, base = self.table.successor_feasible, self.key, self.base
            cr = [c for c, _ in self.coefs]
            edges = []
            for ar in self.candidates(state, Agent.ROBOT):
                s1, d_r = apply(state, Agent.ROBOT, ar)
                key = key_of(s1)
                sm = self.cached_sums(s1, key)
                if sm is not None:
                    h = base + max(v + c * d_r for v, c in zip(sm, cr, strict=True))
                    edges.append(RobotEdge(ar, s1, d_r, key, h))
            out = self._robot_edges[state] = tuple(edges)
        return out

    def human_edges(self, state: State) -> tuple[HumanEdge, ...]:
        out = self._human_edges.get(state)
        if out is None:
            apply, key_of, base = self.table.successor_feasible, self.key, self.base
            hand_h, wait_h = self.table.hand[Agent.HUMAN], self.wait[Agent.HUMAN]
            edges = []
            for ah in self.allowed(state):
                s2, d_h = apply(state, Agent.HUMAN, ah)
                key = key_of(s2)
                sm = self.cached_sums(s2, key)
                if sm is not None:
                    take, holding = ah in self.human_takes, hand_h in s2.where
                    edges.append(HumanEdge(ah, s2, d_h, take, ah != wait_h, holding, key, base + max(sm)))
            out = self._human_edges[state] = tuple(edges)
        return out


def reference_cpu(cases: list[tuple[World, State]], budget: int) -> tuple[float, list[tuple[object, float]]]:
    """Median CPU time of cold plans with :class:`ReferenceSpace`, and the plans found."""
    cpu, plans = [], []
    for world, state in cases:
        fresh = World(world.scenario, world.durations)
        planner = Planner(fresh, PlannerConfig(node_budget=budget))
        planner.space = ReferenceSpace(Domain(fresh, planner.human_model), planner.config.weights)
        start_cpu = time.process_time()
        result = planner.plan(state)
        cpu.append(time.process_time() - start_cpu)
        plans.append((result.plan.cycles if result.plan else None, result.cost))
    return statistics.median(cpu) * 1e3, plans


def percentile(values: list[float], q: float) -> float:
    """The q-th percentile (nearest rank)."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, max(0, round(q / 100 * len(ordered) + 0.5) - 1))]


def measure(cases: list[tuple[World, State]], budget: int) -> dict[str, float | int | str]:
    """Cold and warm planning statistics over ``(world, initial state)`` cases."""
    cold, cpu, init, warm, nodes, proven, plans = [], [], [], [], [], 0, []
    for world, state in cases:
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
    ref_ms, ref_plans = reference_cpu(cases, budget)
    return {
        "median_ms": statistics.median(cold) * 1e3,
        "p95_ms": percentile(cold, 95) * 1e3,
        "cpu_ms": statistics.median(cpu) * 1e3,
        "init_ms": statistics.median(init) * 1e3,
        "warm_us": statistics.median(warm) * 1e6,
        "nodes_med": int(statistics.median(nodes)),
        "nodes_max": max(nodes),
        "proven": f"{proven}/{len(cold)}",
        "ref_ms": ref_ms,
        "same": "yes" if plans == ref_plans else "NO",
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
    args = parser.parse_args()
    header = (
        f"{'workload':<24}{'median ms':>10}{'p95 ms':>10}{'cpu ms':>9}{'init ms':>9}{'warm us':>9}"
        f"{'nodes med':>10}{'nodes max':>10}{'proven':>8}{'ref cpu':>9}{'x':>6}{'same':>6}"
    )
    print(header)
    print("-" * len(header))
    for label, cases in workloads(args.seeds):
        row = measure(cases, args.budget)
        print(
            f"{label:<24}{row['median_ms']:>10.2f}{row['p95_ms']:>10.2f}{row['cpu_ms']:>9.2f}{row['init_ms']:>9.2f}{row['warm_us']:>9.1f}"
            f"{row['nodes_med']:>10}{row['nodes_max']:>10}{row['proven']:>8}{row['ref_ms']:>9.2f}"
            f"{float(row['ref_ms']) / float(row['cpu_ms']):>6.2f}{row['same']:>6}",
            flush=True,
        )


if __name__ == "__main__":
    main()
