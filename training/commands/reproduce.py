"""``hg-marl reproduce``: the paper's experiment, with figures, summary and table."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from hg_marl.training.commands.common import check_duration, check_out_dir, check_workers, counting_bar, default_workers


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
        workers: Annotated[int, typer.Option(min=1, help="Worker processes.")] = default_workers(),
        paper_only: Annotated[bool, typer.Option("--paper-only", help="Only the paper's three conditions.")] = False,
        adaptation: Annotated[
            bool, typer.Option(help="Also run the adaptation experiment (human switches mid-run).")
        ] = True,
        adaptation_seeds: Annotated[int, typer.Option(min=1, help="Seeds per (robot, switch) when adapting.")] = 10,
    ) -> None:
        """Planner alone, habit alone, random mix (+ further criteria): Fig. 3-5, summary.json, table."""
        from hg_marl.training import paper
        from hg_marl.training.limits import MAX_SEEDS, check_count
        from hg_marl.training.reproduce import ReproduceConfig, reproduce

        check_out_dir(out, "--out")
        check_workers(workers)
        check_count(seeds, "--seeds", MAX_SEEDS)
        check_count(adaptation_seeds, "--adaptation-seeds", MAX_SEEDS)
        config = ReproduceConfig(
            out=out,
            seeds=seeds,
            duration=check_duration(paper.DEFAULT_DURATION if duration is None else duration, scenario=scenario),
            scenario=scenario,
            paper_only=paper_only,
            adaptation=adaptation,
            adaptation_seeds=adaptation_seeds,
            workers=workers,
        )
        bars: list[Any] = []

        def progress(stage: str, total: int) -> Any:
            bar, update = counting_bar(total, stage)
            bars.append(bar)
            return update

        try:
            summary = reproduce(config, progress=progress)
        finally:
            for bar in bars:
                bar.close()
        typer.echo(paper.table(summary["conditions"]))
        for name, target in summary["targets"].items():
            verdict = "holds" if target.get("holds") else "MISSED"
            typer.echo(f"target: {name}: {verdict} { ({k: v for k, v in target.items() if k != 'holds'}) }")
        if adaptation:
            from hg_marl.training.adaptation import adaptation_table

            typer.echo(adaptation_table(summary["adaptation"]))
        typer.echo(f"wrote {out / 'summary.json'} and {', '.join(summary['figures'].values())}")
