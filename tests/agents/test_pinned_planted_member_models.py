"""Pinned against a planted bug: the members' results are dropped when the durations change.

A result is the member's optimum in one world: scenario *and* durations. Worked by hand:
doubling every action's duration doubles every cycle's seconds and changes nothing
else (the same states, transitions and policy), so the optimal rate is exactly half.
A robot moved to the doubled world must drop its results and read that half rate.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import fields, replace

import pytest

from hg_marl.agents.member_models import MemberModels, clear_memo
from hg_marl.core import World

COOP = "preference"


@pytest.fixture(autouse=True)
def fresh_memo(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    monkeypatch.delenv("HG_MARL_CACHE", raising=False)
    clear_memo()
    yield
    clear_memo()


def test_a_robot_moved_to_other_durations_drops_its_results() -> None:
    world = World("paper2015")
    d = world.durations
    slow = World("paper2015", replace(d, **{f.name: 2.0 * getattr(d, f.name) for f in fields(d)}))
    models = MemberModels((COOP,), "")
    models.reset(world)
    rate = models.result(0).rate_per_hour
    assert rate > 0.0
    models.reset(slow)
    assert models.built() == []
    assert models.result(0).rate_per_hour == pytest.approx(rate / 2.0, rel=1e-6)
    models.reset(World("paper2015"))  # back to the scenario's own durations: solved for them again
    assert models.built() == []
    assert models.result(0).rate_per_hour == pytest.approx(rate, rel=1e-9)
