"""A model's transitions left in its partners' answer tables (``build_model(keep=False)``).

A pair's transitions against a partner are the entries of its mid-cycle key in that
partner's :class:`~hg_marl.agents.models.AnswerTable`, in order, with the cycle's seconds
``max(d_robot, d_human)``: what the builder would have kept, read when asked. The keys are
fewer than the pairs (several robot actions lead to one mid-cycle state), so the
headroom's joint model of many partners keeps only the tables.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.models.answers import AnswerTable


def ranges(lo: np.ndarray, size: np.ndarray) -> np.ndarray:
    """The positions ``lo[i]:lo[i] + size[i]`` of every ``i``, concatenated."""
    return np.repeat(lo - np.concatenate([[0], np.cumsum(size)[:-1]]).astype(np.int64), size) + np.arange(size.sum())


def starts_of(size: np.ndarray) -> np.ndarray:
    return np.concatenate([[0], np.cumsum(size)]).astype(np.int64)


class TableTransitions:
    """A model's transitions left in the partners' answer tables: per pair its mid-cycle keys and robot seconds."""

    def __init__(
        self,
        tables: list[AnswerTable],
        index: Any,
        canonical: bool,
        mid_seen: np.ndarray,
        mid_plain: np.ndarray,
        d_robot: np.ndarray,
        regen: list[tuple[np.ndarray, np.ndarray, np.ndarray]],
    ) -> None:
        self.tables, self.index, self.canonical = tables, index, canonical
        self.mid_seen, self.mid_plain, self.d_robot, self.regen = mid_seen, mid_plain, d_robot, regen
        self._ids: dict[int, np.ndarray] = {}

    def gather(
        self, partner: int, pairs: np.ndarray, terminal: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """As the builder's kept transitions: a pair's transitions are its key's entries, in order."""
        table = self.tables[partner]
        ids = self._ids.get(partner)
        if ids is None:  # every entry's next state is known: each answer was some pair's transition
            ids = self._ids[partner] = self.index.id_of(table.entries["canonical" if self.canonical else "next"])
        live = ~terminal[pairs]
        keys = (self.mid_seen if table.uses_robot_action else self.mid_plain)[pairs[live]]
        start, count = table.lookup(keys)
        size = np.zeros(len(pairs), dtype=np.int64)
        size[live] = count
        lo = np.zeros(len(pairs), dtype=np.int64)
        lo[live] = start
        at = ranges(lo, size)
        pair_of = np.repeat(pairs, size)
        tau = np.maximum(self.d_robot[pair_of], table.entries["d_human"][at])
        return starts_of(size), ids[at], table.entries["probs"][at], tau
