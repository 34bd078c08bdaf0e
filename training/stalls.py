"""Stalls in a study's runs: the longest stretch of simulated time without a solved task.

The project's rule is that no robot stalls on a partner who leaves the task solvable; the
measure is the longest stretch without a task (from the run's start, between tasks, and to
its end), counted as a stall when over :data:`STALL_SECONDS` while some robot solved tasks
with that partner on that scenario (the task is solvable with it). Read from a study's
store, so it adds no run::

    python -m hg_marl.training.stalls results/family_out
"""

from __future__ import annotations

import gzip
import itertools
import json
import sys
from collections import defaultdict
from pathlib import Path
from typing import Any

import pandas as pd

STALL_SECONDS = 300.0
"""A stretch without a task longer than this is a stall."""


def longest_gap(log: pd.DataFrame, duration: float) -> float:
    """Longest simulated stretch without a solved task in a run's per-decision log."""
    if log.empty:
        return float(duration)
    solved = log["tasks_solved"].to_numpy()
    times = log["time"].to_numpy()
    marks = [0.0, *[float(t) for t, a, b in zip(times[1:], solved[:-1], solved[1:], strict=True) if b > a]]
    if len(solved) and solved[0] > 0:
        marks.append(float(times[0]))
    marks = [*sorted(marks), float(duration)]
    return max(b - a for a, b in itertools.pairwise(marks))


def runs_of(out: Path) -> list[dict[str, Any]]:
    """One row per stored run of a study folder: robot, human, scenario, seed, tasks, gap, guard moves."""
    rows = []
    for result in sorted((out / "store" / "runs").glob("*/*/result.json")):
        data = json.loads(result.read_text())
        job = data["job"]
        with gzip.open(result.parent / "log.csv.gz", "rt") as f:
            log = pd.read_csv(f)
        params = ",".join(f"{k}={v}" for k, v in sorted(job.get("robot_params", {}).items()))
        human = ",".join(f"{k}={v}" for k, v in sorted(job.get("human_params", {}).items()))
        rows.append(
            {
                "robot": job["robot"] + (f":{params}" if params else ""),
                "human": job["human"] + (f":{human}" if human else ""),
                "scenario": job["scenario"],
                "seed": job["seed"],
                "tasks": int(log["tasks_solved"].max()) if len(log) else 0,
                "gap": longest_gap(log, float(job["duration"])),
                "guard_moves": int((log["reason"] == "no_progress").sum()) if "reason" in log else 0,
            }
        )
    return rows


def report(out: Path) -> str:
    """A Markdown table of the stalls (and guard moves) per robot, over solvable (human, scenario) cells."""
    rows = runs_of(out)
    solvable = {(r["human"], r["scenario"]) for r in rows if r["tasks"] > 0}
    by_robot: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for r in rows:
        if (r["human"], r["scenario"]) in solvable:
            by_robot[r["robot"]].append(r)
    lines = [
        f"| robot | runs | stalls (> {STALL_SECONDS:.0f} s without a task) | longest stretch (s) | guard moves/run |",
        "|---|---:|---:|---:|---:|",
    ]
    for robot, rs in sorted(by_robot.items()):
        stalls = [r for r in rs if r["gap"] > STALL_SECONDS]
        worst = max(rs, key=lambda r: r["gap"])
        where = f" ({worst['human'][:40]}, {worst['scenario']}, seed {worst['seed']})"
        guard = sum(r["guard_moves"] for r in rs) / len(rs)
        lines.append(f"| {robot} | {len(rs)} | {len(stalls)} | {worst['gap']:.0f}{where} | {guard:.1f} |")
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover (a reading aid)
    if len(sys.argv) != 2 or not (Path(sys.argv[1]) / "store" / "runs").is_dir():
        print("usage: python -m hg_marl.training.stalls STUDY_OUT_FOLDER (a folder hg-marl evaluate wrote)")
        raise SystemExit(2)
    print(report(Path(sys.argv[1])))
