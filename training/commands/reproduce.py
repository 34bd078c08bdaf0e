"""``hg-marl reproduce``: the paper's experiment, with figures, summary and table."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Annotated, Any

import typer

from hg_marl.training.commands.common import check_duration


def register(app: typer.Typer) -> None:
    """Add the ``reproduce`` subcommand."""

    @app.command("reproduce")
    def reproduce_command(
        seeds: Annotated[int, typer.Option(min=1, help="Seeds per condition (the paper: 10).")] = 10,
        out: Annotated[Path, typer.Option(help="Output folder (resumable: finished runs are kept).")] = Path(
            "results/paper2015"
        ),
        duration: Annotated[
            float | None, typer.Option(help="Simulated seconds per run (default: calibrated, see training/paper.py).")
        ] = None,
        scenario: Annotated[str, typer.Option(help="Scenario.")] = "paper2015",
        workers: Annotated[int, typer.Option(min=1, help="Worker processes.")] = min(2, os.cpu_count() or 1),
        paper_only: Annotated[bool, typer.Option("--paper-only", help="Only the paper's three conditions.")] = False,
        adaptation: Annotated[
            bool, typer.Option(help="Also run the adaptation experiment (human switches mid-run).")
        ] = True,
        adaptation_seeds: Annotated[int, typer.Option(min=1, help="Seeds per (robot, new human) when adapting.")] = 3,
    ) -> None:
        """Planner alone, habit alone, random mix (+ further criteria): Fig. 3-5, summary.json, table."""
        from tqdm import tqdm

        from hg_marl.training import paper, plots
        from hg_marl.training.io import write_json
        from hg_marl.training.sweep import load_log, run_sweep

        duration = paper.DEFAULT_DURATION if duration is None else check_duration(duration)
        jobs = paper.jobs(seeds=seeds, duration=duration, scenario=scenario, further=not paper_only)
        with tqdm(total=len(jobs), unit="run", desc="paper experiment") as bar:
            run_sweep(jobs, out, workers=workers, on_done=lambda job, _: bar.update(1))
        logs: dict[str, list[Any]] = {}
        for job in jobs:
            logs.setdefault(job.label, []).append(load_log(job, out))
        rows = {label: paper.summarise_condition(paper.ConditionLogs(label, runs)) for label, runs in logs.items()}
        summary: dict[str, Any] = {
            "scenario": scenario,
            "duration": duration,
            "seeds": seeds,
            "conditions": rows,
            "paper": paper.PAPER,
            "targets": paper.check_targets(rows),
        }
        figures = {
            "fig3": plots.cumulative_reward(logs, duration, out / "fig3_cumulative_reward.png"),
            "fig4": plots.actions_per_run(logs, out / "fig4_actions_per_run.png"),
            "fig5": plots.weight_amplitude(logs, out / "fig5_weight_amplitude.png"),
        }
        if adaptation:
            from hg_marl.training.adaptation import AdaptationConfig, adaptation_jobs, run_adaptation

            config = AdaptationConfig(scenario=scenario, seeds=adaptation_seeds)
            with tqdm(total=len(adaptation_jobs(config)), unit="run", desc="adaptation") as bar:
                summary["adaptation"], more = run_adaptation(
                    out, config, workers=workers, on_done=lambda job, _: bar.update(1)
                )
            figures.update(more)
        summary["figures"] = {k: str(v) for k, v in figures.items()}
        write_json(out / "summary.json", summary)
        typer.echo(paper.table(rows))
        for name, target in summary["targets"].items():
            verdict = "holds" if target.get("holds") else "MISSED"
            typer.echo(f"target: {name}: {verdict} { ({k: v for k, v in target.items() if k != 'holds'}) }")
        if adaptation:
            from hg_marl.training.adaptation import adaptation_table

            typer.echo(adaptation_table(summary["adaptation"]))
        typer.echo(f"wrote {out / 'summary.json'} and {', '.join(str(p) for p in figures.values())}")
