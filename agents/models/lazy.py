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
from hg_marl.agents.models.keyed import Searches, ranges, starts_of


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
        self._order: dict[bool, tuple[np.ndarray, np.ndarray]] = {}
        """Per kind of key: the live pairs in key order, and their keys."""
        self._last: tuple[int, np.ndarray, np.ndarray] | None = None
        self._searched = Searches()
        """The sorted pair keys' positions, searched once per distinct table keys: the partners of a
        joint model answered on arrays were asked the same keys, so their tables hold the same keys
        (the headroom's twenty), and one search serves them all."""

    def entries_of(self, partner: int, terminal: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(first entry, entry count) of every pair in ``partner``'s table (0 entries: the completing ``wait``).

        Every pair's key is looked up at once, in sorted order (one sort per kind of key,
        kept), and the last partner's positions are kept: the headroom asks one partner for
        the transitions of many policies in a row.
        """
        if self._last is not None and self._last[0] == partner:
            return self._last[1], self._last[2]
        table = self.tables[partner]
        keys = self.mid_seen if table.uses_robot_action else self.mid_plain
        if table.uses_robot_action not in self._order:
            live = np.flatnonzero(~terminal)
            order = live[np.argsort(keys[live], kind="stable")]
            self._order[table.uses_robot_action] = (order, keys[order])
        order, asked = self._order[table.uses_robot_action]
        first = np.zeros(len(keys), dtype=np.int64)
        size = np.zeros(len(keys), dtype=np.int64)
        first[order], size[order] = table.lookup(asked, searches=self._searched)
        self._last = (partner, first, size)
        return first, size

    def gather(
        self, partner: int, pairs: np.ndarray, terminal: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """As the builder's kept transitions: a pair's transitions are its key's entries, in order."""
        return self._gather(partner, pairs, terminal)[:4]

    def every(
        self, partner: int, terminal: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Every pair's transitions (as :meth:`gather` of all pairs), and the pair of each transition."""
        return self._gather(partner, None, terminal)

    def _gather(
        self, partner: int, pairs: np.ndarray | None, terminal: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        table = self.tables[partner]
        ids = self._ids.get(partner)
        if ids is None:  # every entry's next state is known: each answer was some pair's transition
            ids = self._ids[partner] = self.index.id_of(table.entries["canonical" if self.canonical else "next"])
        first, count = self.entries_of(partner, terminal)
        if pairs is None:
            lo, size, pair_of = first, count, np.repeat(np.arange(len(count)), count)
        else:
            lo, size = first[pairs], count[pairs]
            pair_of = np.repeat(pairs, size)
        at = ranges(lo, size)
        tau = np.maximum(self.d_robot[pair_of], table.entries["d_human"][at])
        return starts_of(size), ids[at], table.entries["probs"][at], tau, pair_of
