"""The terminal front end: the same :class:`PlaySession` in a text UI (rich), no browser needed.

Each turn shows the table as text, the robot's last move (and the MetaController's
numbers for a hybrid), then the person's feasible actions with their keys; the person
types a key (or an action's name) and Enter; ``q`` ends the game and saves the trace.
"""

from __future__ import annotations

from collections.abc import Callable

from rich.console import Console
from rich.table import Table

from hg_marl.core.errors import HgMarlError
from hg_marl.envs.render import render_ansi
from hg_marl.training.play.session import PlaySession

QUIT = "q"


def show(session: PlaySession, console: Console) -> None:
    """Print the current turn: table, robot's move, choices."""
    console.print(render_ansi(session.world, session.state, session.clock, session.cycle, session.tasks_solved))
    r = session.last_robot
    if r is not None:
        failed = " [red](failed)[/red]" if r.failed else ""
        console.print(f"robot: [bold]{r.name}[/bold]{failed} by {r.expert}, decided in {r.decision_time:.2f} s")
        if r.weights:
            console.print("  MetaController: " + ", ".join(f"{k}={v:.3f}" for k, v in r.weights.items()))
    if session.last_human:
        console.print(f"you:   {session.last_human}")
    table = Table(show_header=False, box=None, padding=(0, 1))
    for c in session.choices():
        table.add_row(f"[bold cyan]{c.key}[/bold cyan]", c.name)
    console.print(table)


def play_terminal(
    session: PlaySession, console: Console | None = None, read: Callable[[str], str] | None = None
) -> dict[str, object]:
    """Play until ``q`` (or end of input); returns the session's summary.

    Args:
        session: the game.
        console: where to print (default: the terminal).
        read: reads one line given a prompt (default: ``console.input``); tests script it.
    """
    console = console or Console()
    read = read or console.input
    while True:
        show(session, console)
        try:
            answer = read(f"your move (key, action name, or {QUIT} to finish): ").strip()
        except EOFError:
            break
        if answer == QUIT:
            break
        keys = {c.key: c.index for c in session.choices()}
        try:
            session.play(keys.get(answer, answer))
        except HgMarlError as exc:
            console.print(f"[red]{exc}[/red]")
    path = session.close()
    if path is not None:
        console.print(f"trace saved: {path}")
    return session.summary()
