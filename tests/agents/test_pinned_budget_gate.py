"""The model budget's memory readings, refusal line and wall-time timer, pinned for the mutation gate.

Expected values from independent readings: the resident size is pages times the page
size (a Python process with numpy holds more than 8 MB, and about its peak);
the available memory is ``/proc/meminfo``'s ``MemAvailable`` in kB times 1024; the
machine's floor is 512 MB; the timer is armed for the time left plus 0.05 s (so at most
``seconds + 0.05``) and disarmed on leaving the block. Nothing here is timed.
"""

from __future__ import annotations

import multiprocessing
import re
import resource
import signal
import sys
from pathlib import Path

import pytest

from hg_marl.agents.models.budget import Budget, OverBudget, available_bytes, rss

LINUX = sys.platform.startswith("linux")


@pytest.mark.skipif(not LINUX, reason="/proc is Linux's")
def test_resident_size_is_in_bytes() -> None:
    value = rss()
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    assert 8 * 2**20 < value <= 2 * peak  # pages are counted a little differently from the peak


@pytest.mark.skipif(not LINUX, reason="/proc and fork are Linux's")
def test_resident_size_counts_what_a_live_worker_holds_on_its_own_and_forgets_it_once_gone() -> None:
    """A forked worker that writes 64 MB adds at least that to :func:`rss` while it lives, nothing once joined."""
    ctx = multiprocessing.get_context("fork")
    ready_r, ready_w = ctx.Pipe(False)
    stop_r, stop_w = ctx.Pipe(False)
    block = 64 * 2**20

    def hold() -> None:
        data = bytearray(b"x") * block  # written, so resident and the worker's own
        ready_w.send(len(data))
        stop_r.recv()

    before = rss()
    worker = ctx.Process(target=hold)
    worker.start()
    try:
        assert ready_r.poll(300) and ready_r.recv() == block
        during = rss()
    finally:
        stop_w.send(None)
        worker.join()
    after = rss()
    assert during - before >= block
    assert abs(after - before) < 32 * 2**20


@pytest.mark.skipif(not LINUX, reason="/proc is Linux's")
def test_available_memory_is_memavailable() -> None:
    text = Path("/proc/meminfo").read_text()
    kb = int(re.search(r"^MemAvailable:\s+(\d+) kB", text, re.MULTILINE).group(1))  # type: ignore[union-attr]
    value = available_bytes()
    assert value is not None
    assert abs(value - kb * 1024) <= 64 * 2**20  # two readings of a live figure


def test_a_machine_short_of_memory_is_refused_with_its_floor_in_mb() -> None:
    budget = Budget(None, None, None, free_memory=lambda: 0)
    with pytest.raises(OverBudget, match=r"less than 512 MB of memory left"):
        budget.check("explore", 1, memory=True)


@pytest.mark.skipif(not hasattr(signal, "setitimer"), reason="no interval timer")
def test_the_timer_is_armed_for_the_time_left_and_disarmed_after() -> None:
    budget = Budget(2.0, None, None)
    with budget.deadline():
        delay, interval = signal.getitimer(signal.ITIMER_REAL)
        assert 0.0 < delay <= 2.05 and interval == 0.0
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
