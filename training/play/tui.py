"""The terminal front end: the same :class:`PlaySession` in a text UI (rich), no browser needed.

One screen, redrawn in place (rich's ``Live``) after every move: the scenario's rules,
the table as text, what is pending (an offer, your turn), a message when a task is
solved, what the robot did and why (the same words as the web page, from
:mod:`~hg_marl.training.play.explain`), then the person's feasible actions with their
keys. One key per move, no Enter (the terminal is in cbreak mode for the whole game;
from a pipe, characters are read one at a time and newlines skipped). A key that
is not offered is answered with the feasible actions only. ``q`` ends the game, saves
the trace and prints the summary.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager, nullcontext

from rich.console import Console, Group, RenderableType
from rich.live import Live
from rich.table import Table
from rich.text import Text

from hg_marl.envs.render import render_ansi
from hg_marl.training.play import explain
from hg_marl.training.play.session import PlaySession

QUIT = "q"


def read_key() -> str:
    """One key from standard input ("" at end of input); newlines are skipped, so a
    pipe's ``1\nq\n`` plays like the keys ``1`` then ``q``."""
    while True:
        key = sys.stdin.read(1)
        if key not in ("\n", "\r"):
            return key


@contextmanager
def keys_without_enter() -> Iterator[None]:
    """Put a terminal on standard input in cbreak mode (keys arrive as typed) for the
    whole game, so no key typed between two reads waits for Enter; restored on exit."""
    if not sys.stdin.isatty():
        yield
        return
    import termios
    import tty

    fd = sys.stdin.fileno()
    old = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd)
        yield
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, old)


def screen(session: PlaySession, message: str = "") -> RenderableType:
    """The whole screen for the current turn; ``message`` answers the last key."""
    world = session.world
    parts: list[RenderableType] = [Text(" ".join(explain.intro(world)[1:]), style="dim")]  # no "top" here
    parts.append(Text(render_ansi(world, session.state, session.clock, session.cycle, session.tasks_solved)))
    if session.just_solved:
        n = session.tasks_solved
        parts.append(Text(f"Task solved! {n} so far, at t = {session.solved_at[-1]:.1f} s.", style="bold green"))
    r = session.last_robot
    if r is not None:
        lines = explain.why(r)
        parts.append(Text("robot: " + lines[0], style="bold"))
        parts.extend(Text("  " + line) for line in lines[1:])
    if session.last_human:
        parts.append(Text(f"you:   {session.last_human}"))
    parts.append(Text(explain.pending(world, session.state, session.last_human, r.name if r else ""), style="bold"))
    table = Table(show_header=False, box=None, padding=(0, 1))
    for c in session.choices():
        table.add_row(Text(c.key, style="bold cyan"), c.name)
    table.add_row(Text(QUIT, style="bold cyan"), "finish and save")
    parts.append(table)
    if message:
        parts.append(Text(message, style="red"))
    return Group(*parts)


def play_terminal(
    session: PlaySession, console: Console | None = None, read: Callable[[], str] | None = None
) -> dict[str, object]:
    """Play until ``q`` (or end of input); returns the session's summary.

    Args:
        session: the game.
        console: where to draw (default: the terminal).
        read: returns the next key ("" at end of input; default :func:`read_key`); tests script it.
    """
    console = console or Console()
    message = ""
    # "visible": on a short terminal (24 lines) the screen after a move is taller than the window,
    # and the default cut would hide the menu of moves; the top scrolls away instead
    live = Live(
        screen(session), console=console, auto_refresh=False, redirect_stdout=False, vertical_overflow="visible"
    )
    with keys_without_enter() if read is None else nullcontext(), live:
        while True:
            key = read() if read is not None else read_key()
            if key in ("", QUIT):
                break
            keys = {c.key: c for c in session.choices()}
            choice = keys.get(key)
            if choice is None:
                offered = ", ".join(f"{c.key} {c.name}" for c in keys.values())
                message = f"{key!r} is not a key here; your moves: {offered}; {QUIT} finishes"
            else:
                session.play(choice.index)
                message = ""
            live.update(screen(session, message), refresh=True)
    path = session.close()
    console.print(session.summary_text(), highlight=False, markup=False)
    if path is not None:
        console.print(f"trace saved: {path}", highlight=False, markup=False)
    return session.summary()
