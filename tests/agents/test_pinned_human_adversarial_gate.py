"""The ``adversarial`` human (``agents/humans/adversarial.py``), pinned for the mutation gate.

Expected values worked by hand from the scenario files. ``paper2015``: the human's own
mats are 4 and 5, ``mat_shared`` (3) is the one spot both reach, the human's hand is
place 8; action 0 is ``pick(tape1)``. ``roboergosum``: ``placemat3``..``placemat7``
(2..6) are within the human's reach; the robot reaches 2, 3 and 4 from ``ROBOT_LOC``
(0) and 3, 4, 5 and 6 from ``SECOND_LOC`` (1); the bins are places 7 and 8.
"""

from __future__ import annotations

from hg_marl.agents.humans.adversarial import AdversarialHuman
from hg_marl.core import Agent, State, World

PAPER = World("paper2015")
ROBO = World("roboergosum")


def named(world: World, dist: list[tuple[int, float]]) -> list[tuple[str, float]]:
    return [(world.action_names[Agent.HUMAN][i], p) for i, p in dist]


def test_tape1_on_the_shared_mat_is_stolen() -> None:
    """tape1 (action 0) on ``mat_shared``: the adversary picks it, for sure (default ``p_idle`` 0)."""
    assert AdversarialHuman().p_idle == 0.0
    assert named(PAPER, AdversarialHuman().distribution(PAPER, State((3, 0, 1), 3))) == [("pick(tape1)", 1.0)]


def test_a_held_tape1_is_hidden_on_the_first_free_mat_of_its_own() -> None:
    assert named(PAPER, AdversarialHuman().distribution(PAPER, State((8, 0, 1), 0))) == [
        ("place(tape1,human_mat_1)", 1.0)
    ]
    # human_mat_1 taken by tape2: the second of its own mats
    assert named(PAPER, AdversarialHuman().distribution(PAPER, State((8, 4, 1), 0))) == [
        ("place(tape1,human_mat_2)", 1.0)
    ]


def test_with_both_own_mats_taken_the_held_object_is_hoarded() -> None:
    assert named(PAPER, AdversarialHuman(p_idle=0.5).distribution(PAPER, State((8, 4, 5), 0))) == [("wait", 1.0)]


def test_the_steal_prefers_what_the_robot_reaches_from_where_it_stands() -> None:
    """green1 on ``placemat7`` (6), green2 on ``placemat3`` (2), the rest out of the human's reach.

    From ``ROBOT_LOC`` the robot reaches placemat3 (green2), from ``SECOND_LOC`` placemat7
    (green1): the adversary takes the one about to be picked.
    """
    where = (6, 2, 0, 1, 8, 8)
    assert named(ROBO, AdversarialHuman().distribution(ROBO, State(where, 0))) == [("pick(green2)", 1.0)]
    assert named(ROBO, AdversarialHuman().distribution(ROBO, State(where, 1))) == [("pick(green1)", 1.0)]


def test_idling_mixes_wait_into_the_tactic() -> None:
    dist = named(PAPER, AdversarialHuman(p_idle=0.5).distribution(PAPER, State((3, 0, 1), 3)))
    assert dist == [("pick(tape1)", 0.5), ("wait", 0.5)]
