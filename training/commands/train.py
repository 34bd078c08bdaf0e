"""``hg-marl train``: one subcommand per algorithm family.

- ``hg-marl train sb3``: a Stable-Baselines3 algorithm (ppo, a2c, dqn, maskable_ppo, recurrent_ppo) in
  the robot seat against humans, or in the human seat against a robot;
- ``hg-marl train ppo-batched``: the batched PPO learner in the robot seat;
- ``hg-marl train bc``: behaviour cloning of recorded play (a ``learned`` human).

The older form ``hg-marl train --algo ALGO [options]`` (``--algo bc`` and
``--algo ppo_batched`` included) is kept as an alias for a release: it takes every
option of the three and runs the same code. torch and SB3 are imported inside the
command bodies only, so ``hg-marl --help`` stays fast.
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

# ---- options, declared once and shared by the subcommands and the old form -------------------
Seat = Annotated[str, typer.Option(help="robot (against humans) or human (against a robot).")]
Human = Annotated[
    str, typer.Option(help="Robot seat: human(s) to train against; a comma list is a population drawn per episode.")
]
Robot = Annotated[
    str,
    typer.Option(
        help="Human seat: the fixed robot(s) (comma list), live, one per env: the robots runs and studies play "
        "(the batched human seat, HumanTableCleaning-v0's vector entry point, compiles the planner instead)."
    ),
]
EffortWeight = Annotated[float, typer.Option(help="Human seat: reward minus this x seconds of work.")]
ScenarioOpt = Annotated[str, typer.Option(help="paper2015, roboergosum, generated:..., or a .toml.")]
Steps = Annotated[int | None, typer.Option(help="Total environment steps (default: the YAML's).")]
Seed = Annotated[int, typer.Option(min=0, help="Seed of the model and the training tables.")]
Out = Annotated[Path, typer.Option(help="Output directory.")]
Hp = Annotated[list[str] | None, typer.Option("--hp", help="Hyperparameter override key=value.")]
Hyperparams = Annotated[Path | None, typer.Option(help="YAML file instead of the packaged one.")]
Observation = Annotated[str, typer.Option(help="View observation: facts, flat or dict.")]
MaxCycles = Annotated[int, typer.Option(min=1, help="Training episode length in cycles.")]
EvalFreq = Annotated[int, typer.Option(min=0, help="Steps between evaluations (0: none).")]
EvalEpisodes = Annotated[int, typer.Option(min=1, help="Episodes per evaluation.")]
CheckpointFreq = Annotated[
    int | None,
    typer.Option(min=0, help="Steps between checkpoints (default: a tenth of --steps, whole rollouts; 0: none)."),
]
Resume = Annotated[
    Path | None, typer.Option(help="Checkpoint (.json) to continue: keeps its steps and optimizer state.")
]
Traces = Annotated[list[Path] | None, typer.Option("--traces", help="bc: trace files or directories (repeat).")]
BcKind = Annotated[str, typer.Option(help="bc: table or linear_softmax.")]
Population = Annotated[
    Path | None, typer.Option(help="ppo_batched: a population file; trains against its train members.")
]
Recipe = Annotated[
    str, typer.Option(help="ppo_recurrent: population recipe: members, fcp, fcp_init, hsp, e3t or coverage.")
]
Tensorboard = Annotated[bool, typer.Option(help="Write TensorBoard logs to OUT/tb.")]
Progress = Annotated[bool, typer.Option(help="Show a progress bar.")]
Verbose = Annotated[int, typer.Option(help="SB3 verbosity.")]

D_EFFORT = default(EnvSpec, "effort_weight")
D_SCENARIO = default(EnvSpec, "scenario")
D_SEED = default(TrainConfig, "seed")
D_OBSERVATION = default(EnvSpec, "observation")
D_MAX_CYCLES = default(EnvSpec, "max_cycles")
D_EVAL_FREQ = default(TrainConfig, "eval_freq")
D_EVAL_EPISODES = default(TrainConfig, "eval_episodes")
D_TENSORBOARD = default(TrainConfig, "tensorboard")
D_VERBOSE = default(TrainConfig, "verbose")


def register(app: typer.Typer) -> None:
    """Add the ``train`` group: ``sb3``, ``ppo-batched``, ``bc``, and the old ``--algo`` form."""
    train = typer.Typer(
        help="Train a learner on a seat of the table: sb3, ppo-batched or bc (or the older --algo form).",
        no_args_is_help=False,
        add_completion=False,
    )

    @train.callback(invoke_without_command=True)
    def train_command(
        ctx: typer.Context,
        algo: Annotated[
            str,
            typer.Option(
                help="ppo, a2c, dqn, maskable_ppo, ppo_batched (batched tables), ppo_recurrent (batched, with "
                "memory), or bc (behaviour cloning)."
            ),
        ] = "maskable_ppo",
        seat: Seat = "robot",
        human: Human = "cooperative",
        robot: Robot = "planner",
        effort_weight: EffortWeight = D_EFFORT,
        scenario: ScenarioOpt = D_SCENARIO,
        steps: Steps = None,
        seed: Seed = D_SEED,
        out: Out = DEFAULT_OUT,
        hp: Hp = None,
        hyperparams: Hyperparams = None,
        observation: Observation = D_OBSERVATION,
        max_cycles: MaxCycles = D_MAX_CYCLES,
        eval_freq: EvalFreq = D_EVAL_FREQ,
        eval_episodes: EvalEpisodes = D_EVAL_EPISODES,
        checkpoint_freq: CheckpointFreq = None,
        resume: Resume = None,
        traces: Traces = None,
        bc_kind: BcKind = "table",
        population: Population = None,
        recipe: Recipe = "members",
        tensorboard: Tensorboard = D_TENSORBOARD,
        progress: Progress = True,
        verbose: Verbose = D_VERBOSE,
    ) -> None:
        """Train an SB3 algorithm on a seat of the table (or clone recorded play with --algo bc).

        The older form, kept as an alias: ``train sb3``, ``train ppo-batched`` and
        ``train bc`` take the options of their family only.
        """
        if ctx.invoked_subcommand is not None:
            return
        if algo == "bc":
            train_bc(traces, bc_kind, out, "--algo bc")
        elif algo == "ppo_batched":
            train_ppo_batched(human, population, scenario, steps, seed, out, checkpoint_freq, tensorboard, progress, hp)
        elif algo == "ppo_recurrent":
            train_ppo_recurrent(human, population, scenario, recipe, steps, seed, out, checkpoint_freq, progress, hp)
        else:
            train_sb3(
                algo, seat, human, robot, effort_weight, scenario, steps, seed, out, hp, hyperparams, observation,
                max_cycles, eval_freq, eval_episodes, checkpoint_freq, resume, tensorboard, progress, verbose,
            )  # fmt: skip

    @train.command("sb3")
    def sb3_command(
        algo: Annotated[
            str, typer.Option(help="ppo, a2c, dqn, maskable_ppo or recurrent_ppo (sb3-contrib's LSTM PPO, unmasked).")
        ] = "maskable_ppo",
        seat: Seat = "robot",
        human: Human = "cooperative",
        robot: Robot = "planner",
        effort_weight: EffortWeight = D_EFFORT,
        scenario: ScenarioOpt = D_SCENARIO,
        steps: Steps = None,
        seed: Seed = D_SEED,
        out: Out = DEFAULT_OUT,
        hp: Hp = None,
        hyperparams: Hyperparams = None,
        observation: Observation = D_OBSERVATION,
        max_cycles: MaxCycles = D_MAX_CYCLES,
        eval_freq: EvalFreq = D_EVAL_FREQ,
        eval_episodes: EvalEpisodes = D_EVAL_EPISODES,
        checkpoint_freq: CheckpointFreq = None,
        resume: Resume = None,
        tensorboard: Tensorboard = D_TENSORBOARD,
        progress: Progress = True,
        verbose: Verbose = D_VERBOSE,
    ) -> None:
        """A Stable-Baselines3 algorithm on a seat of the table (single-table views)."""
        if algo in ("bc", "ppo_batched", "ppo_recurrent"):
            raise typer.BadParameter(f"--algo {algo}: use `hg-marl train {algo.replace('_', '-')}`")
        train_sb3(
            algo, seat, human, robot, effort_weight, scenario, steps, seed, out, hp, hyperparams, observation,
            max_cycles, eval_freq, eval_episodes, checkpoint_freq, resume, tensorboard, progress, verbose,
        )  # fmt: skip

    @train.command("ppo-batched")
    def ppo_batched_command(
        human: Human = "cooperative",
        population: Population = None,
        scenario: ScenarioOpt = D_SCENARIO,
        steps: Steps = None,
        seed: Seed = D_SEED,
        out: Out = DEFAULT_OUT,
        checkpoint_freq: CheckpointFreq = None,
        tensorboard: Tensorboard = D_TENSORBOARD,
        progress: Progress = True,
        hp: Hp = None,
    ) -> None:
        """The batched PPO learner in the robot seat (many tables per step, partners compiled)."""
        train_ppo_batched(human, population, scenario, steps, seed, out, checkpoint_freq, tensorboard, progress, hp)

    @train.command("ppo-recurrent")
    def ppo_recurrent_command(
        human: Human = "cooperative",
        population: Population = None,
        scenario: ScenarioOpt = D_SCENARIO,
        recipe: Recipe = "members",
        steps: Steps = None,
        seed: Seed = D_SEED,
        out: Out = DEFAULT_OUT,
        checkpoint_freq: CheckpointFreq = None,
        progress: Progress = True,
        hp: Hp = None,
    ) -> None:
        """Masked PPO with memory (a GRU, or an MLP on the history) in the robot seat, batched tables."""
        train_ppo_recurrent(human, population, scenario, recipe, steps, seed, out, checkpoint_freq, progress, hp)

    @train.command("bc")
    def bc_command(
        traces: Traces = None,
        kind: Annotated[str, typer.Option(help="table or linear_softmax.")] = "table",
        out: Out = DEFAULT_OUT,
    ) -> None:
        """Behaviour cloning of recorded play into a ``learned`` human."""
        train_bc(traces, kind, out, "train bc")

    app.add_typer(train, name="train")


def train_bc(traces: list[Path] | None, kind: str, out: Path, form: str) -> None:
    """Clone the recorded play of ``traces`` into a policy in ``out``."""
    check_out_dir(out, "--out")
    from hg_marl.training.baselines.bc import behaviour_clone

    if not traces:
        raise typer.BadParameter(f"{form} needs at least one --traces FILE")
    path, accuracy = checked(lambda: behaviour_clone(traces, out, kind=kind))
    typer.echo(f"behaviour cloning ({kind}): reproduces {accuracy:.1%} of the recorded actions")
    typer.echo(f"  policy  {path}  (make_human('learned', path='{path}'))")


def train_sb3(
    algo: str,
    seat: str,
    human: str,
    robot: str,
    effort_weight: float,
    scenario: str,
    steps: int | None,
    seed: int,
    out: Path,
    hp: list[str] | None,
    hyperparams: Path | None,
    observation: str,
    max_cycles: int,
    eval_freq: int,
    eval_episodes: int,
    checkpoint_freq: int | None,
    resume: Path | None,
    tensorboard: bool,
    progress: bool,
    verbose: int,
) -> None:
    """An SB3 algorithm on ``seat`` against ``human`` (robot seat) or ``robot`` (human seat)."""
    check_out_dir(out, "--out")
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
    if seat == "human":
        typer.echo(
            f"human seat: training against live {partners} robot(s), one per env (the robots runs and studies play)"
        )
    result = checked(lambda: train(config))
    if result.interrupted:
        typer.echo(f"interrupted at {result.num_timesteps} steps; checkpoint {result.path}")
        typer.echo(f"  resume  hg-marl train sb3 --algo {algo} --resume {result.path} (same options)")
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


def train_ppo_batched(
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
    """The batched learner in the robot seat."""
    check_out_dir(out, "--out")
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


def train_ppo_recurrent(
    human: str,
    population: Path | None,
    scenario: str,
    recipe: str,
    steps: int | None,
    seed: int,
    out: Path,
    checkpoint_freq: int | None,
    progress: bool,
    hp: list[str] | None,
) -> None:
    """The recurrent batched learner in the robot seat, against a population recipe."""
    check_out_dir(out, "--out")
    from hg_marl.training.baselines.envs import split_population
    from hg_marl.training.baselines.heldout_curve import held_out_members
    from hg_marl.training.baselines.ppo_batched import population_members
    from hg_marl.training.baselines.ppo_recurrent import train_from_options

    members = population_members(population) if population is not None else tuple(split_population(human))
    held_out = held_out_members(population) if population is not None else ()
    args = (members, scenario, recipe, steps, seed, out, checkpoint_freq, progress, tuple(hp or ()), held_out)
    for line in checked(lambda: train_from_options(*args)):
        typer.echo(line)
