"""Pinned against a planted bug: the oracle's disk cache keys a result by the world's durations.

Two worlds that differ only in their action durations are two optimisation problems: an
entry stored for one must never be read back for the other. Worked by hand from a property:
doubling every duration (failed actions included) doubles the length of every cycle (a
cycle lasts as long as its longer action) and changes nothing else, so the optimal policy
is the same and its seconds per task double, its tasks per hour halve. Solving the slow
world after the fast one in the same cache folder must give half the fast rate, and leave
two entries on disk; a key blind to the durations hands back the fast world's rate.
"""

from __future__ import annotations

from dataclasses import fields, replace
from pathlib import Path

import pytest

from hg_marl.agents.models.cache import result_key
from hg_marl.agents.oracle import oracle_rate
from hg_marl.core import World

OPTIONS = {"failed_actions": True, "symmetry": None, "tolerance": 1e-9, "max_iterations": 200_000}


def twice_as_slow(world: World) -> World:
    """The same scenario with every action duration doubled (nothing else differs)."""
    d = world.durations
    return World(world.scenario, durations=replace(d, **{f.name: 2 * getattr(d, f.name) for f in fields(d)}))


def test_worlds_differing_only_in_durations_have_different_keys() -> None:
    world = World("paper2015")
    slow = twice_as_slow(world)
    assert slow.scenario == world.scenario and slow.durations != world.durations
    assert result_key(world, "no_handover", OPTIONS) == result_key(World("paper2015"), "no_handover", dict(OPTIONS))
    assert result_key(slow, "no_handover", OPTIONS) != result_key(world, "no_handover", OPTIONS)
    assert result_key(slow, "no_handover", OPTIONS) == result_key(twice_as_slow(world), "no_handover", dict(OPTIONS))


def test_a_result_cached_for_one_set_of_durations_is_not_reused_for_another(tmp_path: Path) -> None:
    world = World("paper2015")
    fast = oracle_rate(world, "no_handover", cache=tmp_path)
    assert fast.rate_per_hour > 0
    slow = oracle_rate(twice_as_slow(world), "no_handover", cache=tmp_path)
    assert slow.rate_per_hour == pytest.approx(fast.rate_per_hour / 2, rel=1e-9)  # every cycle twice as long
    assert slow.seconds_per_task == pytest.approx(2 * fast.seconds_per_task, rel=1e-9)
    assert len(list(tmp_path.glob("paper2015-*.npz"))) == 2  # one entry per set of durations
    again = oracle_rate(twice_as_slow(world), "no_handover", cache=tmp_path)  # now read back from its own entry
    assert again.rate_per_hour == slow.rate_per_hour
