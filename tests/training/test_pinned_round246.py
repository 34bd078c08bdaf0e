"""Values that round 246's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.agents.humans.base import check_p_idle
from hg_marl.agents.humans.no_handover import NoHandoverHuman
from hg_marl.core import State
from tests.agents.test_pinned_human_no_handover_gate import PAPER, named


def test_an_idle_probability_is_kept_exactly_as_given() -> None:
    # A probability in [0, 1] is accepted as it is: 0.125 (exact in binary) stays 0.125, not 0.12.
    # paper2015, the human holding tape1 (place 8), the robot at human_side (location 3): tape1's bin
    # is out of the human's reach, so a no_handover human puts it on mat_shared; idling with 0.125, by
    # hand: that move with 1 - 0.125 = 0.875 and wait with 0.125 (both exact in binary).
    assert check_p_idle(0.125) == 0.125
    assert NoHandoverHuman(p_idle=0.125).p_idle == 0.125
    dist = named(NoHandoverHuman(p_idle=0.125).distribution(PAPER, State((8, 0, 1), 3)))
    assert dist == [("place(tape1,mat_shared)", 0.875), ("wait", 0.125)]


def test_a_mostly_idle_no_handover_human_still_never_hands_over() -> None:
    # The same state (the robot at a handover place, the human holding tape1 whose bin it cannot
    # reach): whatever its idling, the human never gives; at p_idle 0.5 and 0.75, by hand: the move to
    # mat_shared with 1 - p_idle and wait with p_idle, and no give(tape1) among the answers.
    for p_idle, move in ((0.5, 0.5), (0.75, 0.25)):
        dist = named(NoHandoverHuman(p_idle=p_idle).distribution(PAPER, State((8, 0, 1), 3)))
        assert dist == [("place(tape1,mat_shared)", move), ("wait", p_idle)]
        assert not any(name.startswith("give") for name, _ in dist)
