"""Round 50's missed planted bug, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

import pytest

from hg_marl.agents.partner import PartnerMonitor
from hg_marl.core import Agent, Kind, World


def _refused_action(world: World) -> tuple[int, int]:
    """A non-wait human action the plan expects, and another the human does instead (a refusal)."""
    actions = world.actions(Agent.HUMAN)
    expected = next(i for i, a in enumerate(actions) if a.kind is not Kind.WAIT)
    actual = next(i for i in range(len(actions)) if i != expected)
    return expected, actual


@pytest.mark.parametrize(("stall_after", "again_after"), [(4, 2), (5, 3), (6, 3)])
def test_after_a_fallback_the_monitor_rearms_at_half_its_count(stall_after: int, again_after: int) -> None:
    # docs/design.md ("Two stall rules in the planning robots"): the monitor fires after
    # stall_after unmet expectations in a row, and "after it fires it re-arms at half its
    # count". Worked by hand: it keeps stall_after // 2 misses (4 -> 2, 5 -> 2, 6 -> 3), so a
    # partner who goes on refusing stalls the robot again after 2, 3 and 3 more misses, not
    # after a whole stall_after again.
    world = World("paper2015")
    expected, actual = _refused_action(world)
    monitor = PartnerMonitor(block_after=1000, stall_after=stall_after)  # blocks never interfere
    for _ in range(stall_after):
        assert not monitor.stalled
        monitor.observe(world, expected, actual, solved=False)
    assert monitor.stalled
    monitor.fell_back()
    assert monitor.fallbacks == 1
    for _ in range(again_after):
        assert not monitor.stalled
        monitor.observe(world, expected, actual, solved=False)
    assert monitor.stalled
