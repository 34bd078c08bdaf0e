"""Model building on arrays beside the Python enumeration it replaced, measured in the same run.

Run: ``python benchmarks/model_build.py [--member m01] [--skip-rates] [--members] [--headroom [--jobs N]]
[--eight] [--robot] [--scenario NAME --population FILE]``. ``--scenario`` and ``--population``
(default ``roboergosum`` and its bundled population, the goals' table) point 1., 2., 3. and 5.
at another table: a smaller one checks that every part runs (the test suite does so on
``paper2015``); the goals are read on the default.

1. **Builder rate** on ``roboergosum`` against a population member (a stationary human;
   no symmetry reduction: the full model). Each builder runs twice: cold (the partner
   answers live, one Python call per distinct mid-cycle state, as both builders must)
   and warm (the partner's answers already tabulated: the array builder reuses its
   ``AnswerTable``; the Python enumeration gets a human answering from a dict of the
   first run's answers), which isolates what the builder itself costs. States per second
   of each, and the ratio; the array builder also with the partner on arrays
   (``agents/models/partners.py``). Times are wall and CPU seconds; the rates are per CPU
   second (one core), which a loaded machine inflates less than wall time. Goal: >= 1M states/s.
2. ``--members``: every ``roboergosum`` member's oracle (wall seconds, states, rate). Goal <= 5 s each.
3. ``--headroom``: ``hg-marl headroom --scenario roboergosum --population populations/roboergosum.toml``
   in-process, timed, with ``--max-seconds 600``: in one process, then with ``--jobs`` forked
   workers (default: one per CPU), and whether both gave the same matrix. Goal <= 60 s.
4. ``--eight``: the oracle of an 8-object table against ``random``, a generated one
   (``generated:objects=8,bins=2``) and a hand-written one (``benchmarks/eight_objects.toml``:
   two colours of tape, a bin for each). Goal <= 60 s and 4 GB.
5. ``--robot``: the compiled planner robot's states on ``roboergosum`` (the builder) and
   the cost of a cold plan on a sample of them (the table needs one per state).
"""

from __future__ import annotations

import argparse
import os
import resource
import time
from pathlib import Path
from typing import Any

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.models import AnswerTable, Budget, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.python_model import PythonModel
from hg_marl.agents.oracle import OverBudget, oracle_rate
from hg_marl.core import Agent, State, World

SCENARIO = "roboergosum"
POPULATION = "populations/roboergosum.toml"


class Tabulated:
    """A human answering from a dict filled by a live one (the warm run of the Python enumeration)."""

    def __init__(self, live: Any) -> None:
        self.live, self.memo = live, {}
        self.uses_robot_action = bool(getattr(live, "uses_robot_action", False))
        self.name = getattr(live, "name", "human")

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Any:
        key = (state, robot_action)
        found = self.memo.get(key)
        if found is None:
            found = self.memo[key] = self.live.distribution(world, state, robot_action)
        return found


def python_build(world: World, human: Any) -> int:
    """The Python enumeration (``agents/oracle.py`` ``PythonModel``) of the full model; its state count."""
    model = PythonModel(world, human, True, 10**7)
    layouts = layout_distribution(world)
    wait, wait_index = world.durations.wait, world.n_actions(Agent.ROBOT) - 1
    regen = [nxt for table, _ in layouts for nxt, _, _ in model.replies(table, wait, wait_index)]
    model.build([s for s, _ in layouts] + regen)
    return len(model.states)


def builder_rates(member: str, scenario: str = SCENARIO, population: str = POPULATION) -> None:
    spec = {m.name: m.spec for m in load_population(population).members()}[member]
    world = World(scenario)
    layouts = layout_distribution(world)
    print(f"{scenario} against {member} ({spec}), full model, one core:")
    tab = Tabulated(stationary_human(spec, world))
    old = new = 0.0
    for run in ("cold", "warm"):
        start, cpu = time.perf_counter(), time.process_time()
        n = python_build(world, tab)
        old = time.process_time() - cpu
        report("python enumeration", run, n, time.perf_counter() - start, old)
    for live in (True, False):
        answers = AnswerTable(world, stationary_human(spec, world), StatePacker(world), arrays=not live)
        for run in ("cold", "warm"):
            start, cpu = time.perf_counter(), time.process_time()
            model = build_model(world, answers, layouts)
            new = time.process_time() - cpu
            report(
                f"array builder, {'live' if live else 'array'} partner", run, model.n, time.perf_counter() - start, new
            )
    print(f"  warm ratio (array / python, CPU): {old / new:.1f}x; goal >= 1,000,000 states/s")


def report(what: str, run: str, n: int, wall: float, cpu: float) -> None:
    """One line: states, wall and CPU seconds, states per CPU second."""
    print(f"  {what:<32} {run}: {n:>9,} states, {wall:7.2f} s wall, {cpu:7.2f} s CPU = {n / cpu:>11,.0f} states/s")


def members(scenario: str = SCENARIO, population: str = POPULATION) -> None:
    print(f"every {scenario} member's oracle (goal <= 5 s each):")
    for m in load_population(population).members():
        start, cpu = time.perf_counter(), time.process_time()
        try:
            r = oracle_rate(scenario, m.spec, max_seconds=600)
            what = f"{r.rate_per_hour:8.3f} tasks/h, {r.n_states:>8,} states, {r.iterations} sweeps"
        except OverBudget as exc:
            what = f"refused: {exc}"
        print(f"  {m.name}: {time.perf_counter() - start:7.2f} s wall, {time.process_time() - cpu:6.2f} s CPU  {what}")


def headroom_time(jobs: int, scenario: str = SCENARIO, population: str = POPULATION) -> None:
    """The headroom in one process and, beside it in the same run, with ``jobs`` forked workers (same matrix)."""
    from hg_marl.agents.headroom import headroom

    pop = load_population(population)
    matrices = []
    for n in dict.fromkeys((1, jobs)):
        start, cpu = time.perf_counter(), time.process_time()
        try:
            res = headroom(scenario, [(m.name, m.spec) for m in pop.members()], max_seconds=600, jobs=n)
            what = f"{res.n_states:,} states, headroom {res.headroom:.3f}"
            matrices.append(res.rates)
        except OverBudget as exc:
            what = f"refused: {exc}"
        wall, spent = time.perf_counter() - start, time.process_time() - cpu
        print(
            f"headroom {scenario}, whole population, jobs={n}: {wall:.1f} s wall, {spent:.1f} s CPU in the parent "
            f"({what}); goal <= 60 s"
        )
    if len(matrices) == 2:
        print(f"  the same matrix with {jobs} jobs as with one: {bool((matrices[0] == matrices[1]).all())}")


EIGHT = ("generated:objects=8,bins=2", str(Path(__file__).with_name("eight_objects.toml")))
"""The 8-object tables of 4.: a generated one and a hand-written one (two colours of tape, a bin for each)."""


def eight() -> None:
    for scenario in EIGHT:
        start, cpu = time.perf_counter(), time.process_time()
        try:
            r = oracle_rate(scenario, "random", budget=Budget(600, None, 10**7))
            what = f"{r.rate_per_hour:.3f} tasks/h, {r.n_states:,} states"
        except OverBudget as exc:
            what = f"refused: {exc}"
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20
        print(
            f"8-object oracle ({Path(scenario).name} vs random): {time.perf_counter() - start:.1f} s wall, "
            f"{time.process_time() - cpu:.1f} s CPU, "
            f"peak {peak:.2f} GB so far in this process ({what}); goal <= 60 s, 4 GB"
        )


def robot(sample: int = 300, scenario: str = SCENARIO) -> None:
    """The compiled planner robot on a scenario: its states by the builder, and the cold plans' cost on a sample."""
    import numpy as np

    from hg_marl.agents.compiled_robot import MAX_STATES, compile_robot, planner_action, robot_states

    world = World(scenario)
    cpu = time.process_time()
    keys = robot_states(world, max_states=10**7)
    sample = min(sample, len(keys))
    print(f"compiled robot, {scenario}: {len(keys):,} robot-turn states in {time.process_time() - cpu:.1f} s CPU")
    b, _ = StatePacker(world).unpack(keys[np.random.default_rng(0).choice(len(keys), sample, replace=False)])
    cpu = time.process_time()
    for i in range(sample):
        planner_action(world, b.state(i))
    each = (time.process_time() - cpu) / sample
    print(
        f"  one cold plan: {each * 1e3:.2f} ms CPU (mean of {sample}); all states: {each * len(keys) / 60:.0f} min CPU"
    )
    cpu = time.process_time()
    compiled = compile_robot(world, cache=None)
    print(
        f"  compiled with the default budget ({MAX_STATES:,} cold plans: one per state up to relabelling): "
        f"{len(compiled):,} states in {time.process_time() - cpu:.0f} s CPU"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--member", default="m01", help="population member of the builder-rate run")
    parser.add_argument("--skip-rates", action="store_true", help="skip the builder-rate runs (1. above)")
    parser.add_argument("--members", action="store_true", help="time every member's oracle")
    parser.add_argument("--headroom", action="store_true", help="time the population's headroom matrix")
    parser.add_argument(
        "--jobs", type=int, default=os.cpu_count() or 1, help="workers of the headroom's second run (default: CPUs)"
    )
    parser.add_argument("--eight", action="store_true", help="time an 8-object table's oracle")
    parser.add_argument("--robot", action="store_true", help="the compiled planner robot's states and plan cost")
    parser.add_argument("--scenario", default=SCENARIO, help="the table of 1., 2., 3. and 5. (default: %(default)s)")
    parser.add_argument("--population", default=POPULATION, help="its population (default: %(default)s)")
    args = parser.parse_args()
    if not args.skip_rates:
        builder_rates(args.member, args.scenario, args.population)
    if args.members:
        members(args.scenario, args.population)
    if args.eight:
        eight()
    if args.headroom:
        headroom_time(args.jobs, args.scenario, args.population)
    if args.robot:
        robot(scenario=args.scenario)


if __name__ == "__main__":
    main()
