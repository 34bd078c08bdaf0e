"""The ``cooperative`` human (``agents/humans/cooperative.py``), pinned for the mutation gate.

The cooperative human executes the human stream of the planner's shared plan; its
answers are checked against a reference: a fresh :class:`Planner` (``cache_suffixes``
off, no human model, as the module builds it) asked for its intent with ``to_move=HUMAN``
and the robot action under way (None when unknown). The robot action classes are worked
by hand from ``paper2015``'s durations (pick 2, throw 2, give 1, take 1.5, goto 3,
wait 1 s): the robot's 18 actions are pick x3, throw x3, give x3, take x3, goto x5, wait.
"""

from __future__ import annotations

from dataclasses import replace

from hg_marl.agents.humans.cooperative import CooperativeHuman, seen_representatives
from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.core import Agent, State, World

PAPER = World("paper2015")
GOTO_TAPE1 = 12
"""The robot's ``goto(tape1)``: 3 s, long enough for a 2 s human action in parallel."""


def planned(world: World, state: State, robot_action: int | None) -> str:
    """The reference: the human action of a cold planner's intent, ``wait`` when it has none."""
    planner = Planner(world, config=replace(PlannerConfig(), cache_suffixes=False), human_model=None)
    intent = planner.intent(state, to_move=Agent.HUMAN, robot_action=robot_action)
    ok = intent.success and intent.human_action >= 0
    return world.action_names[Agent.HUMAN][intent.human_action] if ok else "wait"


def answer(human: CooperativeHuman, world: World, state: State, *robot_action: int) -> str:
    ((index, p),) = human.distribution(world, state, *robot_action)
    assert p == 1.0
    return world.action_names[Agent.HUMAN][index]


def test_robot_actions_are_grouped_by_duration_and_by_being_a_wait_or_a_give() -> None:
    """pick and throw (2 s) share one class, give (1 s), take (1.5 s), goto (3 s) and wait (1 s) their own."""
    assert seen_representatives(PAPER) == [0] * 6 + [6] * 3 + [9] * 3 + [12] * 5 + [17]
    assert CooperativeHuman().seen_representatives(PAPER) == seen_representatives(PAPER)


def test_a_robot_wait_is_its_own_class_even_beside_an_action_as_short() -> None:
    """With ``take`` shortened to 1 s (wait's length), the robot's wait stays apart: a wait is no activity."""
    same_length = World("paper2015", durations=replace(PAPER.durations, take=1.0))
    assert seen_representatives(same_length) == [0] * 6 + [6] * 3 + [9] * 3 + [12] * 5 + [17]


def swap23(text: str) -> str:
    return text.replace("tape2", "#").replace("tape3", "tape2").replace("#", "tape3")


def test_the_cooperative_human_is_equivariant_under_swapping_interchangeable_objects() -> None:
    """``asymmetric_advantages``: tape2 and tape3 share their bins; swapping their places swaps the answer's name.

    (The lazy human, which picks the first object by index, is not: see
    ``test_pinned_human_base_gate.py``.)
    """
    assert CooperativeHuman.equivariant is True
    world = World("asymmetric_advantages")
    human = CooperativeHuman()
    for where, robot_at in (((0, 1, 2, 3), 0), ((6, 1, 2, 3), 0), ((0, 1, 2, 7), 1), ((4, 1, 3, 2), 0)):
        swapped = (where[0], where[2], where[1], where[3])
        first = answer(human, world, State(where, robot_at))
        assert answer(human, world, State(swapped, robot_at)) == swap23(first)
    assert answer(human, world, State((0, 1, 2, 3), 0)) == "pick(tape2)"  # so the swap is seen at work


def test_a_known_robot_action_lets_the_human_work_in_parallel_and_an_unknown_one_does_not() -> None:
    """Holding tape3 with the robot at ``table_left``: each answer is the planner's for that robot action.

    The robot's goto (3 s) leaves time for the 2 s place; without the robot's action the
    planner sees a cycle as long as the human's own. The two answers differ, so each
    rule (known, unknown, the default) is seen.
    """
    state = State((0, 1, 8), 1)
    unknown, known = planned(PAPER, state, None), planned(PAPER, state, GOTO_TAPE1)
    assert unknown != known
    human = CooperativeHuman()
    assert answer(human, PAPER, state, GOTO_TAPE1) == known
    assert answer(human, PAPER, state, -1) == unknown
    assert answer(CooperativeHuman(), PAPER, state) == unknown  # the default is "unknown"
    assert PAPER.action_names[Agent.HUMAN][CooperativeHuman().planned_action(PAPER, state)] == unknown
    # pick(tape1) is robot action 0: known too, and answered as its class (pick, 2 s)
    assert answer(CooperativeHuman(), PAPER, state, 0) == planned(PAPER, state, 0)
    assert planned(PAPER, state, 0) == known


def test_an_unknown_robot_action_is_not_read_as_a_robot_wait() -> None:
    """With a 3 s wait, a robot known to wait leaves the human time it does not have when unknown.

    ``wait`` is the robot's last action; taking "unknown" (-1) for it would answer as the
    planner does for a robot wait, which differs here.
    """
    slow_wait = World("paper2015", durations=replace(PAPER.durations, wait=3.0))
    state = State((0, 1, 8), 1)
    assert planned(slow_wait, state, None) != planned(slow_wait, state, 17)
    assert answer(CooperativeHuman(), slow_wait, state, -1) == planned(slow_wait, state, None)
    assert answer(CooperativeHuman(), slow_wait, state) == planned(slow_wait, state, None)


def test_an_offer_is_not_taken_while_the_humans_hand_holds_tape1() -> None:
    """The robot offers tape2 at ``human_side`` while the human holds tape1 (object 0): a full hand takes nothing."""
    state = State((8, 7, 1), 3, int(Agent.ROBOT), 1)
    got = answer(CooperativeHuman(), PAPER, state)
    assert got != "take(tape2)"
    assert got == planned(PAPER, state, None)


def test_the_planner_is_built_once_per_world() -> None:
    """Built on first use and kept while the world is the same; a new world gets its own."""
    human = CooperativeHuman()
    first = human.planner(PAPER)
    assert human.planner(PAPER) is first
    other = World("asymmetric_advantages")
    assert human.planner(other) is not first
    assert human.planner(other).world is other
