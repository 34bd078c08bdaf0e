"""Partners that switch between two population members at a period, and what each robot loses.

Why: a partner-aware robot earns its keep when its partner is not the one it assumed;
the held-out members test a partner who differs for the whole run, this sweep one who
changes. For a pair of members (A, B) and a period P the partner plays A for P simulated
seconds, then B for P, then A again, to the end of the run (the registry's ``switching``
human with thresholds P, 2P, ...). Periods run from seconds (the partner changes within
a task) to many minutes (a change the robot has time to notice and follow).

Per (pair, period, robot), over seeds, each with a percentile-bootstrap 95% CI:

- **tasks** solved in the run;
- **regret**: the *per-phase best response*'s expected tasks minus the robot's. The
  reference plays, in each phase, the exact best response to that phase's member (the
  oracle's optimal rate, :func:`~hg_marl.agents.oracle.oracle_rate`), so it expects
  ``sum_k rate(member_k) * length_k / 3600`` tasks. It knows the schedule and ignores
  the cost of a change, so it is a reference, not a bound: a robot may beat it by a
  fraction of a task around the changes;
- **difference** from the fixed-model counterpart (``baseline``, default the plain
  planner), paired by seed: tasks minus the baseline's tasks on the same seed. A robot
  *loses* on a cell when the whole CI of the difference lies below 0;
- **recovery**: after each change whose phase lasts at least ``min_phase`` seconds, the
  seconds until the robot keeps the new member's best-response pace (within one task,
  :func:`~hg_marl.training.regret.time_to_recover`), averaged over the changes of a run.

Runs go through the content-addressed store (``OUT/store``): an interrupted sweep
resumes, and a rerun reuses every finished run.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from hg_marl.core.errors import ConfigError, check_finite, check_int
from hg_marl.core.spec import AgentSpec
from hg_marl.training.regret import bootstrap_ci, time_to_recover
from hg_marl.training.sweep import Job, load_log, run_sweep

MAX_PHASES = 10_000
"""Most phases a run may have (duration / period): a switching human holds one human per phase."""


@dataclass(frozen=True)
class SwitchingConfig:
    """What the sweep runs (the CLI checks each field and names its option)."""

    scenario: str
    """Scenario name or TOML path."""
    pairs: tuple[tuple[str, str], ...]
    """The member names (A, B) of each switching partner."""
    periods: tuple[float, ...]
    """Simulated seconds each member plays before the other takes over."""
    robots: tuple[str, ...]
    """Robot specs (``planner``, ``belief:population=FILE``)."""
    baseline: str = "planner"
    """The fixed-model counterpart the others are compared with, paired by seed (one of ``robots``)."""
    seeds: int = 5
    """Seeds per cell."""
    duration: float = 1800.0
    """Simulated seconds per run."""
    min_phase: float = 120.0
    """Recovery is measured after changes into phases at least this long."""
    members: tuple[tuple[str, str], ...] = ()
    """(name, spec) of every member the pairs name."""
    _robot_specs: dict[str, AgentSpec] = field(default_factory=dict, init=False, repr=False, compare=False)
    """Each robot's spec once parsed (see :meth:`robot_spec`)."""

    def spec(self, name: str) -> str:
        """The spec of member ``name``."""
        return dict(self.members)[name]

    def robot_spec(self, robot: str) -> AgentSpec:
        """``--robots`` item ``robot`` parsed and typed, once per config (as a study file types
        them, so the same robot keys the same runs); the check, the jobs and the table share it."""
        spec = self._robot_specs.get(robot)
        if spec is None:
            spec = self._robot_specs[robot] = AgentSpec.parse(robot, "--robots", f"--robots {robot}")
        return spec


def check_config(config: SwitchingConfig) -> None:
    """Refuse what would run wrong or without end, naming the option (one line each)."""
    if not config.pairs:
        raise ConfigError("--pairs: name at least one pair A/B of members")
    if not config.periods:
        raise ConfigError("--periods: name at least one period (simulated seconds)")
    for p in config.periods:
        check_finite(p, "--periods", positive=True)
        if config.duration / p > MAX_PHASES:
            raise ConfigError(
                f"--periods {p:g}: {config.duration:g} s / {p:g} s is over {MAX_PHASES} phases; take a longer period"
            )
    check_int(config.seeds, "--seeds", minimum=1)
    check_finite(config.min_phase, "--min-phase", positive=True)
    if config.baseline not in config.robots:
        raise ConfigError(f"--baseline {config.baseline}: not one of --robots ({', '.join(config.robots)})")
    if len(set(config.robots)) != len(config.robots):
        raise ConfigError("--robots: a robot is named twice")
    from hg_marl.agents.robots import make_robot
    from hg_marl.core.errors import HgMarlError

    for robot in config.robots:  # built once here, so a bad spec is refused before any run
        try:
            job = _job(config, config.pairs[0], config.periods[0], robot, config.robot_spec(robot), 0)
            make_robot(job.robot, **job.robot_params)
        except (HgMarlError, ValueError, TypeError) as exc:
            raise ConfigError(f"--robots {robot}: {exc}") from None


def schedule(names: tuple[str, str], period: float, duration: float) -> tuple[list[str], list[float]]:
    """The members in play and the thresholds at which the next takes over: A, B, A, ... every ``period``."""
    changes = math.ceil(duration / period) - 1
    at = [period * (k + 1) for k in range(changes)]
    return [names[k % 2] for k in range(changes + 1)], at


def _job(config: SwitchingConfig, pair: tuple[str, str], period: float, robot: str, spec: AgentSpec, seed: int) -> Job:
    names, at = schedule(pair, period, config.duration)
    return Job(
        label=f"switch_{pair[0]}_{pair[1]}_{period:g}_{robot}",
        robot=spec.name,
        robot_params=dict(spec.params),
        seed=seed,
        scenario=config.scenario,
        duration=config.duration,
        human="switching",
        human_params={"humans": [config.spec(n) for n in names], "at": at, "by": "time"},
    )


def switching_jobs(config: SwitchingConfig) -> list[Job]:
    """One job per (pair, period, robot, seed); each robot's spec parsed once."""
    return [
        _job(config, pair, period, robot, config.robot_spec(robot), seed)
        for pair in config.pairs
        for period in config.periods
        for robot in config.robots
        for seed in range(config.seeds)
    ]


def reference_tasks(rates: tuple[float, float], period: float, duration: float) -> float:
    """The per-phase best response's expected tasks: each phase at its member's optimal rate (tasks/h)."""
    names, at = schedule(("a", "b"), period, duration)
    bounds = [0.0, *at, duration]
    return sum(
        (rates[0] if name == "a" else rates[1]) * (end - start) / 3600.0
        for name, start, end in zip(names, bounds[:-1], bounds[1:], strict=True)
    )


def mean_recovery(
    log: pd.DataFrame, rates: tuple[float, float], period: float, duration: float, min_phase: float
) -> float | None:
    """Mean seconds to keep the new member's best-response pace after each change into a long enough phase."""
    names, at = schedule(("a", "b"), period, duration)
    bounds = [*at, duration]
    times: list[float] = []
    for k, start in enumerate(at):
        end = bounds[k + 1]
        if end - start < min_phase:
            continue
        phase = log[log["time"] <= end]
        rate = rates[0] if names[k + 1] == "a" else rates[1]
        tau = time_to_recover(phase, start, rate, min_tail=min_phase / 2, end=end)
        if tau is not None:
            times.append(tau)
    return float(np.mean(times)) if times else None


def _ci(values: Sequence[float]) -> dict[str, float | None]:
    if not values:
        return {"mean": None, "low": None, "high": None}
    mean, low, high = bootstrap_ci(list(values))
    return {"mean": mean, "low": low, "high": high}


def run_switching(
    config: SwitchingConfig,
    out: Path,
    workers: int = 1,
    on_done: Callable[[Job, dict[str, Any]], None] | None = None,
) -> dict[str, Any]:
    """Run (or resume) the sweep in ``out``; return its summary (also written as ``switching.json``)."""
    from hg_marl.agents.oracle import oracle_rate

    check_config(config)
    jobs = switching_jobs(config)
    run_sweep(jobs, out, workers=workers, on_done=on_done)
    rate = {
        name: oracle_rate(config.scenario, config.spec(name)).rate_per_hour for pair in config.pairs for name in pair
    }
    cells: list[dict[str, Any]] = []
    for pair in config.pairs:
        rates = (rate[pair[0]], rate[pair[1]])
        for period in config.periods:
            reference = reference_tasks(rates, period, config.duration)
            tasks: dict[str, list[float]] = {}
            recovery: dict[str, list[float]] = {}
            for robot in config.robots:
                spec = config.robot_spec(robot)
                logs = [load_log(_job(config, pair, period, robot, spec, s), out) for s in range(config.seeds)]
                tasks[robot] = [float(log["reward"].sum()) for log in logs]
                rec = [mean_recovery(log, rates, period, config.duration, config.min_phase) for log in logs]
                recovery[robot] = [r for r in rec if r is not None]
            for robot in config.robots:
                diff = [a - b for a, b in zip(tasks[robot], tasks[config.baseline], strict=True)]
                d = _ci(diff) if robot != config.baseline else {"mean": 0.0, "low": 0.0, "high": 0.0}
                cells.append(
                    {
                        "pair": f"{pair[0]}/{pair[1]}",
                        "period": period,
                        "robot": robot,
                        "reference_tasks": reference,
                        "tasks": _ci(tasks[robot]),
                        "regret": _ci([reference - t for t in tasks[robot]]),
                        "difference": d,
                        "loses": d["high"] is not None and d["high"] < 0.0,
                        "recovery": _ci(recovery[robot]),
                        "recovered_runs": len(recovery[robot]),
                    }
                )
    return {
        "scenario": config.scenario,
        "seeds": config.seeds,
        "duration": config.duration,
        "baseline": config.baseline,
        "oracle_rate_per_hour": rate,
        "cells": cells,
    }


def _short(label: str, width: int) -> str:
    """``label`` within ``width`` characters, keeping its start and its end (where specs differ)."""
    if len(label) <= width:
        return label
    keep = width - 3
    return label[: keep // 2] + "..." + label[len(label) - (keep - keep // 2) :]


def switching_table(summary: dict[str, Any]) -> str:
    """The printed table: one row per (pair, period, robot), mean [95% CI]."""

    def fmt(ci: dict[str, float | None], digits: int = 1) -> str:
        if ci["mean"] is None:
            return "-"
        return f"{ci['mean']:.{digits}f} [{ci['low']:.{digits}f}, {ci['high']:.{digits}f}]"

    head = (
        f"{'pair':<28}{'period s':>9}  {'robot':<46}{'tasks':>23}{'regret':>23}"
        f"{_short('vs ' + summary['baseline'], 22):>23}{'recover s':>20}"
    )
    lines = [head, "-" * len(head)]
    for c in summary["cells"]:
        mark = "  LOSES" if c["loses"] else ""
        lines.append(
            f"{c['pair']:<28}{c['period']:>9g}  {_short(c['robot'], 45):<46}{fmt(c['tasks']):>23}{fmt(c['regret']):>23}"
            f"{fmt(c['difference']):>23}{fmt(c['recovery'], 0):>20}{mark}"
        )
    return "\n".join(lines)
