"""The scripted humans' shared helpers (``agents/humans/base.py``), pinned for the mutation gate.

Every expected value is worked by hand from the scenario files: in ``paper2015`` the
human reaches ``mat_shared`` (3, which the robot reaches from ``human_side``, 3) and its
two own mats ``human_mat_1``/``human_mat_2`` (4, 5), no bin; the robot's hand is place 7
and the human's 8, the only handover location is ``human_side``. In
``asymmetric_advantages`` the human reaches ``middle_1``/``middle_2`` (1, 2: the robot
reaches them from ``far_end``, 1), ``human_mat`` (3, the human's alone) and the
``human_bin`` (place 5); the robot's hand is 6, the human's 7, and the robot hands over
at ``home`` (0).
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.humans.base import (
    StationaryHuman,
    check_p_idle,
    deterministic,
    first_feasible,
    human_only_spots,
    human_spots,
    index_of,
    robot_action_of,
    sample,
    shared_spots,
    tidy_action,
    wait_index,
    with_idle,
)
from hg_marl.core import Agent, Event, Kind, State, World
from hg_marl.policy import Turn

PAPER = World("paper2015")
ASYM = World("asymmetric_advantages")


def name(world: World, index: int) -> str:
    return world.action_names[Agent.HUMAN][index]


def turn(world: World, state: State, events: tuple[Event, ...] = (), last: tuple[int, int] = (-1, -1)) -> Turn:
    obs = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.HUMAN)}
    return Turn(world, state, Agent.HUMAN, obs, events=events, last_actions=last)


# ---- probabilities -----------------------------------------------------------------------
@pytest.mark.parametrize("p", [0.0, 1.0, 0.5])
def test_an_idle_probability_from_zero_to_one_inclusive_is_accepted(p: float) -> None:
    assert check_p_idle(p) == p and isinstance(check_p_idle(p), float)


@pytest.mark.parametrize("p", [-1e-9, 1.0 + 1e-9, -1.0, 2.0])
def test_an_idle_probability_outside_zero_to_one_is_refused(p: float) -> None:
    with pytest.raises(ValueError, match="p_idle must be a probability"):
        check_p_idle(p)


def test_no_idling_leaves_the_distribution_as_it_is() -> None:
    """At ``p_idle = 0`` the distribution is returned unchanged: no zero-probability ``wait`` added."""
    dist = [(2, 1.0)]
    assert with_idle(dist, PAPER, 0.0) == [(2, 1.0)]


def test_idling_mixes_wait_in_and_scales_the_rest() -> None:
    """``wait`` (index 30) gets ``p_idle``, every other action ``(1 - p_idle) * p``, sorted by index."""
    assert with_idle([(2, 1.0)], PAPER, 0.25) == [(2, 0.75), (30, 0.25)]
    # a distribution that already holds wait: wait adds both shares, 0.2 + 0.8 * 0.5
    mixed = dict(with_idle([(30, 0.5), (1, 0.5)], PAPER, 0.2))
    assert mixed == pytest.approx({1: 0.4, 30: 0.6})
    assert with_idle([(5, 1.0)], PAPER, 1.0) == [(5, 0.0), (30, 1.0)]


def test_an_idle_probability_of_zero_or_below_adds_no_wait() -> None:
    """Only a positive ``p_idle`` mixes ``wait`` in: at or below 0 the distribution is returned as given."""
    assert with_idle([(2, 1.0)], PAPER, -0.5) == [(2, 1.0)]


def test_a_single_choice_is_taken_without_a_draw() -> None:
    rng = np.random.default_rng(3)
    before = rng.bit_generator.state
    assert sample([(17, 1.0)], rng) == 17
    assert rng.bit_generator.state == before


def test_a_draw_follows_the_normalised_weights() -> None:
    """Unnormalised weights are divided by their sum: the draw is numpy's choice over them, by hand."""
    dist = [(4, 2.0), (9, 6.0)]  # 1/4 and 3/4
    rng, reference = np.random.default_rng(11), np.random.default_rng(11)
    drawn = [sample(dist, rng) for _ in range(200)]
    expected = [(4, 9)[int(reference.choice(2, p=[0.25, 0.75]))] for _ in range(200)]
    assert drawn == expected
    assert sample([(4, 0.0), (9, 3.0)], np.random.default_rng(0)) == 9  # weight 0 never drawn


def test_deterministic_puts_all_the_mass_on_one_action() -> None:
    assert deterministic(12) == [(12, 1.0)]


# ---- geometry ----------------------------------------------------------------------------
def test_the_areas_of_paper2015_are_read_from_the_spots_reach() -> None:
    assert human_spots(PAPER) == (3, 4, 5)
    assert shared_spots(PAPER) == (3,)
    assert human_only_spots(PAPER) == (4, 5)


def test_the_areas_of_asymmetric_advantages_are_read_from_the_spots_reach() -> None:
    assert human_spots(ASYM) == (1, 2, 3)
    assert shared_spots(ASYM) == (1, 2)
    assert human_only_spots(ASYM) == (3,)


def test_wait_and_ground_actions_are_found_by_name() -> None:
    assert name(PAPER, wait_index(PAPER)) == "wait"
    assert name(PAPER, index_of(PAPER, Kind.PLACE, 2, 4)) == "place(tape3,human_mat_1)"
    assert name(PAPER, index_of(PAPER, Kind.PICK, 1)) == "pick(tape2)"


def test_first_feasible_skips_infeasible_candidates_and_answers_minus_one_when_none_is() -> None:
    state = State((0, 1, 4), 0)  # tape3 on human_mat_1, the human's hands empty
    throw3, pick1, pick3 = (index_of(PAPER, k, o) for k, o in ((Kind.THROW, 2), (Kind.PICK, 0), (Kind.PICK, 2)))
    assert first_feasible(PAPER, state, [throw3, pick1, pick3, wait_index(PAPER)]) == pick3
    assert first_feasible(PAPER, state, [throw3, pick1]) == -1
    assert first_feasible(PAPER, state, []) == -1


# ---- the tidying rule --------------------------------------------------------------------
def test_a_held_object_goes_into_the_humans_bin_when_it_reaches_one() -> None:
    holding = State((0, 1, 2, 7), 0)  # tape4 in the human's hand, the robot at home
    assert name(ASYM, tidy_action(ASYM, holding, give=True)) == "throw(tape4)"


def test_a_held_object_is_handed_over_when_the_robot_waits_at_a_handover_place() -> None:
    """``paper2015``: no bin for the human; at ``human_side`` the give comes before the shared mat."""
    holding = State((0, 1, 8), 3)
    assert name(PAPER, tidy_action(PAPER, holding, give=True)) == "give(tape3)"
    assert name(PAPER, tidy_action(PAPER, holding, give=False)) == "place(tape3,mat_shared)"


def test_a_held_tape1_is_handled_like_any_other_held_object() -> None:
    """tape1 is object 0: holding it (place 8) is holding something, handed over at ``human_side``."""
    assert name(PAPER, tidy_action(PAPER, State((8, 1, 4), 3), give=True)) == "give(tape1)"


def test_a_held_object_goes_on_the_shared_mat_when_the_robot_is_away() -> None:
    holding = State((0, 1, 8), 0)
    assert name(PAPER, tidy_action(PAPER, holding, give=True)) == "place(tape3,mat_shared)"


def test_a_held_object_with_nowhere_to_go_is_kept() -> None:
    full = State((3, 1, 8), 0)  # tape1 on the shared mat, the robot away: no give, no place
    assert tidy_action(PAPER, full, give=True) == -1


def test_an_object_only_the_human_reaches_is_picked_while_the_shared_mat_is_free() -> None:
    state = State((0, 1, 4), 0)
    assert name(PAPER, tidy_action(PAPER, state, give=True)) == "pick(tape3)"
    assert name(PAPER, tidy_action(PAPER, state, give=False)) == "pick(tape3)"


def test_with_the_shared_mat_taken_only_a_handover_makes_a_pick_worth_it() -> None:
    """tape1 on ``mat_shared``, tape3 on ``human_mat_1``: picking tape3 helps only if it can be given."""
    robot_away = State((3, 1, 4), 0)
    assert tidy_action(PAPER, robot_away, give=True) == -1
    robot_at_hand = State((3, 1, 4), 3)
    assert name(PAPER, tidy_action(PAPER, robot_at_hand, give=True)) == "pick(tape3)"
    assert tidy_action(PAPER, robot_at_hand, give=False) == -1


def test_objects_the_robot_already_reaches_are_left_alone() -> None:
    """tape3 on ``mat_shared``: the human reaches it, but there is no bin for it and the robot reaches it."""
    assert tidy_action(PAPER, State((0, 1, 3), 0), give=True) == -1
    assert tidy_action(PAPER, State((0, 1, 3), 3), give=True) == -1


def test_an_object_in_reach_of_the_humans_bin_is_picked_first_by_index() -> None:
    """``asymmetric_advantages``: every object the human reaches can go into its bin, so the first is picked.

    tape1 on ``robot_mat`` (out of the human's reach), tape2 and tape3 in the middle,
    tape4 on ``human_mat``: tape2 is the first the human reaches.
    """
    state = State((0, 1, 2, 3), 0)
    assert name(ASYM, tidy_action(ASYM, state, give=False)) == "pick(tape2)"
    thrown = State((0, 5, 5, 3), 0)  # tape2 and tape3 already in the human's bin
    assert name(ASYM, tidy_action(ASYM, thrown, give=False)) == "pick(tape4)"
    assert tidy_action(ASYM, State((0, 5, 5, 5), 0), give=False) == -1  # tape1 beyond reach


# ---- acting ------------------------------------------------------------------------------
def test_the_robots_action_is_seen_only_when_it_did_not_fail() -> None:
    state = State((0, 1, 4), 0)
    assert robot_action_of(turn(PAPER, state, last=(5, 30))) == 5
    failed = (Event("failed", "robot", "tape1"),)
    assert robot_action_of(turn(PAPER, state, failed, last=(5, 30))) == -1
    human_failed = (Event("failed", "human", "tape1"),)
    assert robot_action_of(turn(PAPER, state, human_failed, last=(5, 30))) == 5
    other = (Event("picked", "robot", "tape1"),)
    assert robot_action_of(turn(PAPER, state, other, last=(5, 30))) == 5


class _Echo(StationaryHuman):
    """Answers the robot action it is handed (as a human's index), to show what ``act`` passes on."""

    name = "echo"

    def __init__(self) -> None:
        super().__init__()
        self.handed: list[int] = []

    def distribution(self, world: World, state: State, robot_action: int = 99) -> list[tuple[int, float]]:
        self.handed.append(robot_action)
        return deterministic(robot_action if robot_action >= 0 else wait_index(world))


class _EchoUsing(_Echo):
    uses_robot_action = True


def test_act_hands_the_robots_action_only_to_humans_that_use_it() -> None:
    state = State((0, 1, 4), 0)
    plain, using = _Echo(), _EchoUsing()
    for human in (plain, using):
        human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    assert plain.act(turn(PAPER, state, last=(5, 30))) == 30
    assert using.act(turn(PAPER, state, last=(5, 30))) == 5
    assert using.last_decision == {"human": "echo", "action": "throw(tape3)"}
    assert plain.last_decision == {"human": "echo", "action": "wait"}
    # the documented "unknown" is -1, handed to a human that does not use the robot's action
    assert plain.handed == [-1] and using.handed == [5]


def test_a_scripted_human_is_not_equivariant_unless_it_says_so() -> None:
    """Rules that pick "the first object" by index are not equivariant, so the base class says False.

    ``lazy`` inherits the flag and shows why: in ``asymmetric_advantages`` tape2 and tape3
    (interchangeable: the same bins) lie in the middle; swapping their labels should swap
    the answer, but the lazy human picks tape2 in both layouts.
    """
    from hg_marl.agents.humans.lazy import LazyHuman

    assert StationaryHuman.equivariant is False
    lazy = LazyHuman(p_idle=0.0)
    assert lazy.equivariant is False
    first = lazy.distribution(ASYM, State((0, 1, 2, 3), 0))
    swapped = lazy.distribution(ASYM, State((0, 2, 1, 3), 0))
    assert [name(ASYM, i) for i, _ in first] == [name(ASYM, i) for i, _ in swapped] == ["pick(tape2)"]


def test_reset_takes_the_world_the_seat_and_the_generator() -> None:
    human, rng = _Echo(), np.random.default_rng(5)
    assert human.world is None and human.agent is Agent.HUMAN and human.last_decision == {}
    human.reset(PAPER, Agent.ROBOT, rng)
    assert human.world is PAPER and human.agent is Agent.ROBOT and human.rng is rng
