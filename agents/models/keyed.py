"""Packed int64 keys: deduplicated by sorting or hashing, looked up in sorted order, and tables of segments per key.

Why sorting for the distinct keys with their inverse: numpy's sort of int64 keys is
vectorised (AVX-512 or AVX2 where the CPU has them), and on the builder's batches (each
key about twice) ``np.unique(..., return_inverse=True)`` is faster than a
``pandas.factorize`` hash table followed by a sort of the distinct keys (measured in
``docs/exact-references.md``). Why hashing elsewhere: the distinct keys in order of
first occurrence, or without an inverse, come from ``pandas.unique`` in one pass. Why
sorted queries: ``searchsorted`` with queries in random order misses the cache at every
probe of a large table; sorting the queries first and scattering the answers back gives
the same positions many times faster on the headroom's tables of millions of keys. The
sorts of distinct keys (and of queries, whose equal members get equal positions) need no
stable order, so they use numpy's default, the vectorised one. Every function here
returns exactly what its ``numpy`` counterpart returns (a test compares them on random
keys), so a model built with them is the same, bit for bit.

:class:`SegmentTable` is the answer tables' layout: sorted keys, each with a segment of
entries. Entries are appended, never moved (arrays grown by doubling); only the keys and
their segment positions are kept sorted. Merging a batch into a table therefore costs
the keys, not the entries; :meth:`SegmentTable.compact` gives the contiguous layout
(``starts``) that the compiled partners store.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import pandas as pd

SORT_QUERIES = 4096
"""Queries above this many are sorted before a ``searchsorted`` (below it the sort costs more than it saves)."""


def starts_of(size: np.ndarray) -> np.ndarray:
    """Segment starts of consecutive segments of ``size`` entries each (``len(size) + 1``, from 0)."""
    return np.concatenate([[0], np.cumsum(size)]).astype(np.int64)


def ranges(lo: np.ndarray, size: np.ndarray) -> np.ndarray:
    """The positions ``lo[i]:lo[i] + size[i]`` of every ``i``, concatenated."""
    return np.repeat(lo - np.concatenate([[0], np.cumsum(size)[:-1]]).astype(np.int64), size) + np.arange(size.sum())


def _sorted(codes: np.ndarray, found: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``factorize``'s distinct keys sorted, the order that sorts them, and each code's rank among them."""
    order = np.argsort(found)  # distinct keys: any sort gives the same order
    rank = np.empty(len(order), dtype=np.int64)
    rank[order] = np.arange(len(order))
    return np.asarray(found)[order], order, rank[codes]


def unique(keys: np.ndarray) -> np.ndarray:
    """``np.unique(keys)``: the distinct keys, sorted."""
    return np.sort(pd.unique(keys))


def first_unique(keys: np.ndarray) -> np.ndarray:
    """The distinct keys in order of first occurrence."""
    return np.asarray(pd.unique(keys))


def unique_inverse(keys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(keys, return_inverse=True)``: the distinct keys sorted, and each key's position among them."""
    uniq, inverse = np.unique(keys, return_inverse=True)
    return uniq, inverse.reshape(-1)


def unique_first_inverse(keys: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``np.unique(keys, return_index=True, return_inverse=True)`` (the index is each key's first occurrence)."""
    codes, found = pd.factorize(keys)
    # factorize numbers keys in order of first occurrence: a position is a first one
    # exactly where its code exceeds every code before it.
    seen = np.maximum.accumulate(np.concatenate([[-1], codes[:-1]])) if len(codes) else codes
    uniq, order, inverse = _sorted(codes, found)
    return uniq, np.flatnonzero(codes > seen)[order], inverse


def nonzero_2d(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.nonzero(mask)`` of a 2-D boolean array (rows, columns, row-major).

    Why: numpy's ``nonzero`` of a 2-D array writes both index arrays element by element;
    the positions in the flattened array, split by one division, are the same arrays at a
    fraction of the cost on the builder's masks.
    """
    width = mask.shape[1]
    flat = np.flatnonzero(mask)
    rows = flat // width
    return rows, flat - rows * width


def positions(sorted_keys: np.ndarray, queries: np.ndarray) -> np.ndarray:
    """``np.searchsorted(sorted_keys, queries)``, with large unsorted queries probed in sorted order."""
    if len(queries) <= SORT_QUERIES or bool(np.all(queries[1:] >= queries[:-1])):
        return np.searchsorted(sorted_keys, queries)
    order = np.argsort(queries)  # equal queries get equal positions whatever their order
    found = np.empty(len(queries), dtype=np.int64)
    found[order] = np.searchsorted(sorted_keys, queries[order])
    return found


def known(sorted_keys: np.ndarray, queries: np.ndarray) -> np.ndarray:
    """Whether each query is among ``sorted_keys``."""
    if not len(sorted_keys):
        return np.zeros(len(queries), dtype=bool)
    at = np.minimum(positions(sorted_keys, queries), len(sorted_keys) - 1)
    return sorted_keys[at] == queries


class Searches:
    """Look-ups of the same queries in tables holding the same keys, each made once.

    Why: a joint model's partners answered on arrays are asked the same keys at every
    step, so their tables hold the same keys; what a look-up or a merge finds is then the
    same for all of them. A result is reused for a table whose keys are the array it was
    computed on, or an array equal to it, which the table then shares (so the next
    look-up matches by identity). Results hold their arrays: nothing is matched by an
    address that could be reused.
    """

    def __init__(self) -> None:
        self._done: list[tuple[str, np.ndarray, np.ndarray, Any]] = []

    def __len__(self) -> int:
        """The searches made (each reused for the tables with the same keys)."""
        return len(self._done)

    def get(self, kind: str, table: SegmentTable, queries: np.ndarray, compute: Callable[[], Any]) -> Any:
        """``compute()`` for ``table``'s keys and ``queries``, or what it gave a table with the same keys
        (the same ``queries`` object)."""
        for done, keys, asked, result in self._done:
            if done != kind or asked is not queries:
                continue
            if keys is table.keys or (len(keys) == len(table.keys) and np.array_equal(keys, table.keys)):
                table.keys = keys
                return result
        result = compute()
        for array in result if isinstance(result, tuple) else (result,):
            array.flags.writeable = False  # shared: a reader that wrote into it would change the others'
        self._done.append((kind, table.keys, queries, result))
        return result


_NO_KEYS = np.zeros(0, dtype=np.int64)
_NO_KEYS.flags.writeable = False  # every new table starts from this one array (never written: merged into copies)


class SegmentTable:
    """Sorted distinct keys, each with a segment of entries in append-only arrays.

    Args:
        fields: the entries' arrays by name, with their dtypes.
    """

    def __init__(self, fields: Mapping[str, type | np.dtype]) -> None:
        self.keys = _NO_KEYS
        """(k,) sorted; replaced, never written (tables holding the same keys may share it: :class:`Searches`)."""
        self.first = np.zeros(0, dtype=np.int64)
        """(k,) position of each key's first entry in the entry arrays."""
        self.size = np.zeros(0, dtype=np.int64)
        """(k,) entries of each key."""
        self._buffers = {name: np.zeros(0, dtype=dtype) for name, dtype in fields.items()}
        self.n_entries = 0

    @property
    def entries(self) -> dict[str, np.ndarray]:
        """The entry arrays (in order of insertion; a key's entries are contiguous, in its given order)."""
        return {name: buf[: self.n_entries] for name, buf in self._buffers.items()}

    def lookup(
        self, keys: np.ndarray, at: np.ndarray | None = None, searches: Searches | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """(first entry, entry count) per key; every key must be in the table.

        ``at``: the keys' positions among the table's keys, where the caller has them
        (:func:`positions`; tables with the same keys share them). ``searches``: where
        other tables are asked the same keys (:class:`Searches`).
        """
        if at is None:
            at = self._search("positions", keys, lambda: positions(self.keys, keys), searches)
        return self.first[at], self.size[at]

    def lacks(self, keys: np.ndarray, searches: Searches | None = None) -> np.ndarray:
        """Per key of ``keys``, whether the table lacks it (``searches``: as :meth:`lookup`)."""
        if not len(self.keys):
            return np.ones(len(keys), dtype=bool)
        at = self._search("positions", keys, lambda: positions(self.keys, keys), searches)  # :meth:`lookup`'s too
        lack: np.ndarray = self.keys[np.minimum(at, len(self.keys) - 1)] != keys
        return lack

    def _search(self, kind: str, keys: np.ndarray, compute: Callable[[], Any], searches: Searches | None) -> Any:
        return compute() if searches is None else searches.get(kind, self, keys, compute)

    def missing(self, keys: np.ndarray) -> np.ndarray:
        """The keys of ``keys`` not in the table (in their order)."""
        return keys[self.lacks(keys)]

    def add(
        self, keys: np.ndarray, sizes: np.ndarray, new: Mapping[str, np.ndarray], searches: Searches | None = None
    ) -> None:
        """Store distinct ``keys`` not in the table; key ``i``'s entries are the next ``sizes[i]`` of ``new``.

        ``searches``: where tables with the same keys store the same ``keys`` (the merged
        keys are then computed once and shared: :class:`Searches`).
        """
        total = int(sizes.sum())
        end = self.n_entries + total
        for name, buf in self._buffers.items():
            if end > len(buf):  # doubling: each entry is copied O(1) times over the table's life
                grown = np.empty(max(end, 2 * len(buf), 1024), dtype=buf.dtype)
                grown[: self.n_entries] = buf[: self.n_entries]
                buf = self._buffers[name] = grown
            buf[self.n_entries : end] = new[name]
        first = self.n_entries + starts_of(sizes)[:-1]
        self.n_entries = end

        def merged() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            order = np.argsort(keys)  # distinct keys
            at = np.searchsorted(self.keys, keys[order])
            return order, at, np.insert(self.keys, at, keys[order])

        order, at, self.keys = self._search("add", keys, merged, searches)
        self.first = np.insert(self.first, at, first[order])
        self.size = np.insert(self.size, at, sizes[order].astype(np.int64))

    def compact(self) -> tuple[np.ndarray, np.ndarray, dict[str, np.ndarray]]:
        """(keys, starts, entries) with each key's entries at ``starts[i]:starts[i + 1]``, keys sorted."""
        gather = ranges(self.first, self.size)
        return self.keys, starts_of(self.size), {name: values[gather] for name, values in self.entries.items()}
