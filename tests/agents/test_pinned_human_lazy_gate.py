"""The ``lazy`` human (``agents/humans/lazy.py``), pinned for the mutation gate.

Expected values worked by hand from ``paper2015``'s spots: the human reaches
``mat_shared`` (3) and its own mats ``human_mat_1``/``human_mat_2`` (4, 5) and no bin;
``human_side`` (3) is the handover location; its hand is place 8. Action 0 is
``pick(tape1)`` and 30 is ``wait``, so a rule that confuses "no action" (-1) with
"action 0" shows on tape1.
"""

from __future__ import annotations

from hg_marl.agents.humans.lazy import LazyHuman
from hg_marl.core import Agent, State, World

PAPER = World("paper2015")


def named(dist: list[tuple[int, float]]) -> list[tuple[str, float]]:
    return [(PAPER.action_names[Agent.HUMAN][i], p) for i, p in dist]


def test_the_lazy_human_idles_three_times_in_ten_by_default() -> None:
    """The registry's ``lazy`` (README's example and docs/results.md's rows) idles with 0.3."""
    assert LazyHuman().p_idle == 0.3
    dist = named(LazyHuman().distribution(PAPER, State((4, 0, 1), 0)))
    assert dist == [("pick(tape1)", 0.7), ("wait", 0.3)]


def test_tape1_on_its_own_mat_is_picked_like_any_other() -> None:
    """tape1 (action 0) on ``human_mat_1`` with ``mat_shared`` free: the lazy human picks it."""
    assert named(LazyHuman(p_idle=0.0).distribution(PAPER, State((4, 0, 1), 0))) == [("pick(tape1)", 1.0)]


def test_the_lazy_human_hands_over_to_a_robot_at_the_handover_place() -> None:
    """Holding tape3 with the robot at ``human_side``: no bin in reach, so the give comes first."""
    assert named(LazyHuman(p_idle=0.0).distribution(PAPER, State((0, 1, 8), 3))) == [("give(tape3)", 1.0)]


def test_with_nothing_to_do_the_lazy_human_waits_for_sure() -> None:
    """tape3 on ``mat_shared`` is the robot's to take: the only answer is ``wait``, with probability 1."""
    assert named(LazyHuman(p_idle=0.3).distribution(PAPER, State((0, 1, 3), 0))) == [("wait", 1.0)]
