"""A packed map answers like a dict: a state it does not hold is a ``KeyError``, wherever
its key falls (before the first key, between two, after the last), so ``in`` and ``get``
work; a state it holds gives its value back."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.packing import PackedMap, StatePacker
from hg_marl.core import State, World


def test_absent_states_are_key_errors_on_both_sides_of_the_keys() -> None:
    world = World("paper2015")
    packer = StatePacker(world)
    states = sorted({s for s, _ in layout_distribution(world)}, key=packer.pack_one)
    assert len(states) >= 4
    held = states[1:-1]  # the first and the last are left out: below and above every key
    m = PackedMap(packer, np.array([packer.pack_one(s) for s in held], dtype=np.int64), np.arange(len(held)))
    assert len(m) == len(held) and [m[s] for s in held] == list(range(len(held)))
    for absent in (states[0], states[-1]):
        with pytest.raises(KeyError):
            m[absent]
        assert absent not in m and m.get(absent) is None
    other = State(held[0].where[:-1], 0, -1, -1)  # another scenario's shape
    assert other not in m and "not a state" not in m  # type: ignore[operator]
    assert sorted(m, key=packer.pack_one) == held
