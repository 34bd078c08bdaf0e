"""One budget for every exact-model computation: states, bytes and wall seconds, checked in every phase.

An exact reference (the oracle, the headroom matrix) goes through phases: counting the
layouts, enumerating them, the partner's first answers on them, exploring the model,
solving it. Each phase calls :meth:`Budget.check` with how far it got, often enough that
the work between two calls is small (a few thousand cheap items, or one partner answer);
a refusal is one line, :class:`OverBudget`, naming the budget, the phase and the progress.

Wall time, not CPU time: a user waiting on ``--max-seconds 5`` waits on the clock on the
wall. A single partner answer may itself be long (a planner search on a large table), so
on the main thread :meth:`Budget.deadline` also arms a real-time timer that raises the same
refusal where the work happens to be when the time runs out; the budget therefore holds
within its seconds plus the time to unwind, whatever the phase. Off the main thread
(no signals there) the checks alone hold it.

Tests count work, not seconds: ``clock`` may be any function returning seconds (a test
passes one that advances by one per call), and the states budget counts states.
"""

from __future__ import annotations

import ctypes
import functools
import math
import multiprocessing
import os
import signal
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from types import FrameType

from hg_marl.core.errors import check_finite
from hg_marl_start import MAX_SECONDS as MAX_SECONDS  # (their home: the script's first module)
from hg_marl_start import process_start as process_start

DEFAULT_SECONDS: float | None = None
"""The library's default wall-time budget: none, so that what a study, a robot or a report
computes (and stores) never depends on how loaded the machine was. The commands take an
explicit ``--max-seconds`` (a person waiting at a terminal), and the states and memory
budgets bound every build."""
DEFAULT_MEMORY = 4 * 2**30
"""The default resident memory budget (bytes) of the process and its workers during a solve."""
DEFAULT_STATES = 1_500_000
"""The default states budget of one model."""
MIN_FREE_BYTES = 512 * 2**20
"""Below this much memory available to the kernel, a build stops whatever its own budget."""
RING_AT_ONCE = 1e-6
"""Seconds to an outer timer put back after :meth:`Budget.deadline` whose moment passed in the
block (a timer of 0 would be none)."""


class OverBudget(RuntimeError):
    """A computation stopped at its budget; the message is one line naming budget, phase and progress.

    ``resource`` says which budget stopped it (``states``, ``seconds``, ``memory``, or ``machine``
    where the machine itself had too little memory left; empty where unsaid), so a caller that
    words one refusal its own way (the compiler's ``max_keys``) does not give that reason for another.
    """

    def __init__(self, message: str, resource: str = "") -> None:
        super().__init__(message)
        self.resource = resource

    def __reduce__(self) -> tuple[type[OverBudget], tuple[str, str]]:
        """Pickled with its resource (a forked worker's refusal reaches the parent whole)."""
        return (OverBudget, (str(self), self.resource))


@functools.cache
def _malloc_trim() -> Callable[[int], int] | None:
    """glibc's ``malloc_trim``, or None where the C library has none (musl, macOS)."""
    try:
        return ctypes.CDLL(None).malloc_trim
    except (OSError, AttributeError):
        return None


TRIM_BYTES = 256 * 2**20
"""Freed bytes below which :func:`trim_heap` keeps the pages: pages given back are faulted in
again by the next build in the process, which costs a small model's build more than the
pages are worth."""


def trim_heap(freed: int) -> None:
    """Give the C heap's free pages back to the system, where the C library can, once ``freed`` bytes were freed.

    Why: a model is built from thousands of batch arrays small enough for malloc's heap
    (only large ones are mapped on their own). Once they are joined into the model and
    freed, glibc keeps most of their pages, so the process would stay as large as the
    build's peak through the solve that follows, and the memory budget, which reads
    resident bytes, would count pages that hold nothing. ``malloc_trim(0)`` returns every
    free page it can; elsewhere this does nothing.
    """
    trim = _malloc_trim()
    if trim is not None and freed >= TRIM_BYTES:
        trim(0)


def rss() -> int:
    """Resident bytes of this process and of the worker processes it started.

    A computation spread over forked workers (``--jobs``) is one computation: its memory is
    this process's resident size (``/proc/self/statm``; peak ``ru_maxrss`` elsewhere) plus
    what each live child holds on its own (:func:`private_bytes`; the pages it still shares
    with this process copy-on-write are counted once, here).
    """
    try:
        with open("/proc/self/statm", encoding="ascii") as f:
            own = int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        import resource

        own = int(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss) * 1024
    return own + sum(private_bytes(child.pid) for child in multiprocessing.active_children() if child.pid)


def private_bytes(pid: int) -> int:
    """The resident bytes process ``pid`` maps alone (``Private_Clean`` + ``Private_Dirty``; 0 if unknown).

    Read from ``/proc/PID/smaps_rollup``: a forked worker's pages that its parent maps too are
    "shared" there until either writes them.
    """
    total = 0
    try:
        with open(f"/proc/{pid}/smaps_rollup", encoding="ascii") as f:
            for line in f:
                if line.startswith(("Private_Clean:", "Private_Dirty:")):
                    total += int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        return 0
    return total


def available_bytes() -> int | None:
    """Memory the kernel says is available (Linux ``MemAvailable``), or None if unknown."""
    try:
        with open("/proc/meminfo", encoding="ascii") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        return None
    return None


@dataclass
class Budget:
    """What one exact computation may spend (None: no limit on that resource).

    Args:
        seconds: wall seconds from ``start``.
        memory: resident bytes of the process and its workers (:func:`rss`).
        states: model states (a phase reports them with ``states=``).
        subject: how the refusal names the computation (``"the oracle for 'paper2015'"``).
        hint: the advice closing a refusal.
        clock: the clock ``seconds`` is measured on (tests pass a counter).
    """

    seconds: float | None = DEFAULT_SECONDS
    memory: int | None = DEFAULT_MEMORY
    states: int | None = DEFAULT_STATES
    subject: str = "the computation"
    hint: str = "raise the budget or use a smaller scenario"
    clock: Callable[[], float] = time.perf_counter
    start: float = field(default=math.nan)
    phase: str = "start"
    """The phase under way (the last one :meth:`check` was told of)."""
    progress: str = ""
    """How far that phase got, in words."""
    checks: int = 0
    """How many times :meth:`check` was called (tests count phases with it)."""
    free_memory: Callable[[], int | None] = available_bytes

    def __post_init__(self) -> None:
        if self.seconds is not None:
            self.seconds = check_finite(self.seconds, "--max-seconds", positive=True, maximum=MAX_SECONDS)
        if math.isnan(self.start):
            self.start = self.clock()

    def spent(self) -> float:
        """Seconds since ``start`` on ``clock``."""
        return self.clock() - self.start

    def check(
        self,
        phase: str,
        done: int,
        total: int | None = None,
        unit: str = "states",
        *,
        states: int | None = None,
        memory: bool = True,
    ) -> None:
        """Raise :class:`OverBudget` if over any budget; record where the work is either way.

        ``done`` (of ``total``) ``unit`` tell how far ``phase`` got; ``states``: the model's
        states so far (checked against the states budget); ``memory``: read the resident
        memory too (a system call: callers checking very often pass False most times).
        """
        self.checks += 1
        self.phase = phase
        self.progress = f"{done:,} of {total:,} {unit}" if total is not None else f"{done:,} {unit}"
        if self.states is not None and states is not None and states > self.states:
            self._refuse(f"max_states={self.states:,} states ({states:,} states)", "--max-states", "states")
        if self.seconds is not None:
            spent = self.spent()
            if spent > self.seconds:
                self._refuse(f"{self.seconds:g} s of wall time (after {spent:.1f} s)", "--max-seconds", "seconds")
        if memory:
            if self.memory is not None and rss() > self.memory:
                self._refuse(f"{self.memory / 2**30:g} GB of memory", "--max-memory", "memory")
            free = self.free_memory()
            if free is not None and free < MIN_FREE_BYTES:
                self._refuse(
                    f"the machine: less than {MIN_FREE_BYTES // 2**20} MB of memory left", "--max-states", "machine"
                )

    def refuse_count(self, phase: str, count: int, unit: str) -> None:
        """Refuse before a phase that would enumerate ``count`` items, more than the states budget."""
        if self.states is not None and count > self.states:
            self.phase, self.progress = phase, f"0 of {count:,} {unit}"
            self._refuse(f"max_states={self.states:,} ({count:,} {unit} to enumerate)", "--max-states", "states")

    def _refuse(self, what: str, option: str, resource: str) -> None:
        raise OverBudget(
            f"{self.subject} is over its budget of {what} in phase {self.phase!r} ({self.progress}); "
            f"raise {option} or {self.hint}",
            resource,
        )

    @contextmanager
    def deadline(self) -> Iterator[None]:
        """Within the block, a real-time timer refuses at the time budget wherever the work is.

        Only on the main thread (where signals are delivered); elsewhere, and with no time
        budget, the block runs with the checks alone. The previous handler is restored on
        exit, and a previous timer is put back with the block's seconds taken off it.
        """
        if (
            self.seconds is None
            or threading.current_thread() is not threading.main_thread()
            or self.clock is not time.perf_counter
        ):
            yield
            return
        left = max(self.seconds - self.spent(), 0.0) + 0.05

        def ring(signum: int, frame: FrameType | None) -> None:
            self._refuse(f"{self.seconds:g} s of wall time (after {self.spent():.1f} s)", "--max-seconds", "seconds")

        previous = signal.signal(signal.SIGALRM, ring)
        entered = self.clock()
        old_delay, old_interval = signal.setitimer(signal.ITIMER_REAL, left)
        try:
            yield
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, previous)
            if old_delay > 0:
                # The outer timer lost the block's time too: it rings when it would have,
                # at once if that moment passed during the block (never later, never lost).
                rest = max(old_delay - (self.clock() - entered), RING_AT_ONCE)
                signal.setitimer(signal.ITIMER_REAL, rest, old_interval)
