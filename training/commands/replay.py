"""``hg-marl replay``: play a recorded trace back against its robot, check it, optionally film it."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer


def register(app: typer.Typer) -> None:
    """Add the ``replay`` subcommand."""

    @app.command("replay")
    def replay_command(
        trace: Annotated[Path, typer.Argument(help="A trace file (JSONL) written by `hg-marl play` or a recorder.")],
        episode: Annotated[int, typer.Option(help="Which episode of the file.")] = 0,
        robot: Annotated[
            str | None, typer.Option(help="Robot spec (default: the one recorded in the trace, else planner).")
        ] = None,
        video: Annotated[Path | None, typer.Option(help="Write the replay as a labelled GIF or MP4.")] = None,
    ) -> None:
        """Replay the human's recorded moves with the same seed and robot; report the rewards."""
        from hg_marl.training.play.replay import replay_trace

        result = replay_trace(trace, episode=episode, robot=robot, video=video)
        typer.echo(
            f"replayed {result.moves} moves of {result.player or 'the recorded human'} against {result.robot} "
            f"on {result.scenario}, seed {result.seed}: {result.tasks_solved} tasks, rewards {result.rewards:g}, "
            f"{result.recorded_clock:.2f} simulated s as recorded (the replay ends its last cycle at "
            f"{result.clock:.2f} s)"
        )
        if result.recorded_rewards is not None:
            same = "same as" if result.recorded_rewards == result.rewards else "DIFFERENT from"
            typer.echo(f"  {same} the recording (rewards {result.recorded_rewards:g})")
        if result.video is not None:
            typer.echo(f"  video {result.video} ({result.frames} frames)")
