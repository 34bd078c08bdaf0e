"""Values that round 138's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.agents.array_partners import CompiledSchedule, compiled_humans
from hg_marl.agents.humans.lazy import LazyHuman
from hg_marl.agents.humans.no_handover import NoHandoverHuman
from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.core import State, World
from tests.agents.test_pinned_human_no_handover_gate import PAPER, named


def test_an_idling_no_handover_human_still_never_hands_over() -> None:
    # paper2015, the human holding tape1 (place 8) with the robot at human_side (location 3, a
    # handover place): a no_handover human never gives, whatever its idling; tape1's bin is out of
    # its reach, so it puts tape1 on mat_shared. With p_idle 0.25, by hand: that move with
    # 1 - 0.25 = 0.75 and wait with 0.25 (the same answer as at p_idle 0, mixed with wait).
    dist = named(NoHandoverHuman(p_idle=0.25).distribution(PAPER, State((8, 0, 1), 3)))
    assert dist == [("place(tape1,mat_shared)", 0.75), ("wait", 0.25)]


def test_two_live_humans_of_one_class_are_two_members_of_a_compiled_schedule() -> None:
    # Two LazyHuman instances given as instances (no spec): two different partners, so each phase
    # is compiled from its own human; only the same member named twice is compiled once.
    calm, idle = LazyHuman(p_idle=0.0), LazyHuman(p_idle=0.5)
    schedule = compiled_humans(World("paper2015"), SwitchingHuman([calm, idle, calm], at=[10.0, 20.0]), cache=False)
    assert isinstance(schedule, CompiledSchedule)
    assert schedule.phase_member.tolist() == [0, 1, 0]
    assert [member.human for member in schedule.members] == [calm, idle]
