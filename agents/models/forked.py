"""Worker processes forked from this one, mapping a function they inherit over items.

Exact models are built and solved from large in-memory objects (a live planner with its
memo, a joint model of millions of pairs) that would cost more to pickle than to use. A
forked worker inherits them as they are, copy-on-write; only the items and the results
cross the pipe. :class:`Forked` keeps its workers for the next :meth:`Forked.map` (a
planner's memo keeps growing in each of them) until :meth:`Forked.close`.

Results come back in the order of the items, so what is computed does not depend on the
number of workers; the caller's ``check`` is read in this process after each result (the
budget's wall-time timer, :meth:`~hg_marl.agents.models.budget.Budget.deadline`, also
interrupts the wait), and the workers are terminated on any error or refusal. The
collector is frozen while forking: a worker's collections would otherwise walk, and so
copy page by page, every object the parent holds. Where ``fork`` is unavailable, or with
one job, the items are mapped in this process.
"""

from __future__ import annotations

import gc
import multiprocessing
import os
import weakref
from collections.abc import Callable, Iterator, Sequence
from typing import Any, Generic, TypeVar

T = TypeVar("T")
R = TypeVar("R")

MAX_JOBS = 256
"""The most worker processes one option may start."""

_FUNCTIONS: dict[int, Callable[[Any], Any]] = {}
"""The functions of the live :class:`Forked` objects, by id: a worker finds its function here."""


def check_jobs(jobs: int, option: str = "jobs") -> int:
    """The number of workers ``jobs`` asks for (0: one per CPU), or ValueError naming ``option``."""
    if isinstance(jobs, bool) or not isinstance(jobs, int) or not 0 <= jobs <= MAX_JOBS:
        raise ValueError(f"{option} must be a whole number from 0 (one per CPU) to {MAX_JOBS}, got {jobs!r}")
    return jobs if jobs > 0 else min(os.cpu_count() or 1, MAX_JOBS)


def _call(job: tuple[int, Any]) -> Any:
    key, item = job
    return _FUNCTIONS[key](item)


def _fork_context() -> Any:
    try:
        return multiprocessing.get_context("fork")
    except ValueError:  # no fork on this platform
        return None


class Forked(Generic[T, R]):
    """``function`` mapped over items by ``jobs`` forked workers (in this process with one job)."""

    def __init__(self, function: Callable[[T], R], jobs: int = 1) -> None:
        self.function, self.jobs = function, check_jobs(jobs)
        self._pool: Any = None
        self._key = id(self)
        self._finalizer: weakref.finalize[Any, Any] | None = None

    @property
    def parallel(self) -> bool:
        """Whether :meth:`map` uses worker processes (more than one job and ``fork`` available)."""
        return self.jobs > 1 and _fork_context() is not None

    @property
    def started(self) -> bool:
        """Whether worker processes are running (from the first parallel :meth:`map` to :meth:`close`)."""
        return self._pool is not None

    def map(self, items: Sequence[T], check: Callable[[int], None] | None = None) -> list[R]:
        """``function(item)`` for each item, in order; ``check(done)`` before the first and after each result."""
        return self.submit(items).collect(check)

    def submit(self, items: Sequence[T]) -> Submitted[T, R]:
        """Hand ``items`` to the workers now; :meth:`Submitted.collect` gives what :meth:`map` would.

        Why: the caller can work in this process while the workers compute (the model
        builder steps the array partners' answers while a live partner's are searched).
        In this process (one job, no ``fork``, fewer than two items) nothing starts before
        :meth:`Submitted.collect`.
        """
        if not self.parallel or len(items) < 2:
            return Submitted(self, items, None)
        return Submitted(self, items, self._start().imap(_call, [(self._key, item) for item in items]))

    def _start(self) -> Any:
        if self._pool is None:
            _FUNCTIONS[self._key] = self.function
            gc.freeze()
            try:
                self._pool = _fork_context().Pool(self.jobs)
            finally:
                gc.unfreeze()
            self._finalizer = weakref.finalize(self, _stop, self._pool, self._key)
        return self._pool

    def close(self) -> None:
        """Stop the workers (the next :meth:`map` forks new ones)."""
        if self._finalizer is not None:
            self._finalizer()
        self._pool = self._finalizer = None

    def __enter__(self) -> Forked[T, R]:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class Submitted(Generic[T, R]):
    """Items handed to a :class:`Forked`'s workers (or kept to be mapped in this process), collected once."""

    def __init__(self, owner: Forked[T, R], items: Sequence[T], results: Iterator[R] | None) -> None:
        self.owner, self.items, self.results = owner, items, results

    def collect(self, check: Callable[[int], None] | None = None) -> list[R]:
        """The results in the order of the items; ``check(done)`` before the first and after each result."""
        out: list[R] = []
        if check is not None:
            check(0)
        if self.results is None:
            for item in self.items:
                out.append(self.owner.function(item))
                if check is not None:
                    check(len(out))
            return out
        try:
            for result in self.results:
                out.append(result)
                if check is not None:
                    check(len(out))
        except BaseException:
            self.owner.close()
            raise
        return out


def _stop(pool: Any, key: int) -> None:
    pool.terminate()
    pool.join()
    _FUNCTIONS.pop(key, None)
