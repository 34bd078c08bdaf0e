"""The ``hg-marl`` console script's first module: its time budget armed before any import.

A person who typed ``--max-seconds 5`` waits from the moment the command started, so the
exact commands count their budget from the process's start (:func:`process_start`). The
command reads the clock only once it runs, after the imports; on a loaded machine the
imports alone can outlast a short budget. So the script arms a timer signal for the
budget first (:func:`arm_startup_budget`), which refuses it in one line with exit 2 if
the process is still starting up then; the command stops the timer when its own budget
takes over.

Why a module of its own, outside the ``hg_marl`` package, importing only the standard
library: importing anything under ``hg_marl`` first runs the package's ``__init__``
(numpy, Gymnasium, PettingZoo and the environment's registration), and the script's own
module imports the command-line stack after it. On two cores busy with fourteen other
processes, those imports took several seconds before the script's first line could arm
anything (docs/exact-references.md).
"""

from __future__ import annotations

import math
import os
import signal
import sys
import time
from typing import Any

MAX_SECONDS = 10_000_000.0
"""The longest wall-time budget a command takes (``--max-seconds``, about 16 weeks): a timer
for 1e23 s is past what the platform's ``setitimer`` holds (an ``OverflowError``), and no
exact computation here runs for weeks."""

SCRIPT: dict[str, Any] = {"started": None, "over_budget": False, "startup_timer": False}
"""The ``hg-marl`` script's state: when its process started (None when a command is called
in-process, as tests do), whether the command was refused over its budget (the script then
leaves at once, without freeing what was computed), and whether the start-up's timer
(:func:`arm_startup_budget`) is armed."""


def process_start() -> float:
    """When this process started, on :func:`time.perf_counter`'s scale (now, if the system cannot say).

    A person who typed ``--max-seconds 5`` counts from the moment the command started, the
    interpreter's start-up and imports included, so the commands measure their budget from
    here. Read from ``/proc/self/stat`` (start time in clock ticks since boot) and
    ``/proc/uptime``, to one clock tick.
    """
    now = time.perf_counter()
    try:
        with open("/proc/self/stat", encoding="ascii") as f:
            ticks = int(f.read().rsplit(")", 1)[1].split()[19])
        with open("/proc/uptime", encoding="ascii") as f:
            uptime = float(f.read().split()[0])
        ran = uptime - ticks / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return now
    return now - ran if 0.0 <= ran < 86_400.0 else now


def given_max_seconds(argv: list[str]) -> float | None:
    """The ``--max-seconds`` value on a command line, if in (0, :data:`MAX_SECONDS`] (the command refuses others)."""
    for i, arg in enumerate(argv):
        text = arg.partition("=")[2] if arg.startswith("--max-seconds=") else None
        if arg == "--max-seconds" and i + 1 < len(argv):
            text = argv[i + 1]
        if text is not None:
            try:
                value = float(text)
            except ValueError:
                return None
            return value if math.isfinite(value) and 0 < value <= MAX_SECONDS else None
    return None


def arm_startup_budget(argv: list[str]) -> None:
    """Under the script, end the process at its ``--max-seconds`` if it is still starting up then.

    The timer signal refuses the budget in one line with exit 2, unless
    :func:`stop_startup_timer` (the command's budget taking over) stopped it first.
    """
    started = SCRIPT["started"]
    budget = given_max_seconds(argv)
    if started is None or budget is None or not hasattr(signal, "setitimer"):
        return

    def expire(signum: int, frame: Any) -> None:
        elapsed = time.perf_counter() - float(started)
        sys.stdout.flush()
        sys.stderr.write(
            f"error: --max-seconds {budget:g}: over the budget of wall time while still starting up "
            f"(after {elapsed:.1f} s: the interpreter and its imports took longer); raise --max-seconds\n"
        )
        sys.stderr.flush()
        os._exit(2)

    signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, max(float(started) + budget - time.perf_counter(), 1e-3))
    SCRIPT["startup_timer"] = True


def stop_startup_timer() -> None:
    """The command's own budget takes over: the start-up's timer, if armed, is stopped."""
    if SCRIPT["startup_timer"]:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        SCRIPT["startup_timer"] = False


def begin(argv: list[str]) -> None:
    """Note the process's start and arm the start-up's timer, once (the first caller wins)."""
    if SCRIPT["started"] is None:
        SCRIPT["started"] = process_start()
        arm_startup_budget(argv)


def script() -> None:
    """The ``hg-marl`` console script: the budget armed, then the command line (``hg_marl.training.cli``)."""
    begin(sys.argv)
    from hg_marl.training.cli import script as command_line

    command_line()
