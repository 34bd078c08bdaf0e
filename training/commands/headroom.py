"""``hg-marl headroom``: how much a scenario rewards knowing one's partner (exact, no robot runs)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from hg_marl.training.commands.common import default_workers


def register(app: typer.Typer) -> None:
    """Add the ``headroom`` command to ``app``."""

    @app.command("headroom")
    def headroom_command(
        scenario: Annotated[str, typer.Option(help="Scenario name or TOML path.")] = "paper2015",
        population: Annotated[
            Path | None, typer.Option(help="Population file: its members are the partners, held_out the test split.")
        ] = None,
        humans: Annotated[str | None, typer.Option(help="Or a comma list of stationary human specs.")] = None,
        out: Annotated[Path, typer.Option(help="Output folder: headroom.csv, headroom.png, headroom.json.")] = Path(
            "results/headroom"
        ),
        max_states: Annotated[int, typer.Option(min=1, help="Refuse beyond this many model states.")] = 1_500_000,
        max_seconds: Annotated[float, typer.Option(help="Wall-time budget in seconds (over it: exit 2).")] = 600.0,
        jobs: Annotated[
            int,
            typer.Option(
                help="Worker processes for the planner's answers, the policies and the rates (0: one per CPU); "
                "the matrix does not depend on it.",
            ),
        ] = default_workers(),
    ) -> None:
        """Policy optimal against A played with T over the optimum with T; 1 - IQM of the cooperative row."""
        from hg_marl.agents.humans import HumanError
        from hg_marl.agents.models.budget import MAX_SECONDS
        from hg_marl.agents.models.forked import check_jobs
        from hg_marl.agents.oracle import OracleTooLarge
        from hg_marl.core.errors import ConfigError, check_finite
        from hg_marl.core.scenario import load_scenario
        from hg_marl.core.spec import split_specs
        from hg_marl.training.commands.common import check_out_dir, command_start, over_budget
        from hg_marl.training.headroom import partners, write_headroom

        check_out_dir(out, "--out")
        try:
            check_jobs(jobs, "--jobs")
        except ValueError as exc:
            raise ConfigError(str(exc)) from None
        check_finite(max_seconds, "--max-seconds", positive=True, maximum=MAX_SECONDS)
        specs = split_specs(humans or "")
        columns, held_out = partners(population, specs)
        load_scenario(scenario)
        try:
            result = write_headroom(
                scenario,
                columns,
                held_out,
                out,
                max_states=max_states,
                max_seconds=max_seconds,
                jobs=jobs,
                started=command_start(),
            )
        except (HumanError, OracleTooLarge) as exc:
            if isinstance(exc, OracleTooLarge):
                over_budget()
            raise ConfigError(str(exc)) from None
        width = max(len(a) for a in result.assumed)
        corner = "assumed / true"
        width = max(width, len(corner))
        typer.echo(f"{corner:<{width}}  " + "  ".join(result.true))
        for label, row in zip(result.assumed, result.ratio, strict=True):
            typer.echo(f"{label:<{width}}  " + "  ".join("n/a" if v != v else f"{v:.2f}" for v in row))
        typer.echo(
            "optimal rates (tasks/h): "
            + ", ".join(f"{t} {r:.1f}" for t, r in zip(result.true, result.optimum, strict=True))
        )
        typer.echo(
            f"adaptation headroom {result.headroom:.3f} (1 - IQM of the cooperative row over {', '.join(held_out)})"
        )
        typer.echo(f"model {result.n_states} states, {result.seconds:.1f} s; wrote headroom.csv, .png, .json in {out}")
