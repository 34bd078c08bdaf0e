"""The preference human's action distribution on hand-built states, worked by hand from its rules.

paper2015 indices: objects tape1 0, tape2 1, tape3 2; spots mat_left 0, mat_centre 1,
mat_right 2, mat_shared 3 (the robot reaches it from human_side), human_mat_1 4,
human_mat_2 5 (the human's only); the trashbin is place 6 (the human does not reach
it), the human's hand 8; robot locations bin_side 0 ... human_side 3 (handovers).
Human action indices: pick(o) = o, throw(o) = 3 + o, give(o) = 6 + o, take(o) = 9 + o,
place(o, s) = 12 + 6 o + s, wait = 30.
"""

from __future__ import annotations

import math

import pytest

from hg_marl.agents.humans import HumanError, make_human
from hg_marl.core import State, World

WAIT = 30


@pytest.fixture(scope="module")
def world() -> World:
    return World("paper2015")


def dist(spec: str, world: World, state: State) -> list[tuple[int, float]]:
    return [(i, round(p, 12)) for i, p in make_human(spec).distribution(world, state)]  # type: ignore[attr-defined]


def test_indices_are_the_ones_the_docstring_uses(world: World) -> None:
    names = world.action_names[1]
    assert (names[2], names[8], names[9], names[27], names[28], names[WAIT]) == (
        "pick(tape3)",
        "give(tape3)",
        "take(tape1)",
        "place(tape3,mat_shared)",
        "place(tape3,human_mat_1)",
        "wait",
    )


def test_picks_to_share_when_the_robot_is_away(world: World) -> None:
    # tape3 on human_mat_1, robot at bin_side: after pick(tape3) no throw (no bin in reach),
    # no give (robot not at human_side), place on mat_shared moves it to the robot's side
    # (shared = 0.5), place on human_mat_2 stays on the human's side (no progress, not
    # counted). pick scores 0.5 > 0; p_idle 0.2 mixes in wait.
    state = State((0, 1, 4), 0)
    assert dist("preference:p_idle=0.2", world, state) == [(2, 0.8), (WAIT, 0.2)]


def test_holding_it_gives_rather_than_shares(world: World) -> None:
    # holding tape3 at human_side: give 1.0 > place(mat_shared) 0.5 > wait 0 > keep -1
    state = State((0, 1, 8), 3)
    assert dist("preference", world, state) == [(8, 1.0)]
    # shared 2.0 now beats handover 1.0
    assert dist("preference:shared=2", world, state) == [(27, 1.0)]


def test_haste_prefers_the_quicker_handover(world: World) -> None:
    # shared 1.2 > handover 1.0, but give lasts 1 s and place 2 s: with haste 0.3,
    # give scores 1.0 - 0.3 = 0.7 and place 1.2 - 0.6 = 0.6
    state = State((0, 1, 8), 3)
    assert dist("preference:shared=1.2,haste=0.3", world, state) == [(8, 1.0)]
    # haste 0.6: give 0.4, place 0.0 (not above 0): still give; haste 1.1: give -0.1 -> wait
    assert dist("preference:shared=1.2,haste=0.6", world, state) == [(8, 1.0)]
    assert dist("preference:shared=1.2,haste=1.1", world, state) == [(WAIT, 1.0)]


def test_ties_go_to_the_lowest_index(world: World) -> None:
    # tape2 on human_mat_1, tape3 on human_mat_2: both picks score 0.5 -> pick(tape2)
    state = State((0, 4, 5), 0)
    assert dist("preference", world, state) == [(1, 1.0)]


def test_never_moves_an_object_within_the_robots_side(world: World) -> None:
    # tape3 on mat_shared, robot at bin_side: after the pick only places are feasible;
    # back on mat_shared is its origin, human mats are keep (-1) -> the pick is worth -1
    state = State((0, 1, 3), 0)
    assert dist("preference:shared=1,handover=-1", world, state) == [(WAIT, 1.0)]
    # keep 0.3 (a hoarder): the pick scores keep + robot_side = 0.3 - 0.5 < 0 -> wait;
    # robot_side 0 -> 0.3 > 0 -> it hides tape3 away
    assert dist("preference:keep=0.3", world, state) == [(WAIT, 1.0)]
    assert dist("preference:keep=0.3,robot_side=0", world, state) == [(2, 1.0)]


def test_accepts_an_offer_with_its_probability(world: World) -> None:
    # the robot at human_side offers tape1; tape3 on human_mat_1. take(tape1) with
    # accept 0.25, else the best other action: pick(tape3) (then give: 1.0); p_idle 0.2
    state = State((7, 1, 4), 3, 0, 0)
    assert dist("preference:accept=0.25,p_idle=0.2", world, state) == [(2, 0.6), (9, 0.2), (WAIT, 0.2)]
    assert dist("preference:accept=0", world, state) == [(2, 1.0)]


def test_temperature_draws_from_the_softmax(world: World) -> None:
    # holding tape3 at bin_side: place(mat_shared) 0.5, place(human_mat_1/2) -1, wait 0
    state = State((0, 1, 8), 0)
    weights = {27: math.exp(0.5), 28: math.exp(-1.0), 29: math.exp(-1.0), WAIT: 1.0}
    total = sum(weights.values())
    assert dist("preference:temperature=1", world, state) == [(i, round(w / total, 12)) for i, w in weights.items()]


def test_colour_preference_on_roboergosum() -> None:
    # roboergosum: green1 on placemat3 (2), blue1 on placemat4 (3), the rest in their bins
    # (green_bin 7, blue_bin 8); robot at ROBOT_LOC (handovers). Every spot is within the
    # robot's reach. green1: only give (0.5) follows; blue1: give 0.5 or throw into
    # blue_bin, which the human reaches (0.4). Tie at 0.5 -> pick(green1) = 0; a 0.1
    # bonus for blue -> pick(blue1) = 3.
    world = World("roboergosum")
    state = State((2, 7, 7, 3, 8, 8), 0)
    base = "preference:handover=0.5,self_work=0.4,robot_side=0"
    assert dist(base, world, state) == [(0, 1.0)]
    assert dist(base + ",colour=blue,colour_bonus=0.1", world, state) == [(3, 1.0)]
    assert dist(base + ",colour=red,colour_bonus=0.1", world, state) == [(0, 1.0)]


def test_answers_do_not_depend_on_history(world: World) -> None:
    human = make_human("preference:p_idle=0.1")
    first = State((0, 1, 4), 0)
    answer = human.distribution(world, first)  # type: ignore[attr-defined]
    for where in ((0, 1, 8), (0, 4, 5), (7, 1, 4)):
        human.distribution(world, State(where, 3))  # type: ignore[attr-defined]
    assert human.distribution(world, first) == answer == make_human("preference:p_idle=0.1").distribution(world, first)  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    "spec", ["preference:accept=1.5", "preference:haste=-1", "preference:handover=nan", "preference:handovr=1"]
)
def test_bad_parameters_are_refused(spec: str) -> None:
    with pytest.raises(HumanError):
        make_human(spec)


def test_the_oracle_models_it() -> None:
    from hg_marl.agents.oracle import oracle_rate

    helpful = oracle_rate("paper2015", "preference", progress=False)
    # A hoarder that never hands over, shares or throws hides the human's tape: no task.
    hoarder = oracle_rate("paper2015", "preference:handover=-1,shared=-1,keep=1,robot_side=1", progress=False)
    assert helpful.rate_per_hour > 0
    assert hoarder.rate_per_hour == 0


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum"])
@pytest.mark.parametrize(
    "spec", ["preference", "preference:temperature=0.5,accept=0.3,p_idle=0.2", "preference:keep=0.5,haste=0.2"]
)
def test_distributions_are_feasible_and_sum_to_one(scenario: str, spec: str) -> None:
    import numpy as np

    from hg_marl.core import Agent

    world = World(scenario)
    human = make_human(spec)
    rng = np.random.default_rng(0)
    state = world.initial_state(rng)
    for _ in range(400):
        robot = world.feasible_indices(state, Agent.ROBOT)
        state = world.step(state, Agent.ROBOT, int(robot[rng.integers(len(robot))])).state
        answer = human.distribution(world, state)  # type: ignore[attr-defined]
        assert sum(p for _, p in answer) == pytest.approx(1.0)
        assert all(p > 0 and world.table.feasible(state, Agent.HUMAN, i) for i, p in answer)
        assert [i for i, _ in answer] == sorted({i for i, _ in answer})
        state = world.step(state, Agent.HUMAN, answer[int(rng.integers(len(answer)))][0]).state
        if world.is_clean(state):
            state = world.initial_state(rng)
