"""The paper's experiment as a library function: :func:`reproduce` (``hg-marl reproduce`` wraps it).

Every run goes through the content-addressed store in ``out/store``
(:mod:`hg_marl.training.store`), so a second call with another duration, scenario or
seed count runs exactly the runs it does not have, and the summary always describes the
runs it was computed from.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hg_marl.training import paper, plots
from hg_marl.training.backends import Backend, LocalBackend
from hg_marl.training.io import write_json
from hg_marl.training.store import Job
from hg_marl.training.sweep import run_jobs, store_of


@dataclass(frozen=True)
class ReproduceConfig:
    """What ``hg-marl reproduce`` runs."""

    out: Path = Path("results/paper2015")
    """Output folder (its store makes the experiment resumable)."""
    seeds: int = 10
    """Seeds per condition."""
    duration: float = paper.DEFAULT_DURATION
    """Simulated seconds per run."""
    scenario: str = "paper2015"
    """Scenario."""
    paper_only: bool = False
    """Only the paper's three conditions."""
    adaptation: bool = True
    """Also run the adaptation experiment."""
    adaptation_seeds: int = 3
    """Seeds per (robot, new human) of the adaptation experiment."""
    workers: int = 1
    """Local worker processes (the default backend's, and the adaptation stage's)."""


Progress = Callable[[str, int], Callable[[Job | None, Any], None]]
"""``progress(stage, total)`` returns the per-item callback of that stage (a progress bar's update):
called with each finished job, or with ``None`` and each figure written."""


def reproduce(
    config: ReproduceConfig, backend: Backend | None = None, progress: Progress | None = None
) -> dict[str, Any]:
    """Run (or resume) the experiment; write ``summary.json`` and the figures; return the summary.

    Args:
        config: the experiment.
        backend: executor of the paper's runs (default: ``config.workers`` local processes).
        progress: progress-bar factory (library code prints nothing).
    """
    out = Path(config.out)
    jobs = paper.jobs(
        seeds=config.seeds, duration=config.duration, scenario=config.scenario, further=not config.paper_only
    )
    on_done = progress("paper experiment", len(jobs)) if progress else None
    runs, _ = run_jobs(jobs, store_of(out), backend or LocalBackend(config.workers), on_done)
    logs: dict[str, list[Any]] = {}
    for job, run in zip(jobs, runs, strict=True):
        logs.setdefault(job.label, []).append(run.log())
    rows = {label: paper.summarise_condition(paper.ConditionLogs(label, runs)) for label, runs in logs.items()}
    summary: dict[str, Any] = {
        "scenario": config.scenario,
        "duration": config.duration,
        "seeds": config.seeds,
        "conditions": rows,
        "paper": paper.PAPER,
        "targets": paper.check_targets(rows),
        "runs": {job.label: [] for job in jobs},
    }
    for job, run in zip(jobs, runs, strict=True):
        summary["runs"][job.label].append(run.key)
    # drawing takes seconds: the figures are a stage of their own, so the wait is never silent
    drawn = progress("paper figures", 3) if progress else None
    figures: dict[str, Path] = {}
    for name, draw in (
        ("fig3", lambda: plots.cumulative_reward(logs, config.duration, out / "fig3_cumulative_reward.png")),
        ("fig4", lambda: plots.actions_per_run(logs, out / "fig4_actions_per_run.png")),
        ("fig5", lambda: plots.weight_amplitude(logs, out / "fig5_weight_amplitude.png")),
    ):
        figures[name] = draw()
        if drawn:
            drawn(None, figures[name])
    if config.adaptation:
        from hg_marl.training.adaptation import AdaptationConfig, adaptation_jobs, run_adaptation

        adapt = AdaptationConfig(scenario=config.scenario, seeds=config.adaptation_seeds)
        stage = progress("adaptation", len(adaptation_jobs(adapt))) if progress else None
        on_figure = progress("adaptation figures", len(adapt.switches) + 1) if progress else None
        summary["adaptation"], more = run_adaptation(
            out, adapt, workers=config.workers, on_done=stage, on_figure=on_figure
        )
        figures.update(more)
    summary["figures"] = {k: str(v) for k, v in figures.items()}
    write_json(out / "summary.json", summary)
    return summary
