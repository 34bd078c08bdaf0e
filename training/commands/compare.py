"""``hg-marl compare``: SB3 algorithms vs the planner and the hybrid robot, as fractions of the oracle.

torch and SB3 are imported inside the command body only, so ``hg-marl --help`` stays fast.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from hg_marl.training.commands.common import checked


def _names(text: str) -> tuple[str, ...]:
    return tuple(x.strip() for x in text.split(",") if x.strip())


def register(app: typer.Typer) -> None:
    """Add the ``compare`` subcommand."""

    @app.command("compare")
    def compare_command(
        algos: Annotated[str, typer.Option(help="Comma list of ppo, maskable_ppo, dqn, a2c.")] = (
            "ppo,maskable_ppo,dqn,a2c"
        ),
        humans: Annotated[str, typer.Option(help="Comma list of humans (one training each).")] = (
            "cooperative,lazy,no_handover"
        ),
        scenario: Annotated[str, typer.Option(help="Scenario spec.")] = "paper2015",
        steps: Annotated[int, typer.Option(help="Training budget per (algo, human, seed).")] = 20_000,
        seeds: Annotated[int, typer.Option(help="Training seeds per (algo, human).")] = 1,
        eval_every: Annotated[int, typer.Option(help="Steps between runner evaluations.")] = 2_000,
        eval_seeds: Annotated[int, typer.Option(help="Runner seeds per evaluation.")] = 2,
        duration: Annotated[float, typer.Option(help="Simulated seconds per evaluation run.")] = 1200.0,
        deterministic: Annotated[
            bool, typer.Option(help="Evaluate SB3 policies greedily instead of sampling (DQN: always greedy).")
        ] = False,
        out: Annotated[Path, typer.Option(help="Output directory (resumable).")] = Path("runs/compare"),
    ) -> None:
        """Train each algorithm against each human, evaluate on the runner's protocol, report vs the oracle."""
        from hg_marl.training.baselines.compare import CompareConfig, compare, format_table
        from hg_marl.training.baselines.hyperparams import check_algo

        names = checked(lambda: tuple(check_algo(a) for a in _names(algos)))
        config = CompareConfig(
            algos=names,
            humans=_names(humans),
            scenario=scenario,
            steps=steps,
            seeds=seeds,
            eval_every=eval_every,
            eval_seeds=tuple(range(100, 100 + eval_seeds)),
            duration=duration,
            out=out,
        )
        summary = checked(lambda: compare(config, on_cell=lambda label: typer.echo(f"training {label} ...")))
        typer.echo(f"{scenario}: {steps} steps per cell, {seeds} seed(s), {eval_seeds} eval runs x {duration:.0f} s")
        typer.echo(format_table(summary["rows"]))
        typer.echo(f"summary: {out / 'summary.json'}")
