"""The hashed deduplication and sorted-order lookups return what numpy's own functions return,
and a segment table keeps each key's entries as given however the keys arrive.

References: ``np.unique`` (with its index and inverse) and ``np.searchsorted`` on the same
random keys, long enough to take the sorted-queries path; a table of three keys worked by
hand, filled in two batches out of key order.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.models.keyed import (
    SORT_QUERIES,
    SegmentTable,
    first_unique,
    known,
    nonzero_2d,
    positions,
    unique,
    unique_first_inverse,
    unique_inverse,
)


@pytest.mark.parametrize("n", [0, 1, 7, 3 * SORT_QUERIES])
def test_deduplication_is_numpys(n: int) -> None:
    rng = np.random.default_rng(n)
    keys = rng.integers(0, max(n // 3, 1), n).astype(np.int64) * 1_000_003
    np.testing.assert_array_equal(unique(keys), np.unique(keys))
    u, inv = unique_inverse(keys)
    want_u, want_inv = np.unique(keys, return_inverse=True)
    np.testing.assert_array_equal(u, want_u)
    np.testing.assert_array_equal(inv, want_inv)
    # and by their definition: strictly increasing distinct keys that give back every key
    assert bool(np.all(u[1:] > u[:-1])) and set(u.tolist()) == set(keys.tolist())
    np.testing.assert_array_equal(u[inv], keys)
    u, first, inv = unique_first_inverse(keys)
    want = np.unique(keys, return_index=True, return_inverse=True)
    for got, expected in zip((u, first, inv), want, strict=True):
        np.testing.assert_array_equal(got, expected)


@pytest.mark.parametrize("shape", [(0, 5), (4, 0), (1, 1), (37, 35), (300, 7)])
def test_nonzero_2d_is_numpys_row_major_pairs(shape: tuple[int, int]) -> None:
    mask = np.random.default_rng(sum(shape)).random(shape) < 0.3
    rows, cols = nonzero_2d(mask)
    want_rows, want_cols = np.nonzero(mask)
    np.testing.assert_array_equal(rows, want_rows)
    np.testing.assert_array_equal(cols, want_cols)
    by_hand = [(r, c) for r in range(shape[0]) for c in range(shape[1]) if mask[r, c]]
    assert list(zip(rows.tolist(), cols.tolist(), strict=True)) == by_hand


def test_first_unique_keeps_the_order_of_first_occurrence() -> None:
    assert first_unique(np.array([5, 3, 5, 9, 3, 1], dtype=np.int64)).tolist() == [5, 3, 9, 1]


def test_positions_are_searchsorted_whatever_the_queries_order() -> None:
    rng = np.random.default_rng(0)
    table = np.unique(rng.integers(0, 10**12, 5_000))
    for queries in (rng.integers(0, 10**12, 3 * SORT_QUERIES), np.sort(rng.integers(0, 10**12, 50)), table[::-1]):
        np.testing.assert_array_equal(positions(table, queries), np.searchsorted(table, queries))
    assert known(table, np.array([table[3], table[3] + 1])).tolist() == [True, False]
    assert known(np.zeros(0, dtype=np.int64), np.array([1, 2])).tolist() == [False, False]


def test_a_segment_table_filled_out_of_order_keeps_each_keys_entries() -> None:
    table = SegmentTable({"a": np.int64, "p": np.float64})
    table.add(np.array([30, 10]), np.array([2, 1]), {"a": np.array([7, 8, 9]), "p": np.array([0.25, 0.75, 1.0])})
    table.add(np.array([20]), np.array([3]), {"a": np.array([4, 5, 6]), "p": np.array([0.5, 0.25, 0.25])})
    assert table.keys.tolist() == [10, 20, 30]
    start, size = table.lookup(np.array([30, 20, 10, 30]))
    assert size.tolist() == [2, 3, 1, 2]
    entries = table.entries
    got = [entries["a"][s : s + k].tolist() for s, k in zip(start, size, strict=True)]
    assert got == [[7, 8], [4, 5, 6], [9], [7, 8]]
    assert table.missing(np.array([5, 10, 25, 30])).tolist() == [5, 25]
    keys, starts, flat = table.compact()
    assert keys.tolist() == [10, 20, 30]
    assert starts.tolist() == [0, 1, 4, 6]
    assert flat["a"].tolist() == [9, 4, 5, 6, 7, 8]
    assert flat["p"].tolist() == [1.0, 0.5, 0.25, 0.25, 0.25, 0.75]


def test_a_segment_table_grows_past_its_first_capacity() -> None:
    table = SegmentTable({"a": np.int64})
    for k in range(5):  # 5 x 700 entries: the 1,024 first capacity doubles twice
        table.add(np.array([100 - k]), np.array([700]), {"a": np.full(700, k)})
    assert table.n_entries == 3500
    start, size = table.lookup(np.array([96, 100]))
    assert table.entries["a"][start[0] : start[0] + size[0]].tolist() == [4] * 700
    assert table.entries["a"][start[1] : start[1] + size[1]].tolist() == [0] * 700
