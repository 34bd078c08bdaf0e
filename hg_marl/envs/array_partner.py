"""What a batched seat's partner must and may offer, declared: one protocol per capability.

:class:`ArrayPartner` is the one required shape (a name and ``act`` over arrays). A
partner may offer more, and the batched table (:class:`hg_marl.envs.batched.BatchedTable`)
detects each optional capability once, when it is built, with ``isinstance`` against its
protocol below, so nothing is looked up by name on the hot path and every method a table
may call is named here.
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

import numpy as np

from hg_marl.core.batch import BatchState


class ArrayPartner(Protocol):
    """The partner of a batched seat: one action per table from arrays.

    ``seen`` is, per table, the learning robot's successful action of this cycle (-1 if it
    failed), for partners whose choice depends on it; a robot partner gets -1.

    Optional capabilities, each declared by its own protocol below and detected once when
    the table is built (never looked up on the hot path): :class:`FollowsClock`
    (``follow``), :class:`ResetsRows` (``reset_rows``) and :class:`TabledHuman`
    (``actions``, ``outcome``, ``answer``, ``fall_back``).
    """

    name: str

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """The partner's action index per table."""


@runtime_checkable
class FollowsClock(Protocol):
    """A partner whose behaviour depends on each table's clock (a schedule of humans)."""

    def follow(self, clock: np.ndarray, tasks_solved: np.ndarray) -> None:
        """Called before each of its moves with every table's clock and tasks solved."""


@runtime_checkable
class ResetsRows(Protocol):
    """A partner that keeps something per table (an actor, a member) to start afresh."""

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Tables ``rows`` start a new episode."""


@runtime_checkable
class TabledHuman(Protocol):
    """A compiled human: its answers' outcomes tabulated (``agents/compiled.py``).

    ``outcome`` holds, per table entry, the next state's fields (``where``, ``robot_at``,
    ``offer_by``, ``offer_obj``), its ``facts`` and robot ``mask``, and the action's
    ``ok`` and ``duration``, all computed by :class:`BatchedRules` at compile time.
    """

    actions: np.ndarray
    outcome: dict[str, np.ndarray]

    def answer(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(table entry, found) per table."""

    def fall_back(
        self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator, out: np.ndarray, found: np.ndarray
    ) -> np.ndarray:
        """``out`` with the live partner's answers where ``found`` is False."""
