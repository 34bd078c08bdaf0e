"""A packed map answers like a dict: a state it does not hold is a ``KeyError``, wherever
its key falls (before the first key, between two, after the last), so ``in`` and ``get``
work; a state it holds gives its value back."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.packing import PackedMap, StatePacker
from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchState


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


def _radices(world: World) -> list[int]:
    """The packing's digits worked from the table's counts (each place, the robot's location,
    who offers (none, robot, human), the offered object or none, the robot action seen or none)."""
    t = world.table
    return [t.n_places] * t.n_objects + [t.n_locations, 3, t.n_objects + 1, world.n_actions(Agent.ROBOT) + 1]


@pytest.mark.parametrize("scenario", ["generated:objects=4,spots=5", "paper2015"])
def test_every_robot_action_seen_unpacks_to_itself(scenario: str) -> None:
    """The seen action's digit holds every robot action and none; on a table with an odd
    number of robot actions (23 here) too, the last one (``wait``) included."""
    world = World(scenario)
    packer = StatePacker(world)
    n_actions = world.n_actions(Agent.ROBOT)
    state = layout_distribution(world)[0][0]
    seen = np.arange(-1, n_actions, dtype=np.int64)
    b = BatchState.of([state] * len(seen))
    keys = packer.pack(b, seen)
    assert len(set(keys.tolist())) == len(seen)
    back, got = packer.unpack(keys)
    assert got.tolist() == seen.tolist()
    assert all(back.state(i) == state for i in range(len(seen)))


def test_the_key_limit_is_two_to_the_62() -> None:
    """A table whose keys need fewer than 2**62 values is packed (12 objects on 14 spots:
    about 2**61.3 by the digits worked above), one that needs more (15 spots: 2**62.3) is
    refused with the scenario named."""
    fits, too_big = World("generated:objects=12,spots=14"), World("generated:objects=12,spots=15")
    assert 2**61 < math.prod(_radices(fits)) < 2**62 < math.prod(_radices(too_big))
    packer = StatePacker(fits)
    state = fits.initial_state(np.random.default_rng(0))
    assert packer.unpack(np.array([packer.pack_one(state)], dtype=np.int64))[0].state(0) == state
    with pytest.raises(ValueError, match=r"too many states to pack into 64-bit keys"):
        StatePacker(too_big)


def test_a_state_past_the_last_key_of_a_large_map_is_a_key_error() -> None:
    """A map of more than 256 keys (Python caches the small integers, so an identity test of
    the position against the length holds below that by chance): a state whose key is above
    every held key is a ``KeyError`` too, not an index past the end."""
    world = World("roboergosum")
    packer = StatePacker(world)
    states = sorted({s for s, _ in layout_distribution(world)}, key=packer.pack_one)
    assert len(states) > 300
    held = states[:-1]
    m = PackedMap(packer, np.array([packer.pack_one(s) for s in held], dtype=np.int64), np.arange(len(held)))
    with pytest.raises(KeyError):
        m[states[-1]]
    assert m[held[-1]] == len(held) - 1
