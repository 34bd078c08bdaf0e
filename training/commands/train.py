"""``hg-marl train``: Stable-Baselines3 baselines in the robot seat, learned humans in the human seat.

torch and SB3 are imported inside the command body only, so ``hg-marl --help`` stays fast.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from hg_marl.core.errors import check_finite
from hg_marl.training.baselines.envs import EnvSpec
from hg_marl.training.baselines.train import TrainConfig
from hg_marl.training.commands.common import check_out_dir, checked, default

DEFAULT_OUT: Path = default(TrainConfig, "out")


def register(app: typer.Typer) -> None:
    """Add the ``train`` subcommand."""

    @app.command("train")
    def train_command(
        algo: Annotated[
            str,
            typer.Option(
                help="ppo, a2c, dqn, maskable_ppo, ppo_batched (batched tables), ppo_recurrent (batched, with "
                "memory), or bc (behaviour cloning)."
            ),
        ] = ("maskable_ppo"),
        seat: Annotated[str, typer.Option(help="robot (against humans) or human (against a robot).")] = "robot",
        human: Annotated[
            str,
            typer.Option(help="Robot seat: human(s) to train against; a comma list is a population drawn per episode."),
        ] = ("cooperative"),
        robot: Annotated[str, typer.Option(help="Human seat: the fixed robot(s) (comma list).")] = "planner",
        effort_weight: Annotated[
            float, typer.Option(help="Human seat: reward minus this x seconds of work.")
        ] = default(EnvSpec, "effort_weight"),
        scenario: Annotated[str, typer.Option(help="paper2015, roboergosum, generated:..., or a .toml.")] = default(
            EnvSpec, "scenario"
        ),
        steps: Annotated[int | None, typer.Option(help="Total environment steps (default: the YAML's).")] = None,
        seed: Annotated[int, typer.Option(min=0, help="Seed of the model and the training tables.")] = default(
            TrainConfig, "seed"
        ),
        out: Annotated[Path, typer.Option(help="Output directory.")] = DEFAULT_OUT,
        hp: Annotated[list[str] | None, typer.Option("--hp", help="Hyperparameter override key=value.")] = None,
        hyperparams: Annotated[Path | None, typer.Option(help="YAML file instead of the packaged one.")] = None,
        observation: Annotated[str, typer.Option(help="View observation: facts, flat or dict.")] = default(
            EnvSpec, "observation"
        ),
        max_cycles: Annotated[int, typer.Option(min=1, help="Training episode length in cycles.")] = default(
            EnvSpec, "max_cycles"
        ),
        eval_freq: Annotated[int, typer.Option(min=0, help="Steps between evaluations (0: none).")] = default(
            TrainConfig, "eval_freq"
        ),
        eval_episodes: Annotated[int, typer.Option(min=1, help="Episodes per evaluation.")] = default(
            TrainConfig, "eval_episodes"
        ),
        checkpoint_freq: Annotated[
            int | None,
            typer.Option(
                min=0, help="Steps between checkpoints (default: a tenth of --steps, whole rollouts; 0: none)."
            ),
        ] = None,
        resume: Annotated[
            Path | None, typer.Option(help="Checkpoint (.json) to continue: keeps its steps and optimizer state.")
        ] = None,
        traces: Annotated[
            list[Path] | None, typer.Option("--traces", help="bc: trace files or directories (repeat).")
        ] = None,
        bc_kind: Annotated[str, typer.Option(help="bc: table or linear_softmax.")] = "table",
        population: Annotated[
            Path | None, typer.Option(help="ppo_batched: a population file; trains against its train members.")
        ] = None,
        recipe: Annotated[
            str, typer.Option(help="ppo_recurrent: population recipe: members, fcp, e3t or coverage.")
        ] = "members",
        tensorboard: Annotated[bool, typer.Option(help="Write TensorBoard logs to OUT/tb.")] = default(
            TrainConfig, "tensorboard"
        ),
        progress: Annotated[bool, typer.Option(help="Show a progress bar.")] = True,
        verbose: Annotated[int, typer.Option(help="SB3 verbosity.")] = default(TrainConfig, "verbose"),
    ) -> None:
        """Train an SB3 algorithm on a seat of the table (or clone recorded play with --algo bc)."""
        check_out_dir(out, "--out")
        if algo == "bc":
            from hg_marl.training.baselines.bc import behaviour_clone

            if not traces:
                raise typer.BadParameter("--algo bc needs at least one --traces FILE")
            path, accuracy = checked(lambda: behaviour_clone(traces, out, kind=bc_kind))
            typer.echo(f"behaviour cloning ({bc_kind}): reproduces {accuracy:.1%} of the recorded actions")
            typer.echo(f"  policy  {path}  (make_human('learned', path='{path}'))")
            return

        if algo == "ppo_recurrent":
            from hg_marl.training.baselines.envs import split_population
            from hg_marl.training.baselines.ppo_batched import population_members
            from hg_marl.training.baselines.ppo_recurrent import train_from_options

            members = population_members(population) if population is not None else tuple(split_population(human))
            args = (members, scenario, recipe, steps, seed, out, checkpoint_freq, progress, tuple(hp or ()))
            for line in checked(lambda: train_from_options(*args)):
                typer.echo(line)
            return

        if algo == "ppo_batched":
            _train_batched(human, population, scenario, steps, seed, out, checkpoint_freq, tensorboard, progress, hp)
            return

        from hg_marl.training.baselines.envs import split_population
        from hg_marl.training.baselines.train import train

        partners = human if seat == "robot" else robot
        check_finite(effort_weight, "--effort-weight", minimum=0.0)
        config = checked(
            lambda: TrainConfig(
                algo=algo,
                env=EnvSpec(
                    seat=seat,
                    partners=split_population(partners),
                    scenario=scenario,
                    observation=observation,
                    max_cycles=max_cycles,
                    effort_weight=effort_weight,
                ),
                steps=steps,
                seed=seed,
                out=out,
                hp_overrides=tuple(hp or ()),
                hyperparams_file=hyperparams,
                eval_freq=eval_freq,
                eval_episodes=eval_episodes,
                checkpoint_freq=checkpoint_freq,
                resume=resume,
                tensorboard=tensorboard,
                progress_bar=progress,
                verbose=verbose,
            )
        )
        result = checked(lambda: train(config))
        if result.interrupted:
            typer.echo(f"interrupted at {result.num_timesteps} steps; checkpoint {result.path}")
            typer.echo(f"  resume  hg-marl train --algo {algo} --resume {result.path} (same options)")
            raise typer.Exit(130)
        typer.echo(
            f"{result.hyperparams.class_name} in the {seat} seat vs {partners} on {scenario}: "
            f"{result.num_timesteps} steps ({result.session_steps} now, {result.steps_per_second:.0f} steps/s)"
        )
        typer.echo(f"  model   {result.path}")
        if seat == "robot":
            typer.echo(f"  use it  hg-marl run --robot sb3 --model {result.path} --human {partners.split(',')[0]}")
        else:
            typer.echo(f"  use it  hg-marl run --human learned:path={out}")


def _train_batched(
    human: str,
    population: Path | None,
    scenario: str,
    steps: int | None,
    seed: int,
    out: Path,
    checkpoint_freq: int | None,
    tensorboard: bool,
    progress: bool,
    hp: list[str] | None,
) -> None:
    """``--algo ppo_batched``: the batched learner in the robot seat."""
    from hg_marl.training.baselines.envs import split_population
    from hg_marl.training.baselines.ppo_batched import config_from_options, population_members, train_ppo_batched

    humans = population_members(population) if population is not None else tuple(split_population(human))
    config = checked(
        lambda: config_from_options(
            humans, scenario, steps, seed, out, checkpoint_freq, tensorboard, progress, tuple(hp or ())
        )
    )
    result = checked(lambda: train_ppo_batched(config))
    typer.echo(
        f"ppo_batched in the robot seat vs {','.join(humans)} on {scenario}: {result.num_timesteps} steps "
        f"({result.steps_per_second:.0f} steps/s, {result.seconds:.0f} s); greedy {result.rate_per_hour:.1f} tasks/h"
    )
    typer.echo(f"  model   {result.path}")
    typer.echo(f"  use it  hg-marl run --robot sb3 --model {result.path} --human {humans[0]}")
