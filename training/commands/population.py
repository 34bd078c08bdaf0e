"""``hg-marl population generate | show``: partner populations of preference humans."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from hg_marl.training.commands.common import default_workers


def _robots(text: str) -> tuple[str, ...]:
    from hg_marl.core.errors import ConfigError

    names = tuple(x.strip() for x in text.split(",") if x.strip())
    if not names:
        raise ConfigError("--robots: expected a comma list of reference robots")
    return names


def register(app: typer.Typer) -> None:
    """Add the ``population`` command group."""
    from hg_marl.training.cli import one_line_errors

    group = typer.Typer(help="Partner populations: generate one, show one.", no_args_is_help=True)

    @group.command("generate")
    @one_line_errors
    def generate_command(
        out: Annotated[Path, typer.Option(help="Population file to write (TOML).")],
        scenario: Annotated[str, typer.Option(help="Scenario name or TOML path.")] = "paper2015",
        seed: Annotated[int, typer.Option(help="Seeds the candidates' weights.")] = 0,
        candidates: Annotated[int, typer.Option(help="Preference humans sampled and measured.")] = 32,
        held_out: Annotated[int, typer.Option(help="Members of the held_out split (selected first).")] = 8,
        train: Annotated[int, typer.Option(help="Members of the train split.")] = 8,
        validation: Annotated[int, typer.Option(help="Members of the validation split.")] = 4,
        robots: Annotated[str, typer.Option(help="Reference robots of the measuring runs (comma list).")] = (
            "planner,random"
        ),
        duration: Annotated[float, typer.Option(help="Simulated seconds per measuring run.")] = 600.0,
        seeds: Annotated[int, typer.Option(help="Measuring runs per candidate and robot.")] = 2,
        store: Annotated[
            Path | None, typer.Option(help="Store of the measuring runs (default: OUT's folder / OUT's stem + .store).")
        ] = None,
        backend: Annotated[str, typer.Option(help="local (process pool) or ray.")] = "local",
        address: Annotated[str | None, typer.Option(help="ray: 'auto' or ray://host:port joins a cluster.")] = None,
        workers: Annotated[
            int, typer.Option(help="Worker processes (local) or CPUs of a new Ray instance.")
        ] = default_workers(),
    ) -> None:
        """Sample preference humans, measure them against reference robots, keep a diverse subset (BR-Div)."""
        import math

        from tqdm import tqdm

        from hg_marl.core.errors import ConfigError, check_int
        from hg_marl.core.scenario import load_scenario
        from hg_marl.training.backends import make_backend
        from hg_marl.training.commands.common import check_duration, check_out_dir, check_out_file
        from hg_marl.training.limits import MAX_MEMBERS, check_count
        from hg_marl.training.population_gen import GeneratorConfig, generate, jobs_for, render, write
        from hg_marl.training.store import Store

        check_out_file(out, "--out", (".toml",))
        if store is not None:
            check_out_dir(store, "--store")
        load_scenario(scenario)
        check_int(seed, "--seed", minimum=0)
        check_count(candidates, "--candidates", MAX_MEMBERS, minimum=2)
        check_count(seeds, "--seeds", 100)
        sizes = {  # each split on its own, so the option over the limit is the one named
            "train": check_count(train, "--train", MAX_MEMBERS, minimum=0),
            "validation": check_count(validation, "--validation", MAX_MEMBERS, minimum=0),
            "held_out": check_count(held_out, "--held-out", MAX_MEMBERS, minimum=0),
        }
        if not any(sizes.values()):
            raise ConfigError("--held-out, --train, --validation: at least one member")
        if candidates < sum(sizes.values()):
            raise ConfigError(f"--candidates: {candidates} is fewer than the {sum(sizes.values())} members asked for")
        config = GeneratorConfig(
            scenario=scenario,
            seed=seed,
            candidates=candidates,
            sizes=sizes,
            robots=_robots(robots),
            duration=check_duration(duration, scenario=scenario),
            seeds=seeds,
        )
        from hg_marl.agents.robots import make_robot

        for robot in config.robots:
            make_robot(robot)
        executor = make_backend(backend, workers, address)
        root = store or out.parent / f"{out.stem}.store"
        total = len(jobs_for(config, [{}] * candidates))
        with tqdm(total=total, unit="run", desc="measuring") as bar:

            def done(job: Any, run: Any) -> None:
                bar.update(1)

            result = generate(config, Store(root), executor, done)
        write(out, render(config, result, out.stem))
        typer.echo(f"{result.n_candidates} candidates, {len(result.dropped)} dropped (no task with {config.robots[0]})")
        typer.echo("spread (log det of the RBF kernel over behaviour features; higher = more diverse):")
        typer.echo(f"{'split':<11} {'members':>7} {'selected':>9} {'random':>9}")
        for split, values in result.spread.items():
            rnd = values["random"]
            shown = f"{rnd:9.2f}" if math.isfinite(rnd) else f"{'-inf':>9}"
            typer.echo(f"{split:<11} {sizes[split]:>7} {values['selected']:9.2f} {shown}")
        typer.echo(f"wrote {out}; measuring runs in {root}")

    @group.command("show")
    @one_line_errors
    def show_command(
        file: Annotated[Path, typer.Argument(help="Population file (TOML).")],
    ) -> None:
        """The members (name, split, spec) and the spreads of a population file."""
        from hg_marl.agents.humans.population import load_population

        pop = load_population(file)
        typer.echo(f"{pop.name}: {len(pop.members())} members measured on {pop.scenario or '(unknown scenario)'}")
        for split, values in pop.spread.items():
            parts = ", ".join(f"{k} {v:.2f}" for k, v in values.items())
            typer.echo(f"spread {split}: {parts}")
        typer.echo(f"{'name':<6} {'split':<10} spec")
        for member in pop.members():
            typer.echo(f"{member.name:<6} {member.split:<10} {member.spec}")

    app.add_typer(group, name="population")
