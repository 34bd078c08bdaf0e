"""Resumable sweeps of runner jobs over local processes.

A job is (condition label, robot spec, human spec, scenario, duration, seed). Each
finished job writes its per-decision log and its summary atomically under
``out/runs/<label>/seed<k>.{csv,json}``; a job whose summary exists is skipped, so an
interrupted sweep resumes where it stopped and never loses a finished run. Jobs run
in a process pool (``jobs`` workers; 1 runs in-process, which tests and profilers
prefer). Every job is a pure function of its spec, so results do not depend on the
number of workers.
"""

from __future__ import annotations

import json
import logging
from collections.abc import Callable, Iterable
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from hg_marl.training.io import write_json
from hg_marl.training.runner import RunConfig, RunResult, run

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Job:
    """One run of a sweep."""

    label: str
    """Condition name, used for the output folder."""
    robot: str
    """Robot registry name."""
    seed: int
    """Run seed."""
    scenario: str = "paper2015"
    """Scenario."""
    duration: float = 1200.0
    """Simulated seconds."""
    human: str = "cooperative"
    """Human registry name."""
    robot_params: dict[str, Any] = field(default_factory=dict)
    """Keyword arguments of ``make_robot``."""
    human_params: dict[str, Any] = field(default_factory=dict)
    """Keyword arguments of ``make_human``."""

    def paths(self, out: Path) -> tuple[Path, Path]:
        """Where this job's log (CSV) and summary (JSON) go."""
        base = out / "runs" / self.label / f"seed{self.seed}"
        return base.with_suffix(".csv"), base.with_suffix(".json")


def execute(job: Job) -> RunResult:
    """Build the actors from their specs and run the job."""
    from hg_marl.agents.humans import make_human
    from hg_marl.agents.robots import make_robot

    robot = make_robot(job.robot, **job.robot_params)
    human = make_human(job.human, **job.human_params)
    return run(robot, human, RunConfig(scenario=job.scenario, duration=job.duration, seed=job.seed))


def _execute_and_save(job: Job, out: Path) -> dict[str, Any]:
    result = execute(job)
    log_path, summary_path = job.paths(out)
    result.save(log_path)
    summary = {**result.summary, "job": asdict(job)}
    write_json(summary_path, summary)
    return summary


def run_sweep(
    jobs: Iterable[Job],
    out: str | Path,
    workers: int = 1,
    on_done: Callable[[Job, dict[str, Any]], None] | None = None,
) -> list[dict[str, Any]]:
    """Run every job not already finished under ``out``; return all summaries, in job order.

    Args:
        jobs: the sweep.
        out: output folder (created).
        workers: worker processes; 1 runs in this process.
        on_done: called after each job (finished now or found finished).
    """
    out = Path(out)
    jobs = list(jobs)
    summaries: dict[int, dict[str, Any]] = {}
    todo: list[int] = []
    for i, job in enumerate(jobs):
        _, summary_path = job.paths(out)
        if summary_path.exists():
            summaries[i] = json.loads(summary_path.read_text())
            if on_done:
                on_done(job, summaries[i])
        else:
            todo.append(i)
    if todo:
        log.info("%d jobs to run, %d already done", len(todo), len(summaries))
    if workers <= 1 or len(todo) <= 1:
        for i in todo:
            summaries[i] = _execute_and_save(jobs[i], out)
            if on_done:
                on_done(jobs[i], summaries[i])
    else:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            futures = {pool.submit(_execute_and_save, jobs[i], out): i for i in todo}
            for future in as_completed(futures):
                i = futures[future]
                summaries[i] = future.result()
                if on_done:
                    on_done(jobs[i], summaries[i])
    return [summaries[i] for i in range(len(jobs))]


def load_log(job: Job, out: str | Path) -> pd.DataFrame:
    """The per-decision log of a finished job."""
    return pd.read_csv(job.paths(Path(out))[0])
