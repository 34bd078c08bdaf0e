"""``hg-marl plan``: plan from a scenario's initial state and show the plan.

Prints the two-stream Gantt chart, the cost broken down by term and the planning time;
``--png`` also writes the chart as an image.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from hg_marl.agents.planner import Planner, PlannerConfig, make_human_model
from hg_marl.agents.planner.gantt import gantt_png, gantt_text
from hg_marl.core import World
from hg_marl.core.errors import ConfigError
from hg_marl.training.commands.common import check_out_file, checked, default


def register(app: typer.Typer) -> None:
    """Add the ``plan`` command to ``app``."""

    @app.command("plan")
    def plan(
        scenario: Annotated[str, typer.Option(help="Built-in name, generated:k=v,... or a .toml path.")] = "paper2015",
        seed: Annotated[int, typer.Option(min=0, help="Seed of the initial layout.")] = 0,
        png: Annotated[Path | None, typer.Option(help="Also write the Gantt chart to this PNG file.")] = None,
        human: Annotated[str, typer.Option(help="Human model: cooperative, no_handover, lazy.")] = "cooperative",
        budget: Annotated[int, typer.Option(min=1, help="Node budget of the search.")] = default(
            PlannerConfig, "node_budget"
        ),
    ) -> None:
        """Plan the table cleaning from a scenario's initial state and print the plan."""
        check_out_file(png, "--png", (".png",))
        world = World(scenario)
        state = world.initial_state(np.random.default_rng(seed))
        try:
            model = make_human_model(human)
        except ValueError as exc:
            raise ConfigError(f"--human: {exc}") from None
        planner = Planner(world, checked(lambda: PlannerConfig(node_budget=budget)), model)
        start = time.perf_counter()
        result = planner.plan(state)
        elapsed = time.perf_counter() - start
        typer.echo(f"scenario {world.scenario.name}, seed {seed}, human model {human}")
        if not result.success or result.plan is None:
            typer.echo(f"no plan: {result.reason}")
            typer.echo(f"planning time {elapsed * 1e3:.2f} ms, {result.nodes} nodes")
            raise typer.Exit(code=1)
        typer.echo(gantt_text(world, result.plan))
        typer.echo("")
        typer.echo(f"cost {result.cost:.3f} ({'proven optimal' if result.optimal else 'not proven optimal'})")
        for term, value in result.breakdown.items():
            typer.echo(f"  {term:<15} {value:8.3f}")
        typer.echo(f"planning time {elapsed * 1e3:.2f} ms, {result.nodes} nodes expanded")
        if png is not None:
            typer.echo(f"wrote {gantt_png(world, result.plan, png, title=f'{world.scenario.name} seed {seed}')}")
