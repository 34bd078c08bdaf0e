"""The model budget's memory readings, refusal line and wall-time timer, pinned for the mutation gate.

Expected values from independent readings: the resident size is pages times the page
size (a Python process with numpy holds more than 8 MB, and about its peak);
the available memory is ``/proc/meminfo``'s ``MemAvailable`` in kB times 1024; the
machine's floor is 512 MB; the timer is armed for the time left plus 0.05 s (so at most
``seconds + 0.05``) and disarmed on leaving the block. Nothing here is timed.
"""

from __future__ import annotations

import multiprocessing
import os
import re
import resource
import signal
import sys
from pathlib import Path

import pytest

from hg_marl.agents.models.budget import MIN_FREE_BYTES, Budget, OverBudget, available_bytes, private_bytes, rss

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


@pytest.mark.skipif(not LINUX, reason="/proc is Linux's")
def test_private_bytes_are_the_private_lines_of_smaps_rollup_in_bytes() -> None:
    text = Path("/proc/self/smaps_rollup").read_text()
    kb = sum(int(m) for m in re.findall(r"^Private_(?:Clean|Dirty):\s+(\d+) kB", text, re.MULTILINE))
    assert abs(private_bytes(os.getpid()) - kb * 1024) <= 16 * 2**20  # two readings of a live figure
    assert private_bytes(2**22 + 12345) == 0  # no such process: nothing to count


def test_a_machine_with_exactly_its_floor_of_memory_left_is_not_refused() -> None:
    Budget(None, None, None, free_memory=lambda: MIN_FREE_BYTES).check("explore", 1, memory=True)
    with pytest.raises(OverBudget):
        Budget(None, None, None, free_memory=lambda: MIN_FREE_BYTES - 1).check("explore", 1, memory=True)


@pytest.mark.parametrize(("spent", "timer"), [(4.0, 6.05), (20.0, 0.05)])
def test_the_deadline_timer_rings_a_twentieth_of_a_second_after_the_time_left(
    spent: float, timer: float, monkeypatch: pytest.MonkeyPatch
) -> None:
    """10 s of budget with 4 spent: the timer is set to 6 s and a twentieth; with the budget
    already spent, to a twentieth (the check after the block refuses)."""
    import signal
    import time

    monkeypatch.setattr(time, "perf_counter", lambda: 100.0)
    armed: list[float] = []
    real = signal.setitimer

    def record(which: int, seconds: float, interval: float = 0.0) -> tuple[float, float]:
        armed.append(seconds)
        return real(which, 0) if seconds == 0 else (0.0, 0.0)

    monkeypatch.setattr(signal, "setitimer", record)
    budget = Budget(10.0, None, None, clock=time.perf_counter, start=100.0 - spent)
    with budget.deadline():
        pass
    assert armed[0] == pytest.approx(timer, abs=1e-12) and armed[-1] == 0


@pytest.mark.parametrize(("ran", "counted"), [(86_399.5, True), (86_400.5, False)])
def test_a_process_start_is_read_from_proc_up_to_a_day_back(
    ran: float, counted: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Started ``ran`` seconds ago by /proc's clocks: within a day the start is that far back,
    beyond it (a clock that cannot be right) the start is now."""
    import io
    import time

    import hg_marl_start as module  # process_start's home

    tick = os.sysconf("SC_CLK_TCK")
    files = {
        "/proc/self/stat": "1 (python) S " + " ".join(["0"] * 18 + [str(1000 * tick)] + ["0"] * 10),
        "/proc/uptime": f"{1000 + ran} 0.0",
    }
    monkeypatch.setattr(module, "open", lambda path, **kw: io.StringIO(files[path]), raising=False)
    before = time.perf_counter()
    start = module.process_start()
    back = before - start
    assert (back == pytest.approx(ran, abs=1.0)) if counted else abs(back) <= 1.0


def test_the_memory_budget_refuses_only_above_its_bytes_and_names_them_in_gb(monkeypatch: pytest.MonkeyPatch) -> None:
    from hg_marl.agents.models import budget as module

    monkeypatch.setattr(module, "rss", lambda: 3 * 2**29)  # 1.5 GB resident
    Budget(None, 3 * 2**29, None, free_memory=lambda: None).check("explore", 1, memory=True)
    with pytest.raises(OverBudget, match=r"over its budget of 1\.5 GB of memory in phase 'explore'"):
        Budget(None, 3 * 2**29 - 1, None, free_memory=lambda: None).check("explore", 1, memory=True)


def test_without_proc_the_resident_size_is_the_peak_in_bytes(monkeypatch: pytest.MonkeyPatch) -> None:
    """Where /proc cannot be read, ``ru_maxrss`` (kB on Linux) times 1024."""
    from hg_marl.agents.models import budget as module

    def no_proc(path: str, **kw: object) -> object:
        raise OSError(path)

    monkeypatch.setattr(module, "open", no_proc, raising=False)
    low = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    value = rss()
    high = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    assert low <= value <= high


@pytest.mark.parametrize(
    ("stat", "uptime"),
    [("1 (python) S", "1000.0 0.0"), ("1 (python) S " + " ".join(["0"] * 18 + ["200000"]), "1000.0 0.0")],
)
def test_a_process_start_that_cannot_be_read_or_lies_ahead_is_now(
    stat: str, uptime: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A /proc/self/stat without its start field, or a start after the uptime (a start in
    the future: 2,000 s of ticks at 100 a second against 1,000 s up), gives now."""
    import io
    import time

    import hg_marl_start as module  # process_start's home

    monkeypatch.setattr(os, "sysconf", lambda name: 100)
    files = {"/proc/self/stat": stat, "/proc/uptime": uptime}
    monkeypatch.setattr(module, "open", lambda path, **kw: io.StringIO(files[path]), raising=False)
    before = time.perf_counter()
    start = module.process_start()
    assert before <= start <= time.perf_counter()


def _timers_armed(outer: float, block: float, monkeypatch: pytest.MonkeyPatch) -> list[tuple[float, float]]:
    """The ``setitimer`` calls of a 10 s budget's deadline block (4 s spent) that lasts ``block``
    seconds, an outer timer with ``outer`` seconds left (0: none) armed before it."""
    import signal
    import time

    now = [100.0]
    monkeypatch.setattr(time, "perf_counter", lambda: now[0])
    calls: list[tuple[float, float]] = []

    def record(which: int, seconds: float, interval: float = 0.0) -> tuple[float, float]:
        calls.append((seconds, interval))
        return (outer, 0.0) if len(calls) == 1 else (0.0, 0.0)

    monkeypatch.setattr(signal, "setitimer", record)
    with Budget(10.0, None, None, clock=time.perf_counter, start=96.0).deadline():
        now[0] += block
    return calls


@pytest.mark.parametrize("outer", [5.0, 0.0])
def test_the_deadline_puts_back_a_timer_armed_before_it(outer: float, monkeypatch: pytest.MonkeyPatch) -> None:
    """An outer timer with 5 s left is re-armed for them when the block ends; none is armed
    where none was."""
    calls = _timers_armed(outer, 0.0, monkeypatch)
    assert calls == [(6.05, 0.0), (0.0, 0.0), *([(5.0, 0.0)] if outer else [])]


@pytest.mark.parametrize(("outer", "block", "expected"), [(5.0, 2.0, 3.0), (1.0, 2.0, 1e-6), (5.0, 5.0, 1e-6)])
def test_an_outer_timer_put_back_rings_when_it_would_have(
    outer: float, block: float, expected: float, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The block's seconds count against the outer timer too: 5 s left, a 2 s block, 3 s left
    after it (re-armed with 5 s, it rang 2 s late). A moment that passed in the block rings at
    once (1e-6 s: a timer of 0 is none); it is never lost."""
    calls = _timers_armed(outer, block, monkeypatch)
    assert calls[:2] == [(6.05, 0.0), (0.0, 0.0)]
    assert calls[2] == (pytest.approx(expected), 0.0)
    assert len(calls) == 3
