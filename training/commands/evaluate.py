"""``hg-marl evaluate``: a study file's robots x humans x scenarios x seeds, with rliable aggregates."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from hg_marl.training.commands.common import check_out_dir, check_workers, counting_bar, default_workers, name_list


def register(app: typer.Typer) -> None:
    """Add the ``evaluate`` subcommand."""

    @app.command("evaluate")
    def evaluate_command(
        study: Annotated[Path, typer.Argument(help="Study file (TOML), e.g. studies/crossplay.toml.")],
        out: Annotated[Path, typer.Option(help="Output folder (resumable: its store keeps every run).")],
        backend: Annotated[str, typer.Option(help="local (process pool) or ray.")] = "local",
        address: Annotated[
            str | None, typer.Option(help="ray: 'auto' or ray://host:port joins a cluster; none starts one.")
        ] = None,
        workers: Annotated[
            int, typer.Option(help="Worker processes (local) or CPUs of a new Ray instance.")
        ] = default_workers(),
        seeds: Annotated[int | None, typer.Option(help="Only the study's first N seeds.")] = None,
        robots: Annotated[str | None, typer.Option(help="Only these robots (comma list of labels or names).")] = None,
        humans: Annotated[str | None, typer.Option(help="Only these humans (comma list of labels or names).")] = None,
        scenarios: Annotated[str | None, typer.Option(help="Only these of the study's scenarios (comma list).")] = None,
    ) -> None:
        """Every robot with every human: scores.csv, aggregate.json, crossplay/profiles/intervals PNGs, report.md."""
        import time

        from hg_marl.training.backends import make_backend
        from hg_marl.training.evaluate import cells, evaluate
        from hg_marl.training.report import robot_table
        from hg_marl.training.study import load_study

        check_out_dir(out, "--out")
        check_workers(workers)
        chosen = load_study(study).narrowed(
            seeds, name_list(robots, "--robots"), name_list(humans, "--humans"), name_list(scenarios, "--scenarios")
        )
        executor = make_backend(backend, workers, address)
        start = time.perf_counter()
        bar, done = counting_bar(len(cells(chosen)), chosen.name)
        try:
            agg = evaluate(chosen, out, executor, done, progress=True)
        finally:
            bar.close()
        wall = time.perf_counter() - start
        typer.echo(robot_table(agg))
        if agg["bootstrap"]["flag"]:
            typer.echo(f"caution: {agg['bootstrap']['flag']}")
        typer.echo(
            f"wall time {wall:.1f} s, of which aggregation {agg['seconds']:.2f} s "
            f"({100 * agg['seconds'] / max(wall, 1e-9):.0f}%); report: {out / 'report.md'}"
        )
