"""``hg-marl switching``: partners that switch between two population members at a period."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer


def register(app: typer.Typer) -> None:
    """Add the ``switching`` command to ``app``."""

    @app.command("switching")
    def switching_command(
        population: Annotated[Path, typer.Option(help="Population file whose members the partner switches between.")],
        pairs: Annotated[str, typer.Option(help="Comma list of member pairs A/B (the partner plays A, B, A, ...).")],
        scenario: Annotated[str, typer.Option(help="Scenario name or TOML path.")] = "forced_coordination",
        periods: Annotated[str, typer.Option(help="Comma list of switching periods (simulated s).")] = "10,60,300,900",
        robots: Annotated[
            str | None,
            typer.Option(help="Comma list of robot specs (default: planner and belief over the population)."),
        ] = None,
        baseline: Annotated[str, typer.Option(help="The fixed-model counterpart, paired by seed.")] = "planner",
        seeds: Annotated[int, typer.Option(help="Seeds per (pair, period, robot).")] = 5,
        duration: Annotated[float, typer.Option(help="Simulated seconds per run.")] = 1800.0,
        min_phase: Annotated[float, typer.Option(help="Recovery is read after changes into phases this long.")] = 120.0,
        out: Annotated[Path, typer.Option(help="Output folder (resumable: its store keeps every run).")] = Path(
            "results/switching"
        ),
        workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
    ) -> None:
        """Tasks, regret against the per-phase best response, paired difference from the baseline, recovery."""

        from hg_marl.agents.humans.population import load_population
        from hg_marl.core.errors import ConfigError
        from hg_marl.core.spec import split_specs
        from hg_marl.training import plots
        from hg_marl.training.commands.common import check_duration, check_out_dir, check_workers, counting_bar
        from hg_marl.training.io import write_json
        from hg_marl.training.limits import MAX_SEEDS, check_count
        from hg_marl.training.switching import (
            SwitchingConfig,
            check_config,
            run_switching,
            switching_jobs,
            switching_table,
        )

        check_out_dir(out, "--out")
        check_workers(workers)
        check_count(seeds, "--seeds", MAX_SEEDS)
        check_duration(duration, scenario=scenario)
        pop = load_population(population)
        names = {m.name: str(m.spec) for m in pop.members()}
        chosen: list[tuple[str, str]] = []
        for item in (p.strip() for p in pairs.split(",") if p.strip()):
            a, sep, b = item.partition("/")
            if not sep or not a or not b or a == b:
                raise ConfigError(f"--pairs {item!r}: expected two different members A/B")
            unknown = [n for n in (a, b) if n not in names]
            if unknown:
                raise ConfigError(f"--pairs: {', '.join(unknown)} not a member of {population} ({', '.join(names)})")
            chosen.append((a, b))
        try:
            period_values = tuple(float(p) for p in periods.split(",") if p.strip())
        except ValueError:
            raise ConfigError(f"--periods {periods!r}: expected a comma list of seconds") from None
        robot_specs = tuple(split_specs(robots)) if robots else ("planner", f"belief:population={population}")
        config = SwitchingConfig(
            scenario=scenario,
            pairs=tuple(chosen),
            periods=period_values,
            robots=robot_specs,
            baseline=baseline,
            seeds=seeds,
            duration=duration,
            min_phase=min_phase,
            members=tuple(names.items()),
        )
        check_config(config)
        bar, done = counting_bar(len(switching_jobs(config)), "switching")
        try:
            summary = run_switching(config, out, workers=workers, on_done=done)
        finally:
            bar.close()
        typer.echo(switching_table(summary))
        write_json(out / "switching.json", summary)  # strict JSON, as every result file
        figure = plots.switching(summary, out / "switching.png")
        lost = [c for c in summary["cells"] if c["loses"]]
        typer.echo(
            f"{len(lost)} of {len(summary['cells'])} cells where a robot loses to {baseline} beyond the CI; "
            f"wrote switching.json and {figure.name} in {out}"
        )
