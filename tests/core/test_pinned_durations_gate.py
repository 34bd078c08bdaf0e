"""Action durations: the default table, the failed duration, the bounds and the shortest/longest, pinned for the gate.

The defaults below are the task's parameters, written here by hand: every built-in
scenario without a ``[durations]`` table (``paper2015``) runs on them, so a stored result,
a trajectory digest and an oracle rate all assume them; changing one is a change of the
task, not a refactoring. The bounds are the module's documented ones: 0.01 s (so a run
of ``D`` seconds has at most ``100 D`` cycles) and one simulated day, 24 x 3600 =
86,400 s, both inclusive. Shortest and longest are worked by hand on the tables below.
"""

from __future__ import annotations

import dataclasses

import pytest

from hg_marl.core import World
from hg_marl.core.durations import Durations
from hg_marl.core.errors import ConfigError
from hg_marl.core.types import Kind

DEFAULTS = {"pick": 2.0, "throw": 2.0, "give": 1.0, "take": 1.5, "place": 2.0, "goto": 3.0, "wait": 1.0, "failed": 0.2}
ONE_DAY = 24 * 3600.0


def test_the_default_durations_are_the_tasks() -> None:
    assert dataclasses.asdict(Durations()) == DEFAULTS
    assert World("paper2015").durations == Durations(**DEFAULTS)  # paper2015 has no [durations] table


def test_an_action_lasts_its_kinds_duration_and_a_failed_one_the_failed_duration() -> None:
    """Distinct values per kind (1..7 s, failed 0.5 s), so a kind read as another shows."""
    durations = Durations(pick=1, throw=2, give=3, take=4, place=5, goto=6, wait=7, failed=0.5)
    for value, kind in enumerate(Kind, start=1):  # Kind's order: PICK, THROW, GIVE, TAKE, PLACE, GOTO, WAIT
        assert durations.of(kind) == float(value), kind
        assert durations.of(kind, True) == float(value), kind
        assert durations.of(kind, ok=False) == 0.5, kind


def test_shortest_and_longest_are_read_over_every_duration_failed_included() -> None:
    assert Durations().shortest == 0.2  # the failed duration
    assert Durations().longest == 3.0  # goto
    slow_failure = Durations(pick=0.5, goto=1.0, failed=9.0)
    assert slow_failure.shortest == 0.5
    assert slow_failure.longest == 9.0


@pytest.mark.parametrize("field", list(DEFAULTS))
def test_each_duration_accepts_its_bounds_and_refuses_just_outside(field: str) -> None:
    assert getattr(Durations(**{field: 0.01}), field) == 0.01
    assert getattr(Durations(**{field: ONE_DAY}), field) == ONE_DAY
    assert getattr(Durations.from_mapping({field: ONE_DAY}), field) == ONE_DAY
    for outside in (0.0099, ONE_DAY + 0.5):
        with pytest.raises(ConfigError, match=rf"durations\.{field}"):
            Durations(**{field: outside})
        with pytest.raises(ConfigError, match=rf"^scenario: field 'durations\.{field}'"):
            Durations.from_mapping({field: outside}, "scenario")


def test_durations_are_frozen_and_hashable() -> None:
    """A world's durations are read by its rule table and name its disk caches (their ``repr``): never changed in place.

    Frozen, equal durations hash alike, so they can key a dict too.
    """
    durations = Durations()
    with pytest.raises(dataclasses.FrozenInstanceError):
        durations.pick = 5.0  # type: ignore[misc]
    assert hash(durations) == hash(Durations(**DEFAULTS))
