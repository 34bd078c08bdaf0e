"""Adaptation: the human changes behaviour mid-run, without notice.

Each *switch* is a sequence of humans (registry specs) and the times they take over;
the robot is measured from the last change to the end of the run, against the oracle's
optimal rate for the human it then faces (value iteration on the exact model,
:mod:`hg_marl.agents.oracle`), with the metrics of :mod:`hg_marl.training.regret`:

- *tasks lost*: cumulative regret against the oracle at the end of the run;
- *time to recover*: seconds after the change until the robot keeps the oracle's pace
  (within one task), read on the per-decision log.

Each is reported as a mean over seeds with a percentile-bootstrap 95% CI.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from hg_marl.training.paper import FURTHER_CRITERIA, PAPER_HABIT
from hg_marl.training.regret import bootstrap_ci, tasks_lost, time_to_recover
from hg_marl.training.sweep import Job, load_log, run_sweep

DURATION = 1500.0
"""Simulated seconds per adaptation run."""
SWITCH_AT = 600.0
"""When the human first changes."""
WINDOW = 300.0
"""Trailing window (simulated seconds) of the plotted reward rates (not used by the metrics)."""


@dataclass(frozen=True)
class Switch:
    """Who the human is, and from when: ``humans[k]`` acts from ``at[k - 1]`` on."""

    humans: tuple[str, ...]
    at: tuple[float, ...]

    @property
    def last(self) -> float:
        """The last change: the metrics start here."""
        return self.at[-1]

    @property
    def final(self) -> str:
        """The human faced after the last change."""
        return self.humans[-1]


SWITCHES: dict[str, Switch] = {
    "lazy": Switch(("cooperative", "lazy"), (SWITCH_AT,)),
    "no_handover": Switch(("cooperative", "no_handover"), (SWITCH_AT,)),
    "noisy": Switch(("cooperative", "noisy"), (SWITCH_AT,)),
    "adversarial_and_back": Switch(("cooperative", "adversarial", "cooperative"), (SWITCH_AT, SWITCH_AT + 300.0)),
}
"""The switch types (label -> switch); ``adversarial_and_back`` is measured after the return."""

ROBOTS: dict[str, tuple[str, dict[str, Any]]] = {
    "planner": ("planner", {}),
    "planner_partner_aware": ("planner", {"partner_aware": True}),
    "habit": ("habit", {"q_config": dict(PAPER_HABIT)}),
    "random": ("hybrid", {"criterion": "random", "q_config": dict(PAPER_HABIT), "share_objects": False}),
    **{c: ("hybrid", {"criterion": c}) for c in FURTHER_CRITERIA if c != "entropy"},
    "hybrid_partner_aware": ("hybrid", {"partner_aware": True}),
}
"""Robots compared (hybrids with their default, best-measured settings unless marked)."""


@dataclass(frozen=True)
class AdaptationConfig:
    """The adaptation experiment's protocol (defaults: the module constants)."""

    scenario: str = "paper2015"
    """Scenario."""
    seeds: int = 10
    """Seeds per (robot, switch)."""
    duration: float = DURATION
    """Simulated seconds per run."""
    switches: tuple[str, ...] = tuple(SWITCHES)
    """Labels of :data:`SWITCHES` to run."""
    robots: tuple[str, ...] = tuple(ROBOTS)
    """Labels of :data:`ROBOTS` to compare."""
    window: float = WINDOW
    """Trailing window of the plotted rates."""
    custom: dict[str, Switch] = field(default_factory=dict)
    """Extra switches (label -> :class:`Switch`), e.g. shorter ones for tests."""

    def switch(self, label: str) -> Switch:
        """The switch called ``label``."""
        return self.custom.get(label) or SWITCHES[label]


def adaptation_jobs(config: AdaptationConfig) -> list[Job]:
    """One job per (switch, robot, seed)."""
    out = []
    for label in config.switches:
        sw = config.switch(label)
        for robot in config.robots:
            for seed in range(config.seeds):
                out.append(
                    Job(
                        label=f"adapt_{label}_{robot}",
                        robot=ROBOTS[robot][0],
                        robot_params=ROBOTS[robot][1],
                        seed=seed,
                        scenario=config.scenario,
                        duration=config.duration,
                        human="switching",
                        human_params={"humans": list(sw.humans), "at": list(sw.at), "by": "time"},
                    )
                )
    return out


def rate_curve(log: pd.DataFrame, grid: np.ndarray, window: float = WINDOW) -> np.ndarray:
    """Tasks per hour over the trailing window ``(t - window, t]`` at each grid time.

    The tasks solved by time t are counted with the count interpolated linearly between
    completions (a task counts as it is being done, from the previous completion on), so
    the rate is continuous in t. Counting whole tasks instead made every curve a
    saw-tooth: each completion entering or leaving the window moves it by 3600 / window
    tasks/h (12 for 300 s), the size of the differences the figures compare. At
    completion times the two counts agree; after the last completion the count stays.
    """
    done = np.sort(log.loc[log["reward"] > 0, "time"].to_numpy(dtype=float))
    times, counts = np.unique(done, return_counts=True)
    xs = np.concatenate([[0.0], times])
    ys = np.concatenate([[0.0], np.cumsum(counts)]).astype(float)
    grid = np.asarray(grid, dtype=float)
    solved = np.interp(grid, xs, ys) - np.interp(grid - window, xs, ys, left=0.0)
    return solved * 3600.0 / window


def _ci(values: list[float]) -> dict[str, float | None]:
    if not values:
        return {"mean": None, "low": None, "high": None}
    mean, low, high = bootstrap_ci(values)
    return {"mean": mean, "low": low, "high": high}


def summarise_switch(logs: list[pd.DataFrame], sw: Switch, oracle_rate: float, duration: float) -> dict[str, Any]:
    """Regret and recovery of one robot on one switch, over its seeds."""
    lost = [tasks_lost(log, sw.last, oracle_rate, end=duration) for log in logs]
    recover = [time_to_recover(log, sw.last, oracle_rate, end=duration) for log in logs]
    reached = [r for r in recover if r is not None]
    return {
        "tasks_lost": _ci(lost),
        "time_to_recover": _ci(reached),
        "recovered_runs": len(reached),
        "runs": len(logs),
    }


def run_adaptation(
    out: Path,
    config: AdaptationConfig | None = None,
    workers: int = 1,
    on_done: Callable[[Job, dict[str, Any]], None] | None = None,
    on_figure: Callable[[None, Path], None] | None = None,
) -> tuple[dict[str, Any], dict[str, Path]]:
    """Run (or resume) the adaptation sweep; return its summary and figure paths.

    ``on_figure(None, path)`` is called after each figure is written (a progress bar's update).
    """
    from hg_marl.agents.oracle import oracle_rate
    from hg_marl.training import plots

    c = config or AdaptationConfig()
    jobs = adaptation_jobs(c)
    run_sweep(jobs, out, workers=workers, on_done=on_done)
    needed = {h for label in c.switches for h in c.switch(label).humans if h != "adversarial"}
    oracle = {name: oracle_rate(c.scenario, name).rate_per_hour for name in sorted(needed)}
    oracle["adversarial"] = 0.0  # it hides what the robot cannot reach: most layouts never finish
    summary: dict[str, Any] = {"duration": c.duration, "seeds": c.seeds, "oracle_rate_per_hour": oracle, "results": {}}
    figures: dict[str, Path] = {}
    grid = np.arange(c.window, c.duration + 1e-9, 10.0)
    for label in c.switches:
        sw = c.switch(label)
        rows: dict[str, Any] = {}
        curves: dict[str, np.ndarray] = {}
        for robot in c.robots:
            logs = [load_log(j, out) for j in jobs if j.label == f"adapt_{label}_{robot}"]
            rows[robot] = summarise_switch(logs, sw, oracle[sw.final], c.duration)
            curves[robot] = np.array([rate_curve(log, grid, c.window) for log in logs])
        summary["results"][label] = {"humans": list(sw.humans), "at": list(sw.at), "robots": rows}
        phases = [(0.0, oracle[sw.humans[0]])] + [(t, oracle[h]) for t, h in zip(sw.at, sw.humans[1:], strict=True)]
        figures[f"adaptation_{label}"] = plots.adaptation(
            grid,
            curves,
            phases,
            f"Human: {' -> '.join(sw.humans)}; trailing {c.window:.0f} s rate, mean and 95% CI of {c.seeds} seeds",
            out / f"adaptation_{label}.png",
        )
        if on_figure:
            on_figure(None, figures[f"adaptation_{label}"])
    figures["adaptation_regret"] = plots.regret_bars(summary["results"], out / "adaptation_regret.png")
    if on_figure:
        on_figure(None, figures["adaptation_regret"])
    return summary, figures


def adaptation_table(summary: dict[str, Any]) -> str:
    """Printed table of the adaptation results (mean [95% CI])."""
    oracle = summary["oracle_rate_per_hour"]
    lines = [
        f"adaptation: {summary['seeds']} seeds, {summary['duration']:.0f} s runs; oracle tasks/h: "
        + ", ".join(f"{k} {v:.1f}" for k, v in oracle.items())
    ]
    head = f"{'switch':<22}{'robot':<23}{'tasks lost [95% CI]':>24}{'recover s [95% CI]':>24}{'recovered':>11}"
    lines += [head, "-" * len(head)]

    def fmt(ci: dict[str, float | None], digits: int) -> str:
        if ci["mean"] is None:
            return "never"
        return f"{ci['mean']:.{digits}f} [{ci['low']:.{digits}f}, {ci['high']:.{digits}f}]"

    for label, block in summary["results"].items():
        for robot, row in block["robots"].items():
            lines.append(
                f"{label:<22}{robot:<23}{fmt(row['tasks_lost'], 1):>24}{fmt(row['time_to_recover'], 0):>24}"
                f"{row['recovered_runs']:>6}/{row['runs']:<4}"
            )
    return "\n".join(lines)
