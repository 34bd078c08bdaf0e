"""Adaptation: the human switches from cooperative to another policy mid-run.

For each robot and each new human, runs of :data:`DURATION` simulated seconds in which
the human is ``cooperative`` until :data:`SWITCH_AT`, then ``no_handover`` or ``lazy``.
Measured against the oracle's optimal rate for the new human (value iteration on the
exact model, :mod:`hg_marl.agents.oracle`):

- *time to regain*: simulated seconds after the switch until the robot's reward rate,
  over a sliding window of :data:`WINDOW` seconds lying wholly after the switch, first
  reaches 90% of the new oracle rate (``None`` when it never does within the run);
- *tasks lost*: tasks the oracle robot would solve after the switch minus those solved.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from hg_marl.training.paper import FURTHER_CRITERIA, PAPER_HABIT
from hg_marl.training.sweep import Job, load_log, run_sweep

DURATION = 2400.0
"""Simulated seconds per adaptation run."""
SWITCH_AT = 900.0
"""When the human changes."""
WINDOW = 300.0
"""Sliding window (simulated seconds) of the reward-rate estimate."""
NEW_HUMANS = ("no_handover", "lazy")
"""Humans switched to."""
ROBOTS: dict[str, tuple[str, dict[str, Any]]] = {
    "planner": ("planner", {}),
    "habit": ("habit", {}),
    "random": ("hybrid", {"criterion": "random", "q_config": dict(PAPER_HABIT)}),
    **{c: ("hybrid", {"criterion": c}) for c in FURTHER_CRITERIA},
}
"""Robots compared."""


@dataclass(frozen=True)
class AdaptationConfig:
    """The adaptation experiment's protocol (defaults: the module constants)."""

    scenario: str = "paper2015"
    """Scenario."""
    seeds: int = 3
    """Seeds per (robot, new human)."""
    duration: float = DURATION
    """Simulated seconds per run."""
    switch_at: float = SWITCH_AT
    """When the human changes."""
    window: float = WINDOW
    """Sliding window of the rate estimate."""
    new_humans: tuple[str, ...] = NEW_HUMANS
    """Humans switched to."""
    robots: tuple[str, ...] = tuple(ROBOTS)
    """Labels of :data:`ROBOTS` to compare."""


def adaptation_jobs(config: AdaptationConfig) -> list[Job]:
    """One job per (new human, robot, seed)."""
    return [
        Job(
            label=f"adapt_{new}_{label}",
            robot=ROBOTS[label][0],
            robot_params=ROBOTS[label][1],
            seed=seed,
            scenario=config.scenario,
            duration=config.duration,
            human="switching",
            human_params={"humans": ["cooperative", new], "at": [config.switch_at], "by": "time"},
        )
        for new in config.new_humans
        for label in config.robots
        for seed in range(config.seeds)
    ]


def rate_curve(log: pd.DataFrame, grid: np.ndarray, window: float = WINDOW) -> np.ndarray:
    """Tasks per hour over the window ending at each grid time."""
    done = np.sort(log.loc[log["reward"] > 0, "time"].to_numpy())
    counts = np.searchsorted(done, grid, side="right") - np.searchsorted(done, grid - window, side="right")
    return counts * 3600.0 / window


def time_to_regain(
    log: pd.DataFrame, target_rate: float, switch_at: float = SWITCH_AT, window: float = WINDOW
) -> float | None:
    """Seconds after the switch until the windowed rate first reaches ``target_rate``."""
    end = float(log["time"].iloc[-1]) if len(log) else switch_at
    grid = np.arange(switch_at + window, end + 1e-9, 5.0)
    if len(grid) == 0:
        return None
    hit = np.flatnonzero(rate_curve(log, grid, window) >= target_rate - 1e-9)
    return float(grid[hit[0]] - switch_at) if len(hit) else None


def run_adaptation(
    out: Path,
    config: AdaptationConfig | None = None,
    workers: int = 1,
    on_done: Callable[[Job, dict[str, Any]], None] | None = None,
) -> tuple[dict[str, Any], dict[str, Path]]:
    """Run (or resume) the adaptation sweep; return its summary and figure paths."""
    from hg_marl.agents.oracle import oracle_rate
    from hg_marl.training import plots

    c = config or AdaptationConfig()
    jobs = adaptation_jobs(c)
    run_sweep(jobs, out, workers=workers, on_done=on_done)
    oracle = {name: oracle_rate(c.scenario, name).rate_per_hour for name in ("cooperative", *c.new_humans)}
    summary: dict[str, Any] = {
        "switch_at": c.switch_at,
        "duration": c.duration,
        "window": c.window,
        "seeds": c.seeds,
        "oracle_rate_per_hour": oracle,
        "results": {},
    }
    figures: dict[str, Path] = {}
    grid = np.arange(c.window, c.duration + 1e-9, 10.0)
    after_hours = (c.duration - c.switch_at) / 3600.0
    for new in c.new_humans:
        target = 0.9 * oracle[new]
        curves: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        rows: dict[str, Any] = {}
        for label in c.robots:
            logs = [load_log(j, out) for j in jobs if j.label == f"adapt_{new}_{label}"]
            regain = [time_to_regain(log, target, c.switch_at, c.window) for log in logs]
            after = [float(((log["reward"] > 0) & (log["time"] > c.switch_at)).sum()) for log in logs]
            reached = [r for r in regain if r is not None]
            rows[label] = {
                "time_to_regain_90_mean": float(np.mean(reached)) if reached else None,
                "recovered_runs": len(reached),
                "runs": len(logs),
                "tasks_after_switch_mean": float(np.mean(after)),
                "tasks_lost_mean": float(oracle[new] * after_hours - np.mean(after)),
            }
            curves[label] = (grid, np.mean([rate_curve(log, grid, c.window) for log in logs], axis=0))
        summary["results"][new] = rows
        figures[f"adaptation_{new}"] = plots.adaptation(
            curves,
            c.switch_at,
            (oracle["cooperative"], oracle[new]),
            f"Adaptation: cooperative -> {new} (mean of {c.seeds} seeds)",
            out / f"adaptation_{new}.png",
        )
    return summary, figures


def adaptation_table(summary: dict[str, Any]) -> str:
    """Printed table of the adaptation results."""
    lines = [
        f"adaptation: human switches from cooperative at {summary['switch_at']:.0f} s "
        f"(oracle tasks/h: {', '.join(f'{k} {v:.1f}' for k, v in summary['oracle_rate_per_hour'].items())})"
    ]
    head = f"{'new human':<13}{'robot':<18}{'regain 90% (s)':>16}{'recovered':>11}{'tasks lost':>12}"
    lines += [head, "-" * len(head)]
    for new, rows in summary["results"].items():
        for label, row in rows.items():
            regain = "never" if row["time_to_regain_90_mean"] is None else f"{row['time_to_regain_90_mean']:.0f}"
            lines.append(
                f"{new:<13}{label:<18}{regain:>16}{row['recovered_runs']:>6}/{row['runs']:<4}{row['tasks_lost_mean']:>12.1f}"
            )
    return "\n".join(lines)
