"""The preference human's haste on a pick, softmax temperature, colour rule and memo, pinned for the mutation gate.

Every expected answer is worked by hand from the rules in ``agents/humans/preference.py``'s
docstring, with the indices of ``tests/agents/test_preference.py``: on paper2015 the human's
``pick(tape3)`` is 2, ``place(tape3, mat_shared)`` 27, ``place(tape3, human_mat_1/2)`` 28
and 29, ``wait`` 30; every action of paper2015 and roboergosum lasts 2 s except ``give``
and ``wait`` (1 s). On roboergosum, ``pick(green1)`` is 0 and ``pick(blue1)`` 3.
"""

from __future__ import annotations

import math

import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.preference import PreferenceHuman
from hg_marl.core import State, World

WAIT = 30


@pytest.fixture(scope="module")
def paper() -> World:
    return World("paper2015")


@pytest.fixture(scope="module")
def robo() -> World:
    return World("roboergosum")


def dist(spec: str, world: World, state: State) -> list[tuple[int, float]]:
    human = make_human(spec)
    assert isinstance(human, PreferenceHuman)
    return [(i, round(p, 12)) for i, p in human.distribution(world, state)]


def test_haste_charges_a_pick_for_its_own_two_seconds_as_well_as_the_place_after_it(paper: World) -> None:
    """tape3 on human_mat_1, robot at bin_side: the only worthwhile pick is tape3's, worth
    ``shared`` 0.5 for the place after it, less ``haste`` x (2 s place + 2 s pick).
    haste 0.1: 0.5 - 0.4 = 0.1 > 0, it picks; haste 0.15: 0.5 - 0.6 = -0.1, it waits."""
    state = State((0, 1, 4), 0)
    assert dist("preference:haste=0.1", paper, state) == [(2, 1.0)]
    assert dist("preference:haste=0.15", paper, state) == [(WAIT, 1.0)]


def test_the_softmax_divides_the_scores_by_the_temperature(paper: World) -> None:
    """Holding tape3 at bin_side: place(mat_shared) 0.5, place on a human mat -1 (keep), wait 0;
    at temperature 2 each weighs ``exp(score / 2)`` (a reference softmax written here)."""
    state = State((0, 1, 8), 0)
    scores = {27: 0.5, 28: -1.0, 29: -1.0, WAIT: 0.0}
    weights = {i: math.exp(s / 2.0) for i, s in scores.items()}
    total = sum(weights.values())
    expected = [(i, round(w / total, 12)) for i, w in sorted(weights.items())]
    assert dist("preference:temperature=2", paper, state) == expected


def test_a_preferred_colour_without_a_bonus_changes_nothing(robo: World) -> None:
    """``colour_bonus`` defaults to 0: naming a colour alone adds nothing. roboergosum, green1 on
    placemat3 and blue1 on placemat4, the rest in their bins: both picks are worth the give
    after them (0.5), a tie that pick(green1) wins by its lower index; a negative default
    bonus would drop the green pick below 0 and leave blue1's, a positive one for blue would
    put pick(blue1) first."""
    state = State((2, 7, 7, 3, 8, 8), 0)
    assert dist("preference:handover=0.5,self_work=0.4,robot_side=0,colour=green", robo, state) == [(0, 1.0)]
    # and a positive default bonus for blue would lift pick(blue1) above the tie
    assert dist("preference:handover=0.5,self_work=0.4,robot_side=0,colour=blue", robo, state) == [(0, 1.0)]


def test_the_colour_bonus_goes_to_objects_of_that_colour_alone(robo: World) -> None:
    """Same layout, self_work 0.6: blue1 can be thrown into blue_bin (0.6 > its give 0.5),
    green1 only given (0.5). A 0.2 bonus for green lifts pick(green1) to 0.7, above
    pick(blue1)'s 0.6; a bonus leaking to blue (which sorts before green) would make it 0.8."""
    state = State((2, 7, 7, 3, 8, 8), 0)
    spec = "preference:handover=0.5,self_work=0.6,robot_side=0,colour=green,colour_bonus=0.2"
    assert dist(spec, robo, state) == [(0, 1.0)]
    assert dist("preference:handover=0.5,self_work=0.6,robot_side=0", robo, state) == [(3, 1.0)]  # no bonus


def test_answers_are_memoised_per_state(paper: World) -> None:
    """The answers are "memoised per state": asking again about a state (in the same world)
    returns the cached answer itself, not a new computation of it."""
    human = make_human("preference:p_idle=0.1")
    assert isinstance(human, PreferenceHuman)
    state = State((0, 1, 4), 0)
    first = human.distribution(paper, state)
    assert human.distribution(paper, state) is first
    human.distribution(paper, State((0, 1, 8), 3))
    assert human.distribution(paper, state) is first


def test_a_hoarder_does_not_count_moving_an_object_between_its_own_mats(paper: World) -> None:
    """tape3 on human_mat_1 (the human's side), robot at bin_side, keep 0.5 and shared -1: after
    the pick, place on mat_shared is -1, back on human_mat_1 is its origin and on human_mat_2
    stays on the human's side (no progress): neither counts, so the pick is worth -1 and it waits."""
    state = State((0, 1, 4), 0)
    assert dist("preference:keep=0.5,shared=-1", paper, state) == [(WAIT, 1.0)]
