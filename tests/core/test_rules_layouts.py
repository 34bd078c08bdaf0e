"""Rules on a layout beyond paper2015: two coloured bins, several robot locations reaching
one spot, a bin the human reaches. Expected outcomes come from the rules as docs/environment.md
states them (goto moves to the first reaching location in scenario order and is
infeasible when the target is already in reach; an object goes into the bin of its
colour; give needs the robot at a handover location; success is a robot wait on a
clean table)."""

from __future__ import annotations

import pytest

from hg_marl.core import Agent, State, World

R, H = Agent.ROBOT, Agent.HUMAN

LAYOUT = """
name = "two_bins"
description = "two coloured bins, a spot reached from two robot locations"
robot_locations = ["loc_a", "loc_b", "loc_c", "loc_d"]
handover_locations = ["loc_d"]
robot_start = ["loc_a"]
[[objects]]
name = "red1"
colour = "red"
[[objects]]
name = "blue1"
colour = "blue"
[[bins]]
name = "red_bin"
colour = "red"
robot_reach = ["loc_a"]
human_reach = false
[[bins]]
name = "blue_bin"
colour = "blue"
robot_reach = ["loc_d", "loc_c"]
human_reach = true
[[spots]]
name = "mat"
robot_reach = ["loc_c", "loc_b"]
[[spots]]
name = "shelf"
robot_reach = ["loc_a"]
[[spots]]
name = "human_mat"
human_reach = true
[[layout]]
count = 2
spots = ["mat", "shelf", "human_mat"]
"""
# place codes: spots mat 0, shelf 1, human_mat 2; bins red 3, blue 4; robot hand 5, human hand 6
MAT, SHELF, HMAT, RED_BIN, BLUE_BIN, RHAND, HHAND = range(7)
LOC_A, LOC_B, LOC_C, LOC_D = range(4)
RED, BLUE = 0, 1


@pytest.fixture(scope="module")
def w(tmp_path_factory: pytest.TempPathFactory) -> World:
    path = tmp_path_factory.mktemp("layout") / "two_bins.toml"
    path.write_text(LAYOUT)
    return World(str(path))


def do(w: World, state: State, agent: Agent, name: str) -> tuple[bool, State, float]:
    out = w.step(state, agent, w.action_names[agent].index(name))
    return out.ok, out.state, out.reward


def test_action_names(w: World) -> None:
    gotos = [n for n in w.action_names[R] if n.startswith("goto")]
    assert gotos == ["goto(red1)", "goto(blue1)", "goto(red_bin)", "goto(blue_bin)", "goto(human)"]
    assert list(w.bin_of) == [RED, BLUE]


@pytest.mark.parametrize(
    ("at", "target", "dest"),
    [
        (LOC_A, "goto(red1)", LOC_B),  # mat reached from loc_c and loc_b: loc_b comes first in robot_locations
        (LOC_D, "goto(red1)", LOC_B),
        (LOC_B, "goto(red1)", None),  # already in reach
        (LOC_C, "goto(red1)", None),  # in reach from the other reaching location too
        (LOC_A, "goto(blue_bin)", LOC_C),  # blue bin reached from loc_d and loc_c: loc_c first
        (LOC_C, "goto(blue_bin)", None),
        (LOC_B, "goto(red_bin)", LOC_A),
        (LOC_A, "goto(human)", LOC_D),
        (LOC_D, "goto(human)", None),
        (LOC_B, "goto(blue1)", LOC_A),  # blue1 on the shelf: only loc_a reaches it
    ],
)
def test_goto_goes_to_first_reaching_location(w: World, at: int, target: str, dest: int | None) -> None:
    state = State((MAT, SHELF), at)
    ok, after, _ = do(w, state, R, target)
    if dest is None:
        assert not ok and after == state
    else:
        assert ok and after.robot_at == dest and after.where == state.where


@pytest.mark.parametrize("at", [LOC_B, LOC_C])
def test_pick_from_either_reaching_location(w: World, at: int) -> None:
    ok, after, _ = do(w, State((MAT, SHELF), at), R, "pick(red1)")
    assert ok and after.where == (RHAND, SHELF)
    ok, _, _ = do(w, State((MAT, SHELF), LOC_A), R, "pick(red1)")
    assert not ok


@pytest.mark.parametrize(
    ("agent", "where", "at", "action", "ok", "after"),
    [
        (R, (RHAND, SHELF), LOC_A, "throw(red1)", True, (RED_BIN, SHELF)),  # red bin from loc_a
        (R, (RHAND, SHELF), LOC_C, "throw(red1)", False, None),  # loc_c reaches the blue bin only
        (R, (MAT, RHAND), LOC_C, "throw(blue1)", True, (MAT, BLUE_BIN)),
        (R, (MAT, RHAND), LOC_D, "throw(blue1)", True, (MAT, BLUE_BIN)),
        (R, (MAT, RHAND), LOC_A, "throw(blue1)", False, None),  # the red bin's place is not blue1's bin
        (H, (MAT, HHAND), LOC_A, "throw(blue1)", True, (MAT, BLUE_BIN)),  # the human reaches the blue bin
        (H, (HHAND, SHELF), LOC_A, "throw(red1)", False, None),  # but not the red one
        (H, (HMAT, SHELF), LOC_A, "pick(red1)", True, (HHAND, SHELF)),
        (H, (MAT, SHELF), LOC_A, "pick(red1)", False, None),  # the human does not reach the mat
    ],
)
def test_objects_go_into_their_own_bin(
    w: World, agent: Agent, where: tuple[int, int], at: int, action: str, ok: bool, after: tuple[int, int] | None
) -> None:
    state = State(where, at)
    done, new, _ = do(w, state, agent, action)
    assert done is ok
    assert new.where == (after if ok else where)


def test_give_needs_the_handover_location(w: World) -> None:
    assert not do(w, State((RHAND, SHELF), LOC_B), R, "give(red1)")[0]
    ok, after, _ = do(w, State((RHAND, SHELF), LOC_D), R, "give(red1)")
    assert ok and (after.offer_by, after.offer_obj) == (int(R), RED)
    ok, taken, _ = do(w, after, H, "take(red1)")
    assert ok and taken.where == (HHAND, SHELF) and taken.offer_by == -1


def test_success_needs_every_object_in_its_own_bin(w: World) -> None:
    assert do(w, State((RED_BIN, BLUE_BIN), LOC_B), R, "wait")[2] == 1.0
    assert do(w, State((RED_BIN, SHELF), LOC_B), R, "wait")[2] == 0.0
    assert do(w, State((RED_BIN, BLUE_BIN), LOC_B), H, "wait")[2] == 0.0  # the robot's wait completes it
    assert w.is_clean(State((RED_BIN, BLUE_BIN), LOC_A)) and not w.is_clean(State((BLUE_BIN, RED_BIN), LOC_A))


def test_layout_draws_two_distinct_spots(w: World) -> None:
    import numpy as np

    rng = np.random.default_rng(0)
    for _ in range(20):
        s = w.initial_state(rng)
        assert len(set(s.where)) == 2 and set(s.where) <= {MAT, SHELF, HMAT} and s.robot_at == LOC_A


def test_place_names(w: World) -> None:
    names = [w.place_name(p) for p in range(7)]
    assert names == ["mat", "shelf", "human_mat", "red_bin", "blue_bin", "robot's hand", "human's hand"]


def test_only_the_two_bin_codes_are_bins(w: World) -> None:
    # place codes 3 and 4 are the bins (the comment above the fixture); spots and hands are not
    assert [w.is_in_bin(p) for p in range(7)] == [False, False, False, True, True, False, False]


def facts(w: World, state: State) -> dict[str, int]:
    return dict(zip(w.fact_names, w.facts(state).tolist(), strict=True))


def test_facts_robot_holding_at_a_bin_location(w: World) -> None:
    # red1 in the robot's hand, blue1 in its bin, robot at loc_c (reaches the mat and the blue bin)
    assert facts(w, State((RHAND, BLUE_BIN), LOC_C)) == {
        "isReachableBy(red1,robot)": 0,  # in a hand, not on a spot
        "isReachableBy(blue1,robot)": 0,  # in a bin
        "isReachableBy(red_bin,robot)": 0,  # only from loc_a
        "isReachableBy(blue_bin,robot)": 1,
        "isReachableBy(red1,human)": 0,
        "isReachableBy(blue1,human)": 0,
        "isReachableBy(red_bin,human)": 0,
        "isReachableBy(blue_bin,human)": 1,
        "isIn(red1,red_bin)": 0,
        "isIn(blue1,blue_bin)": 1,
        "isReachableBy(human,robot)": 0,  # loc_c is not a handover location
        "hasInHand(robot,red1)": 1,
        "hasInHand(robot,blue1)": 0,
        "hasInHand(human,red1)": 0,
        "hasInHand(human,blue1)": 0,
        "isOffering(robot,red1)": 0,
        "isOffering(robot,blue1)": 0,
        "isOffering(human,red1)": 0,
        "isOffering(human,blue1)": 0,
    }


def test_facts_human_offering_at_the_handover_location(w: World) -> None:
    # the human holds red1 out to the robot at loc_d; blue1 on the shelf (reached from loc_a only)
    assert facts(w, State((HHAND, SHELF), LOC_D, offer_by=int(H), offer_obj=RED)) == {
        "isReachableBy(red1,robot)": 0,
        "isReachableBy(blue1,robot)": 0,
        "isReachableBy(red_bin,robot)": 0,
        "isReachableBy(blue_bin,robot)": 1,  # loc_d reaches the blue bin
        "isReachableBy(red1,human)": 0,
        "isReachableBy(blue1,human)": 0,
        "isReachableBy(red_bin,human)": 0,
        "isReachableBy(blue_bin,human)": 1,
        "isIn(red1,red_bin)": 0,  # in a hand (a place code above the bins'), not in the bin
        "isIn(blue1,blue_bin)": 0,
        "isReachableBy(human,robot)": 1,
        "hasInHand(robot,red1)": 0,
        "hasInHand(robot,blue1)": 0,
        "hasInHand(human,red1)": 1,
        "hasInHand(human,blue1)": 0,
        "isOffering(robot,red1)": 0,
        "isOffering(robot,blue1)": 0,
        "isOffering(human,red1)": 1,
        "isOffering(human,blue1)": 0,
    }


def test_facts_objects_on_reachable_spots(w: World) -> None:
    # red1 on the mat (robot at loc_b reaches it), blue1 on the human's mat
    on = {k for k, v in facts(w, State((MAT, HMAT), LOC_B)).items() if v}
    assert on == {"isReachableBy(red1,robot)", "isReachableBy(blue1,human)", "isReachableBy(blue_bin,human)"}
    # from loc_a the robot reaches the red bin and the shelf, not the mat
    on = {k for k, v in facts(w, State((MAT, SHELF), LOC_A)).items() if v}
    assert on == {"isReachableBy(blue1,robot)", "isReachableBy(red_bin,robot)", "isReachableBy(blue_bin,human)"}
