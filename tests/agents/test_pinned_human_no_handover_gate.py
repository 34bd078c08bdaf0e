"""The ``no_handover`` human (``agents/humans/no_handover.py``), pinned for the mutation gate.

Expected values worked by hand from ``paper2015``'s spots (see
``test_pinned_human_lazy_gate.py``): action 0 is ``pick(tape1)``, so a rule that
confuses "no action" (-1) with "action 0" shows on tape1.
"""

from __future__ import annotations

from hg_marl.agents.humans.no_handover import NoHandoverHuman
from hg_marl.core import Agent, State, World

PAPER = World("paper2015")


def named(dist: list[tuple[int, float]]) -> list[tuple[str, float]]:
    return [(PAPER.action_names[Agent.HUMAN][i], p) for i, p in dist]


def test_tape1_on_its_own_mat_is_picked_with_no_idling_by_default() -> None:
    """tape1 (action 0) on ``human_mat_1``, ``mat_shared`` free: picked for sure (default ``p_idle`` 0)."""
    assert NoHandoverHuman().p_idle == 0.0
    assert named(NoHandoverHuman().distribution(PAPER, State((4, 0, 1), 0))) == [("pick(tape1)", 1.0)]


def test_a_held_tape1_goes_on_the_shared_mat_even_with_the_robot_at_hand() -> None:
    """Holding tape1 with the robot at ``human_side``: never given, put on ``mat_shared`` instead."""
    assert named(NoHandoverHuman().distribution(PAPER, State((8, 0, 1), 3))) == [("place(tape1,mat_shared)", 1.0)]


def test_with_nothing_to_do_it_waits_for_sure_whatever_its_idling() -> None:
    assert named(NoHandoverHuman(p_idle=0.5).distribution(PAPER, State((0, 1, 3), 0))) == [("wait", 1.0)]


def test_idling_mixes_wait_into_its_move() -> None:
    dist = named(NoHandoverHuman(p_idle=0.25).distribution(PAPER, State((4, 0, 1), 0)))
    assert dist == [("pick(tape1)", 0.75), ("wait", 0.25)]
