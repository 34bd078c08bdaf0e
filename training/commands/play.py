"""``hg-marl play``: a person plays the human seat against any robot, in a browser or a terminal."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer


def register(app: typer.Typer) -> None:
    """Add the ``play`` subcommand."""

    @app.command("play")
    def play_command(
        robot: Annotated[
            str, typer.Option(help="Robot spec: planner, habit, hybrid:criterion=vpi, sb3:path=model.json, ...")
        ] = "planner",
        scenario: Annotated[str, typer.Option(help="paper2015, roboergosum, generated:..., or a .toml.")] = (
            "paper2015"
        ),
        seed: Annotated[int, typer.Option(help="Seed of the layouts and the robot.")] = 0,
        record: Annotated[Path | None, typer.Option(help="Directory for the trace (JSONL) of the game.")] = Path(
            "runs/play"
        ),
        player: Annotated[str | None, typer.Option(help="Who plays (written in the trace).")] = None,
        tui: Annotated[bool, typer.Option("--tui", help="Play in the terminal instead of a browser.")] = False,
        port: Annotated[int, typer.Option(help="Port on 127.0.0.1, 0 to 65535 (0: a free one).")] = 0,
        no_browser: Annotated[bool, typer.Option("--no-browser", help="Print the URL only.")] = False,
    ) -> None:
        """Play the human seat yourself; the game is recorded as a trace for replay and cloning."""
        from hg_marl.training.play.session import PlaySession

        frontend = "terminal" if tui else "browser"
        if not tui:
            try:
                import starlette  # noqa: F401
                import uvicorn  # noqa: F401
            except ImportError:
                typer.secho(
                    "error: the browser front end needs the play extra: pip install 'hg-marl[play]' (or use --tui)",
                    fg=typer.colors.RED,
                    err=True,
                )
                raise typer.Exit(2) from None
            from hg_marl.training.play.web import check_port

            check_port(port)
        if record is not None:
            from hg_marl.training.play.session import check_record_dir

            check_record_dir(record)
        session = PlaySession(robot, scenario, seed, record=record, player=player, frontend=frontend)
        if tui:
            from hg_marl.training.play.tui import play_terminal

            summary = play_terminal(session)
        else:
            from hg_marl.training.play.web import Server

            server = Server(session, port)
            typer.echo(f"play at {server.url}  (the URL carries the session's token; Ctrl-C or 'Finish' stops)")
            try:
                server.run(open_browser=not no_browser)
            finally:
                session.close()
            summary = session.summary()
        typer.echo(
            f"{summary['moves']} moves, {summary['tasks_solved']} tasks in {summary['clock']:.1f} simulated s"
            + (f"; trace {summary['trace']}" if summary["trace"] else "")
        )
