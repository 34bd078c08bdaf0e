"""The array answers of the partners, worked by hand on paper2015 states.

The reference is the rule as the preference human's docstring states it, applied by hand
(default weights: ``handover`` 1, ``shared`` 0.5, ``keep`` -1, ``robot_side`` -0.5, no haste):
the robot at ``human_side`` (a handover location) holds tape1 and offers it; tape2 lies on
``mat_left`` (out of the human's reach); tape3 lies on ``human_mat_1`` (only the human
reaches it). The human may pick tape3 (action 2), take tape1 (9) or wait (30). Picking
tape3 scores 1: after it, ``give`` (the robot stands at a handover location) scores
``handover`` 1, ``place`` on ``mat_shared`` (the robot's side) ``shared`` 0.5, and a place on
``human_mat_2`` stays on the human's side (no progress, not counted); no ``robot_side``
bonus (the robot cannot reach ``human_mat_1``). So the best action is the pick. With
``accept`` a and ``p_idle`` q the answer is take a(1-q), pick (1-a)(1-q), wait q, in action
index order; the probabilities are binary fractions, so the sums are exact.
"""

from __future__ import annotations

from hg_marl.agents.humans.preference import PreferenceHuman
from hg_marl.agents.humans.random_human import RandomHuman
from hg_marl.agents.models.partners import batch_answers
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchState
from tests.agents.ragged import per_state

ROBOT_HAND, HUMAN_HAND = 7, 8
HUMAN_SIDE = 3
PICK_TAPE3, GIVE_TAPE3, TAKE_TAPE1, PLACE_TAPE3_SHARED, WAIT = 2, 8, 9, 27, 30

OFFERED = State((ROBOT_HAND, 0, 4), HUMAN_SIDE, Agent.ROBOT, 0)
"""The offer, with tape3 for the human to pick (see the module docstring)."""
NOTHING_TO_PICK = State((ROBOT_HAND, 0, 1), HUMAN_SIDE, Agent.ROBOT, 0)
"""The offer, tape3 on ``mat_centre`` (the robot's side): the human's only moves are take and wait."""
HANDS_FULL = State((ROBOT_HAND, 0, HUMAN_HAND), HUMAN_SIDE, Agent.ROBOT, 0)
"""The offer while the human holds tape3: no take (its hand is full); give scores 1, above the
place on ``mat_shared`` (0.5) and the places on its own side (``keep`` -1)."""
NO_OFFER = State((ROBOT_HAND, 0, 4), HUMAN_SIDE)


def answers(human: object, states: list[State]) -> list[list[tuple[int, float]]]:
    """The array answers of ``human`` per state, as (action, probability) lists."""
    world = World("paper2015")
    batch = batch_answers(world, human)
    assert batch is not None
    return per_state(*batch(BatchState.of(states)))


def test_the_offer_the_choice_and_the_idle_wait_in_action_order() -> None:
    human = PreferenceHuman(accept=0.25, p_idle=0.5)
    got = answers(human, [OFFERED, NOTHING_TO_PICK, HANDS_FULL, NO_OFFER])
    assert got == [
        # take 0.25 x 0.5, pick 0.75 x 0.5, wait 0.5: the take (stacked first) sorted after the pick
        [(PICK_TAPE3, 0.375), (TAKE_TAPE1, 0.125), (WAIT, 0.5)],
        # the choice is wait: its share 0.75 x 0.5 joins the idle 0.5 in one entry
        [(TAKE_TAPE1, 0.125), (WAIT, 0.875)],
        [(GIVE_TAPE3, 0.5), (WAIT, 0.5)],
        [(PICK_TAPE3, 0.5), (WAIT, 0.5)],
    ]


def test_without_idling_there_is_no_wait_entry_unless_chosen() -> None:
    human = PreferenceHuman(accept=0.25)
    got = answers(human, [OFFERED, NOTHING_TO_PICK, NO_OFFER])
    assert got == [
        [(PICK_TAPE3, 0.75), (TAKE_TAPE1, 0.25)],
        [(TAKE_TAPE1, 0.25), (WAIT, 0.75)],
        [(PICK_TAPE3, 1.0)],
    ]


def test_an_offer_never_taken_leaves_no_take_entry() -> None:
    human = PreferenceHuman(accept=0.0, p_idle=0.5)
    assert answers(human, [OFFERED]) == [[(PICK_TAPE3, 0.5), (WAIT, 0.5)]]


def test_the_random_human_is_uniform_over_its_feasible_actions() -> None:
    # OFFERED: pick tape3, take tape1, wait; HANDS_FULL: give tape3, place it on mat_shared,
    # human_mat_1 and human_mat_2 (all free), wait
    human = RandomHuman(feasible_only=True)
    third, fifth = 1 / 3, 1 / 5
    assert answers(human, [OFFERED, HANDS_FULL]) == [
        [(PICK_TAPE3, third), (TAKE_TAPE1, third), (WAIT, third)],
        [(GIVE_TAPE3, fifth), (PLACE_TAPE3_SHARED, fifth), (28, fifth), (29, fifth), (WAIT, fifth)],
    ]
