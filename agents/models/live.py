"""A live partner's answers for a list of states, in this process or in forked workers.

The model builder asks a live partner (one whose rule has no array form, such as the
planner-driven ``cooperative`` human) for the answers of every new key of a batch; on a
large table that is tens of thousands of planner searches, most of a headroom's build.
The searches are independent (a scripted partner answers as a function of what it sees),
so :class:`LiveAnswers` can spread them over ``jobs`` workers forked from this process
(:class:`~hg_marl.agents.models.forked.Forked`): each inherits the partner as it is and
keeps its memo from one batch to the next; the answers come back in the order asked, so
a model is the same whatever ``jobs`` is (``tests/agents/test_live_jobs.py``). The memory
budget reads this process only: each worker adds the partner's own memo.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from hg_marl.agents.models.forked import Forked, Submitted
from hg_marl.core import State, World

Check = Callable[[int, int], None]
"""Called with (answers done, answers asked) between answers (between chunks in parallel)."""

Row = tuple[tuple[int, ...], int, int, int, int]
"""One question: the state's (where, robot_at, offer_by, offer_obj) and the robot action seen."""

CHUNK = 32
"""States a worker answers per message at most: small enough that the budget is read often (a
planner search is about a millisecond), large enough that messages cost little beside it."""
MIN_PARALLEL = 4 * CHUNK
"""Fewer questions than this do not start the workers (forking costs more than it saves); once
they run, any two questions or more go to them: the builder's first batches are small, and
answered here they would keep the workers idle while this process searches alone."""


def chunks(n: int, jobs: int) -> list[tuple[int, int]]:
    """(start, stop) of the messages of ``n`` questions for ``jobs`` workers: :data:`CHUNK` each,
    smaller where that leaves a worker without one (at least two per worker where ``n`` allows)."""
    size = max(1, min(CHUNK, -(-n // (2 * jobs))))
    return [(i, min(i + size, n)) for i in range(0, n, size)]


def questions(
    where: np.ndarray, robot_at: np.ndarray, offer_by: np.ndarray, offer_obj: np.ndarray, seen: np.ndarray
) -> list[Row]:
    """The rows of a batch of states (their arrays) and the robot actions seen, as :data:`Row` questions."""
    columns = (where.tolist(), robot_at.tolist(), offer_by.tolist(), offer_obj.tolist(), seen.tolist())
    return [(tuple(w), a, b, o, r) for w, a, b, o, r in zip(*columns, strict=True)]


class LiveAnswers:
    """The answers of ``partner`` (``distribution(world, state, seen)``) to lists of questions."""

    def __init__(self, world: World, partner: Any, jobs: int = 1) -> None:
        self.world, self.partner = world, partner
        self.workers: Forked[list[Row], list[list[tuple[int, float]]]] = Forked(self._chunk, jobs)

    def _answer(self, row: Row) -> list[tuple[int, float]]:
        where, at, by, obj, seen = row
        return [(h, p) for h, p in self.partner.distribution(self.world, State(where, at, by, obj), seen) if p > 0.0]

    def _chunk(self, rows: list[Row]) -> list[list[tuple[int, float]]]:
        return [self._answer(row) for row in rows]

    def __call__(self, rows: Sequence[Row], check: Check) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(entries per row, actions, probabilities): the answers with probability > 0, as the partner lists them."""
        return self.submit(rows).collect(check)

    def submit(self, rows: Sequence[Row]) -> Asked:
        """Start answering ``rows`` in the workers (where there are workers and enough rows); collect with
        :meth:`Asked.collect`, which gives what :meth:`__call__` gives."""
        workers = self.workers
        if workers.parallel and len(rows) >= (2 if workers.started else MIN_PARALLEL):
            spans = chunks(len(rows), workers.jobs)
            return Asked(self, rows, workers.submit([list(rows[a:b]) for a, b in spans]), [b for _, b in spans])
        return Asked(self, rows, None)

    def close(self) -> None:
        """Stop the workers, if any."""
        self.workers.close()


class Asked:
    """Questions handed to a :class:`LiveAnswers` (being answered in its workers, or to be answered here)."""

    def __init__(
        self,
        owner: LiveAnswers,
        rows: Sequence[Row],
        chunks: Submitted[list[Row], list[list[tuple[int, float]]]] | None,
        ends: list[int] | None = None,
    ) -> None:
        self.owner, self.rows, self.chunks = owner, rows, chunks
        self.ends = ends or []
        """The questions answered once each chunk is back (the budget's readings)."""

    def collect(self, check: Check) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(entries per row, actions, probabilities), as :meth:`LiveAnswers.__call__`."""
        rows = self.rows
        answers: list[list[tuple[int, float]]] = []
        if self.chunks is not None:
            ends = [0, *self.ends]
            for chunk in self.chunks.collect(lambda done: check(ends[done], len(rows))):
                answers.extend(chunk)
        else:
            for i, row in enumerate(rows):
                check(i, len(rows))
                answers.append(self.owner._answer(row))
        sizes = np.array([len(a) for a in answers], dtype=np.int64)
        actions = np.array([h for a in answers for h, _ in a], dtype=np.int64)
        probs = np.array([p for a in answers for _, p in a], dtype=np.float64)
        return sizes, actions, probs
