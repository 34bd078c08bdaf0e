"""``hg-marl run``: one robot with one human on a scenario, for a simulated duration."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from hg_marl.core.errors import ConfigError
from hg_marl.core.scenario import load_scenario
from hg_marl.core.spec import Spec
from hg_marl.training.commands.common import check_duration, check_out_file, checked, default, spec_with
from hg_marl.training.runner import RunConfig, check_cycles


def robot_label(robot: object, spec: str) -> str:
    """What the summary calls the robot: a hybrid with the criterion it was built with, else its spec."""
    from hg_marl.agents.robots.hybrid import HybridRobot

    if isinstance(robot, HybridRobot) and "criterion=" not in spec:
        return f"{spec}({robot.meta.criterion.name})"
    return spec


def register(app: typer.Typer) -> None:
    """Add the ``run`` subcommand."""

    @app.command("run")
    def run_command(
        robot: Annotated[
            str, typer.Option(help="Robot agent, with parameters if any: hybrid:criterion=vpi (see --list).")
        ] = "hybrid",
        criterion: Annotated[
            str | None,
            typer.Option(help="MetaController criterion (hybrid robot only; default entropy_and_cost), e.g. vpi."),
        ] = None,
        human: Annotated[str, typer.Option(help="Human partner (see `hg-marl run --list`).")] = "cooperative",
        scenario: Annotated[
            str, typer.Option(help="paper2015, roboergosum, generated:..., or a .toml path.")
        ] = default(RunConfig, "scenario"),
        duration: Annotated[float, typer.Option(help="Simulated seconds.")] = default(RunConfig, "duration"),
        seed: Annotated[int, typer.Option(min=0, help="Seed of the layouts and of both actors.")] = default(
            RunConfig, "seed"
        ),
        model: Annotated[Path | None, typer.Option(help="Trained SB3 model (robot sb3).")] = None,
        robot_param: Annotated[list[str] | None, typer.Option("--robot-param", help="key=value for the robot.")] = None,
        human_param: Annotated[list[str] | None, typer.Option("--human-param", help="key=value for the human.")] = None,
        out: Annotated[Path | None, typer.Option(help="Write the per-decision log (CSV) here.")] = None,
        video: Annotated[
            Path | None, typer.Option(help="Write the run as a labelled GIF or MP4 (one frame per cycle).")
        ] = None,
        list_agents: Annotated[
            bool, typer.Option("--list", help="List robots, criteria and humans, then exit.")
        ] = False,
    ) -> None:
        """Play a robot with a human for a fixed simulated duration and print a summary."""
        from tqdm import tqdm

        from hg_marl.agents.humans import available_humans, make_human
        from hg_marl.agents.meta import available_criteria
        from hg_marl.agents.robots import available_robots, make_robot
        from hg_marl.training.runner import RunConfig, run

        if list_agents:
            typer.echo(f"robots:   {', '.join(available_robots())}")
            typer.echo(f"criteria: {', '.join(available_criteria())}")
            typer.echo(f"humans:   {', '.join(available_humans())}")
            return
        duration = check_duration(duration)
        check_out_file(out, "--out")
        robot_spec = spec_with(robot, robot_param, "--robot", "--robot-param")
        robot_kwargs: dict[str, object] = {}
        if criterion is not None:  # given: it must take effect, never be dropped silently
            if robot_spec.name != "hybrid":
                raise ConfigError(f"--criterion {criterion}: only for --robot hybrid, not {robot_spec.name}")
            if "criterion" in robot_spec.raw:
                raise ConfigError("--criterion and --robot/--robot-param both set criterion")
            # a shorthand for --robot-param criterion=...: one spec carries every robot parameter
            robot_spec = Spec(robot_spec.name, {**robot_spec.raw, "criterion": criterion})
        if model is not None:
            if robot_spec.name not in ("sb3", "memory"):
                raise ConfigError(f"--model is for --robot sb3 or memory, not {robot_spec.name}")
            robot_kwargs["path"] = str(model)
        the_robot = checked(lambda: make_robot(robot_spec, **robot_kwargs))
        the_human = checked(lambda: make_human(spec_with(human, human_param, "--human", "--human-param")))
        config = RunConfig(scenario=scenario, duration=duration, seed=seed)
        # A bad scenario, or a run too long for its durations, fails before the progress bar starts.
        check_cycles(duration, load_scenario(scenario).durations.shortest)
        recorder = None
        if video is not None:
            from hg_marl.training.video import FrameRecorder, check_video_path

            check_video_path(video)
            recorder = FrameRecorder(the_robot)
        with tqdm(total=int(duration), unit="sim s", desc=f"{robot} + {human}", leave=False) as bar:

            def progress(clock: float) -> None:
                bar.update(int(min(clock, duration)) - bar.n)

            result = checked(lambda: run(recorder or the_robot, the_human, config, on_decision=progress))
        s = result.summary
        label = robot_label(the_robot, robot)
        typer.echo(f"robot {label} with human {human} on {scenario}, seed {seed}, {duration:.0f} simulated s")
        typer.echo(f"  tasks solved     {s['tasks_solved']}")
        typer.echo(f"  robot actions    {s['actions']} ({s['failed_actions']} failed)")
        typer.echo(f"  planner share    {s['planner_share']:.2f}")
        typer.echo(f"  simulated time   {s['simulated_time']:.1f} s")
        if out is not None:
            typer.echo(f"  log              {result.save(out)}")
        if recorder is not None and video is not None:
            from hg_marl.training.video import write_video

            written = write_video(recorder.frames, video)
            typer.echo(f"  video            {written} ({len(recorder.frames)} frames)")
