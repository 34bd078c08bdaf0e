"""Table-driven tests of each action's preconditions and effects on hand-built states."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.core import WAIT, Action, Agent, Kind, State, World

R, H = Agent.ROBOT, Agent.HUMAN
# paper2015 place codes (see conftest): spots 0-5, bin 6, robot hand 7, human hand 8.
LEFT, CENTRE, RIGHT, SHARED, HMAT1, HMAT2, BIN, RHAND, HHAND = range(9)
BIN_SIDE, TABLE_LEFT, TABLE_RIGHT, HUMAN_SIDE = range(4)
GOTO_BIN, GOTO_HUMAN = 3, 4  # goto target codes: objects 0-2, bin 3, human 4


def s(where: tuple[int, ...], at: int = BIN_SIDE, offer_by: int = -1, offer_obj: int = -1) -> State:
    return State(where, at, offer_by, offer_obj)


CASES = [
    # (id, state, agent, action, feasible, expected where, expected robot_at, expected offer)
    (
        "robot picks reachable",
        s((LEFT, RIGHT, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.PICK, 0),
        True,
        (RHAND, RIGHT, HMAT1),
        TABLE_LEFT,
        (-1, -1),
    ),
    (
        "robot cannot pick out of reach",
        s((LEFT, RIGHT, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.PICK, 1),
        False,
        None,
        None,
        None,
    ),
    (
        "robot cannot pick human-side",
        s((LEFT, RIGHT, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.PICK, 2),
        False,
        None,
        None,
        None,
    ),
    (
        "robot cannot pick with full hand",
        s((RHAND, CENTRE, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.PICK, 1),
        False,
        None,
        None,
        None,
    ),
    (
        "robot throws at bin",
        s((RHAND, CENTRE, HMAT1), BIN_SIDE),
        R,
        Action(Kind.THROW, 0),
        True,
        (BIN, CENTRE, HMAT1),
        BIN_SIDE,
        (-1, -1),
    ),
    (
        "robot cannot throw away from bin",
        s((RHAND, CENTRE, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.THROW, 0),
        False,
        None,
        None,
        None,
    ),
    (
        "robot cannot throw what it lacks",
        s((LEFT, CENTRE, HMAT1), BIN_SIDE),
        R,
        Action(Kind.THROW, 0),
        False,
        None,
        None,
        None,
    ),
    (
        "robot goes to object",
        s((LEFT, RIGHT, HMAT1), BIN_SIDE),
        R,
        Action(Kind.GOTO, -1, 1),
        True,
        (LEFT, RIGHT, HMAT1),
        TABLE_RIGHT,
        (-1, -1),
    ),
    (
        "goto to what is in reach fails",
        s((LEFT, RIGHT, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.GOTO, -1, 0),
        False,
        None,
        None,
        None,
    ),
    (
        "goto unreachable object fails",
        s((LEFT, RIGHT, HMAT1), BIN_SIDE),
        R,
        Action(Kind.GOTO, -1, 2),
        False,
        None,
        None,
        None,
    ),
    (
        "goto held object fails",
        s((RHAND, RIGHT, HMAT1), BIN_SIDE),
        R,
        Action(Kind.GOTO, -1, 0),
        False,
        None,
        None,
        None,
    ),
    (
        "robot goes to bin",
        s((RHAND, RIGHT, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.GOTO, -1, GOTO_BIN),
        True,
        (RHAND, RIGHT, HMAT1),
        BIN_SIDE,
        (-1, -1),
    ),
    (
        "robot goes to human",
        s((RHAND, RIGHT, HMAT1), TABLE_LEFT),
        R,
        Action(Kind.GOTO, -1, GOTO_HUMAN),
        True,
        (RHAND, RIGHT, HMAT1),
        HUMAN_SIDE,
        (-1, -1),
    ),
    (
        "robot gives at human side",
        s((RHAND, RIGHT, HMAT1), HUMAN_SIDE),
        R,
        Action(Kind.GIVE, 0),
        True,
        (RHAND, RIGHT, HMAT1),
        HUMAN_SIDE,
        (R, 0),
    ),
    (
        "robot cannot give far from human",
        s((RHAND, RIGHT, HMAT1), BIN_SIDE),
        R,
        Action(Kind.GIVE, 0),
        False,
        None,
        None,
        None,
    ),
    (
        "human takes the offer",
        s((RHAND, RIGHT, HMAT1), HUMAN_SIDE, R, 0),
        H,
        Action(Kind.TAKE, 0),
        True,
        (HHAND, RIGHT, HMAT1),
        HUMAN_SIDE,
        (-1, -1),
    ),
    (
        "human cannot take unoffered",
        s((RHAND, RIGHT, HMAT1), HUMAN_SIDE),
        H,
        Action(Kind.TAKE, 0),
        False,
        None,
        None,
        None,
    ),
    (
        "human picks own side",
        s((LEFT, RIGHT, HMAT1)),
        H,
        Action(Kind.PICK, 2),
        True,
        (LEFT, RIGHT, HHAND),
        BIN_SIDE,
        (-1, -1),
    ),
    ("human cannot pick robot side", s((LEFT, RIGHT, HMAT1)), H, Action(Kind.PICK, 0), False, None, None, None),
    (
        "human cannot throw: bin out of reach",
        s((LEFT, RIGHT, HHAND)),
        H,
        Action(Kind.THROW, 2),
        False,
        None,
        None,
        None,
    ),
    (
        "human places on shared mat",
        s((LEFT, RIGHT, HHAND)),
        H,
        Action(Kind.PLACE, 2, SHARED),
        True,
        (LEFT, RIGHT, SHARED),
        BIN_SIDE,
        (-1, -1),
    ),
    (
        "human cannot place on robot side",
        s((LEFT, RIGHT, HHAND)),
        H,
        Action(Kind.PLACE, 2, LEFT),
        False,
        None,
        None,
        None,
    ),
    (
        "human cannot place on occupied",
        s((SHARED, RIGHT, HHAND)),
        H,
        Action(Kind.PLACE, 2, SHARED),
        False,
        None,
        None,
        None,
    ),
    (
        "human gives only with robot near",
        s((LEFT, RIGHT, HHAND), BIN_SIDE),
        H,
        Action(Kind.GIVE, 2),
        False,
        None,
        None,
        None,
    ),
    (
        "human gives with robot near",
        s((LEFT, RIGHT, HHAND), HUMAN_SIDE),
        H,
        Action(Kind.GIVE, 2),
        True,
        (LEFT, RIGHT, HHAND),
        HUMAN_SIDE,
        (H, 2),
    ),
    (
        "robot takes the human's offer",
        s((LEFT, RIGHT, HHAND), HUMAN_SIDE, H, 2),
        R,
        Action(Kind.TAKE, 2),
        True,
        (LEFT, RIGHT, RHAND),
        HUMAN_SIDE,
        (-1, -1),
    ),
    (
        "robot with full hand cannot take",
        s((RHAND, RIGHT, HHAND), HUMAN_SIDE, H, 2),
        R,
        Action(Kind.TAKE, 2),
        False,
        None,
        None,
        None,
    ),
    ("wait always feasible", s((LEFT, RIGHT, HMAT1)), R, WAIT, True, (LEFT, RIGHT, HMAT1), BIN_SIDE, (-1, -1)),
]


@pytest.mark.parametrize(
    ("state", "agent", "action", "ok", "where", "at", "offer"), [c[1:] for c in CASES], ids=[c[0] for c in CASES]
)
def test_preconditions_and_effects(paper: World, state, agent, action, ok, where, at, offer) -> None:
    out = paper.apply(state, agent, action)
    assert out.ok is ok
    assert paper.feasible(state, agent, action) is ok
    if ok:
        assert out.state.where == where
        assert out.state.robot_at == at
        assert (out.state.offer_by, out.state.offer_obj) == offer
        assert out.duration == paper.durations.of(action.kind)
    else:
        assert out.state.where == state.where and out.state.robot_at == state.robot_at, "no effect"
        if state.offer_by == agent.other:
            assert out.state.offer_by == -1, "any reply but a successful take lets the offer lapse"
        else:
            assert out.state == state
        assert out.duration == paper.durations.failed
        assert any(e.kind == "failed" for e in out.events)


def test_handover_completed(paper: World) -> None:
    state = s((LEFT, RIGHT, HHAND), HUMAN_SIDE)
    give = paper.index(H, Action(Kind.GIVE, 2))
    take = paper.index(R, Action(Kind.TAKE, 2))
    after_give = paper.step(state, H, give)
    assert after_give.state.offer_by == H and after_give.state.where[2] == HHAND, "the giver keeps it until taken"
    after_take = paper.step(after_give.state, R, take)
    assert after_take.ok and after_take.state.where[2] == RHAND and after_take.state.offer_by == -1


def test_handover_lapses_on_any_other_reply(paper: World) -> None:
    state = s((LEFT, RIGHT, HHAND), HUMAN_SIDE, H, 2)
    out = paper.step(state, R, paper.index(R, WAIT))
    assert out.state.offer_by == -1 and out.state.where[2] == HHAND
    assert out.events[0].kind == "let_lapse"
    # after the lapse the robot can no longer take it
    assert not paper.feasible(out.state, R, Action(Kind.TAKE, 2))


def test_success_needs_clean_table_and_robot_wait(paper: World) -> None:
    clean = s((BIN, BIN, BIN))
    assert paper.is_clean(clean)
    assert paper.step(clean, R, paper.index(R, WAIT)).reward == 1.0
    assert paper.step(clean, H, paper.index(H, WAIT)).reward == 0.0, "only the robot's wait completes the task"
    assert paper.step(s((BIN, BIN, RHAND)), R, paper.index(R, WAIT)).reward == 0.0


def test_initial_state_follows_layout(paper: World) -> None:
    rng = np.random.default_rng(0)
    for _ in range(200):
        st = paper.initial_state(rng)
        robot_side = [p for p in st.where if p in (LEFT, CENTRE, RIGHT)]
        human_side = [p for p in st.where if p in (HMAT1, HMAT2)]
        assert len(robot_side) == 2 and len(set(robot_side)) == 2 and len(human_side) == 1
        assert st.robot_at == BIN_SIDE and st.offer_by == -1


def test_initial_state_is_seeded(roboergosum: World) -> None:
    a = [roboergosum.initial_state(np.random.default_rng(7)) for _ in range(3)]
    assert a[0] == a[1] == a[2]
    assert len(set(a[0].where)) == 6, "distinct placemats"


def test_action_names_and_sizes(paper: World, roboergosum: World) -> None:
    assert paper.n_actions(R) == 18, "the paper's 18 robot actions"
    assert paper.action_names[R][0] == "pick(tape1)" and paper.action_names[R][-1] == "wait"
    assert "place(tape3,mat_shared)" in paper.action_names[H]
    assert roboergosum.n_actions(R) == 34
    assert len(set(paper.action_names[H])) == paper.n_actions(H)


def test_facts(paper: World) -> None:
    state = s((LEFT, RHAND, HHAND), HUMAN_SIDE, H, 2)
    facts = dict(zip(paper.fact_names, paper.facts(state), strict=True))
    assert len(facts) == 24
    assert facts["isReachableBy(tape1,robot)"] == 0  # robot at human_side
    assert facts["isReachableBy(human,robot)"] == 1
    assert facts["hasInHand(robot,tape2)"] == 1 and facts["hasInHand(human,tape3)"] == 1
    assert facts["isOffering(human,tape3)"] == 1 and facts["isOffering(robot,tape3)"] == 0
    assert facts["isReachableBy(trashbin,robot)"] == 0 and facts["isReachableBy(trashbin,human)"] == 0
    assert not paper.facts(state).flags.writeable, "cached arrays are read-only"


def test_generated_scenario_is_seeded() -> None:
    a, b = World("generated:objects=5,spots=8,seed=3"), World("generated:objects=5,spots=8,seed=3")
    assert a.scenario == b.scenario
    assert a.scenario != World("generated:objects=5,spots=8,seed=4").scenario
    assert a.n_objects == 5 and a.n_spots == 8


def test_failed_take_lets_the_offer_lapse(paper: World) -> None:
    # the robot holds tape1 and cannot take tape3: its failed take is a reply, so the offer lapses
    state = s((RHAND, RIGHT, HHAND), HUMAN_SIDE, H, 2)
    out = paper.step(state, R, paper.index(R, Action(Kind.TAKE, 2)))
    assert not out.ok
    assert (out.state.offer_by, out.state.offer_obj) == (-1, -1) and out.state.where == state.where
    assert [e.kind for e in out.events] == ["failed", "let_lapse"]


def test_throw_reports_a_threw_event_naming_the_bin(paper: World) -> None:
    # the robot at the bin side holds tape1 and throws it: one event, "robot threw tape1 into trashbin"
    state = s((RHAND, CENTRE, HMAT1), BIN_SIDE)
    out = paper.step(state, R, paper.index(R, Action(Kind.THROW, 0)))
    assert out.ok and out.state.where == (BIN, CENTRE, HMAT1)
    assert [tuple(e) for e in out.events] == [("threw", "robot", "tape1", "trashbin")]
    assert out.reward == 0.0
