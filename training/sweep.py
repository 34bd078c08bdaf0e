"""Resumable sweeps of runner jobs on the content-addressed store, on any backend.

:func:`run_jobs` is the driver: for each job (in order) it reuses the stored run when
the job's key is in the store, else claims the key, checks the store once more (another
process may just have finished it) and hands the job to the backend; each finished
result is written to the store before its claim is released. Jobs claimed by another
live process are waited for, not run again. So an interrupted sweep resumes where it
stopped, two sweeps on one folder share the work, and the results depend on neither
the backend nor the number of workers (every job is a pure function of its key).

:func:`run_sweep` and :func:`load_log` keep the older folder-based signature: the store
lives in ``out/store``.
"""

from __future__ import annotations

import contextlib
import logging
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from hg_marl.training.backends import Backend, LocalBackend
from hg_marl.training.store import Job, Store, StoredRun

__all__ = ["Job", "SweepStats", "load_log", "run_jobs", "run_sweep", "store_of"]

log = logging.getLogger(__name__)

POLL = 0.2
"""Seconds between looks at jobs another process is running."""


@dataclass
class SweepStats:
    """What a sweep did."""

    ran: int = 0
    """Jobs this process ran."""
    reused: int = 0
    """Jobs found finished in the store (including those another process finished meanwhile)."""


def run_jobs(
    jobs: Sequence[Job],
    store: Store,
    backend: Backend | None = None,
    on_done: Callable[[Job, StoredRun], None] | None = None,
) -> tuple[list[StoredRun], SweepStats]:
    """Run every job whose key is not in ``store``; return all stored runs, in job order.

    Args:
        jobs: the sweep (jobs with equal keys run once).
        store: where results are kept.
        backend: executor (default: in this process); closed on return.
        on_done: called once per job as it is found or finished (progress bars hook in here).
    """
    backend = backend or LocalBackend(1)
    keys = [job.key() for job in jobs]
    positions: dict[str, list[int]] = {}
    for i, key in enumerate(keys):
        positions.setdefault(key, []).append(i)
    first = {key: at[0] for key, at in positions.items()}
    found: dict[str, StoredRun] = {}
    stats = SweepStats()

    def record(key: str, stored: StoredRun) -> None:
        found[key] = stored
        if on_done:
            for i in positions[key]:
                on_done(jobs[i], stored)

    pending = list(first)
    claims: dict[str, contextlib.ExitStack] = {}
    try:
        while pending or claims:
            waiting: list[str] = []
            for key in pending:
                job = jobs[first[key]]
                if len(claims) >= backend.capacity:
                    waiting.append(key)
                    continue
                stored = store.get(job, key)
                if stored is None:
                    stack = contextlib.ExitStack()
                    if not stack.enter_context(store.claim(key)):
                        stack.close()
                        waiting.append(key)
                        continue
                    stored = store.get(job, key, repair=True)
                    if stored is None:
                        claims[key] = stack
                        backend.submit(key, job)
                        continue
                    stack.close()
                stats.reused += 1
                record(key, stored)
            pending = waiting
            if claims:
                for key, result in backend.wait(timeout=POLL):
                    stored = store.put(jobs[first[key]], result, key)
                    claims.pop(key).close()
                    stats.ran += 1
                    record(key, stored)
            elif pending:
                time.sleep(POLL)  # the rest is being run by another process
    finally:
        backend.close()
        for stack in claims.values():
            stack.close()
    if jobs:
        log.info("store %s: %d runs made, %d reused", store.root, stats.ran, stats.reused)
    return [found[key] for key in keys], stats


def store_of(out: str | Path) -> Store:
    """The store of an output folder."""
    return Store(Path(out) / "store")


def run_sweep(
    jobs: Iterable[Job],
    out: str | Path,
    workers: int = 1,
    on_done: Callable[[Job, dict[str, Any]], None] | None = None,
    backend: Backend | None = None,
) -> list[dict[str, Any]]:
    """Run every job not already in ``out``'s store; return all summaries, in job order.

    Args:
        jobs: the sweep.
        out: output folder (its store is ``out/store``).
        workers: local worker processes; 1 runs in this process (ignored with ``backend``).
        on_done: called with each job and its summary as it is found or finished.
        backend: executor (default: :class:`LocalBackend` with ``workers``).
    """
    callback = None if on_done is None else (lambda job, stored: on_done(job, stored.summary))
    runs, _ = run_jobs(list(jobs), store_of(out), backend or LocalBackend(workers), callback)
    return [{**run.summary, "job": run.job, "key": run.key} for run in runs]


def load_log(job: Job, out: str | Path) -> pd.DataFrame:
    """The per-decision log of a finished job of ``out``'s store."""
    stored = store_of(out).get(job)
    if stored is None:
        raise FileNotFoundError(f"no finished run of {job.label or job.robot} seed {job.seed} in {out}")
    return stored.log()
