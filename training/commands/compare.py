"""``hg-marl compare``: SB3 algorithms vs the planner and the hybrid robot, as fractions of the oracle.

torch and SB3 are imported inside the command body only, so ``hg-marl --help`` stays fast.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from hg_marl.training.baselines.comparison import CompareConfig
from hg_marl.training.commands.common import check_out_dir, checked, default, name_list

DEFAULT_OUT: Path = default(CompareConfig, "out")


def register(app: typer.Typer) -> None:
    """Add the ``compare`` subcommand."""

    @app.command("compare")
    def compare_command(
        algos: Annotated[str, typer.Option(help="Comma list of ppo, maskable_ppo, dqn, a2c, ppo_batched.")] = ",".join(
            default(CompareConfig, "algos")
        ),
        humans: Annotated[str, typer.Option(help="Comma list of humans (one training each).")] = ",".join(
            default(CompareConfig, "humans")
        ),
        scenario: Annotated[str, typer.Option(help="Scenario spec.")] = default(CompareConfig, "scenario"),
        steps: Annotated[int, typer.Option(help="Training budget per (algo, human, seed).")] = default(
            CompareConfig, "steps"
        ),
        seeds: Annotated[
            int, typer.Option(help="Training seeds per (algo, human); 2 or more give confidence intervals.")
        ] = default(CompareConfig, "seeds"),
        eval_every: Annotated[int, typer.Option(help="Steps between runner evaluations.")] = default(
            CompareConfig, "eval_every"
        ),
        eval_seeds: Annotated[int, typer.Option(help="Runner seeds per evaluation.")] = len(
            default(CompareConfig, "eval_seeds")
        ),
        duration: Annotated[float, typer.Option(help="Simulated seconds per evaluation run.")] = default(
            CompareConfig, "duration"
        ),
        deterministic: Annotated[
            bool, typer.Option(help="Evaluate SB3 policies greedily instead of sampling (DQN: always greedy).")
        ] = default(CompareConfig, "deterministic"),
        out: Annotated[Path, typer.Option(help="Output directory (resumable).")] = DEFAULT_OUT,
    ) -> None:
        """Train each algorithm against each human, evaluate on the runner's protocol, report vs the oracle."""
        from hg_marl.agents.humans import make_human
        from hg_marl.core.errors import ConfigError, HgMarlError
        from hg_marl.core.scenario import load_scenario
        from hg_marl.training.baselines.compare import compare
        from hg_marl.training.baselines.comparison import format_aggregate, format_table
        from hg_marl.training.baselines.hyperparams import check_algo
        from hg_marl.training.limits import MAX_SEEDS, check_count

        check_out_dir(out, "--out")
        check_count(seeds, "--seeds", MAX_SEEDS)
        check_count(eval_seeds, "--eval-seeds", MAX_SEEDS)
        load_scenario(scenario)
        for human in name_list(humans, "--humans"):  # every name, before a store or a claim exists
            try:
                make_human(human)
            except HgMarlError as exc:
                raise ConfigError(f"--humans: {exc}") from None
        names = checked(lambda: tuple(a if a == "ppo_batched" else check_algo(a) for a in name_list(algos, "--algos")))
        config = CompareConfig(
            algos=names,
            humans=name_list(humans, "--humans"),
            scenario=scenario,
            steps=steps,
            seeds=seeds,
            eval_every=eval_every,
            eval_seeds=tuple(range(100, 100 + eval_seeds)),
            duration=duration,
            deterministic=deterministic,
            out=out,
        )
        summary = checked(lambda: compare(config, on_cell=lambda label: typer.echo(f"training {label} ...")))
        typer.echo(f"{scenario}: {steps} steps per cell, {seeds} seed(s), {eval_seeds} eval runs x {duration:.0f} s")
        typer.echo(format_table(summary["rows"]))
        if summary["aggregate"]:
            typer.echo("over humans (rliable, stratified bootstrap over seeds, 95% CIs):")
            typer.echo(format_aggregate(summary["aggregate"]))
        typer.echo(f"summary: {out / 'summary.json'}")
