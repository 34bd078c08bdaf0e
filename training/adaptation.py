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

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

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
    "random": ("hybrid", {"criterion": "random"}),
    "entropy": ("hybrid", {"criterion": "entropy"}),
    "entropy_and_cost": ("hybrid", {"criterion": "entropy_and_cost"}),
    "vpi": ("hybrid", {"criterion": "vpi"}),
    "learning_state": ("hybrid", {"criterion": "learning_state"}),
}
"""Robots compared."""


def adaptation_jobs(scenario: str, seeds: int) -> list[Job]:
    """One job per (new human, robot, seed)."""
    return [
        Job(
            label=f"adapt_{new}_{label}",
            robot=robot,
            robot_params=params,
            seed=seed,
            scenario=scenario,
            duration=DURATION,
            human="switching",
            human_params={"humans": ["cooperative", new], "at": [SWITCH_AT], "by": "time"},
        )
        for new in NEW_HUMANS
        for label, (robot, params) in ROBOTS.items()
        for seed in range(seeds)
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
    out: Path, scenario: str = "paper2015", seeds: int = 5, workers: int = 1
) -> tuple[dict[str, Any], dict[str, Path]]:
    """Run (or resume) the adaptation sweep; return its summary and figure paths."""
    from hg_marl.agents.oracle import oracle_rate
    from hg_marl.training import plots

    jobs = adaptation_jobs(scenario, seeds)
    run_sweep(jobs, out, workers=workers)
    oracle = {name: oracle_rate(scenario, name).rate_per_hour for name in ("cooperative", *NEW_HUMANS)}
    summary: dict[str, Any] = {
        "switch_at": SWITCH_AT,
        "duration": DURATION,
        "window": WINDOW,
        "seeds": seeds,
        "oracle_rate_per_hour": oracle,
        "results": {},
    }
    figures: dict[str, Path] = {}
    grid = np.arange(WINDOW, DURATION + 1e-9, 10.0)
    for new in NEW_HUMANS:
        target = 0.9 * oracle[new]
        after_hours = (DURATION - SWITCH_AT) / 3600.0
        curves: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        rows: dict[str, Any] = {}
        for label in ROBOTS:
            logs = [load_log(j, out) for j in jobs if j.label == f"adapt_{new}_{label}"]
            regain = [time_to_regain(log, target) for log in logs]
            after = [float(log.loc[(log["reward"] > 0) & (log["time"] > SWITCH_AT)].shape[0]) for log in logs]
            reached = [r for r in regain if r is not None]
            rows[label] = {
                "time_to_regain_90_mean": float(np.mean(reached)) if reached else None,
                "recovered_runs": len(reached),
                "runs": len(logs),
                "tasks_after_switch_mean": float(np.mean(after)),
                "tasks_lost_mean": float(oracle[new] * after_hours - np.mean(after)),
            }
            curves[label] = (grid, np.mean([rate_curve(log, grid) for log in logs], axis=0))
        summary["results"][new] = rows
        figures[f"adaptation_{new}"] = plots.adaptation(
            curves,
            SWITCH_AT,
            (oracle["cooperative"], oracle[new]),
            f"Adaptation: cooperative -> {new} (mean of {seeds} seeds)",
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
