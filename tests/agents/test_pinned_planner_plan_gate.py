"""A plan's streams, methods and links, its failure value and its action distribution, pinned.

What ``hg-marl plan`` and the Gantt chart show is derived from a plan's cycles
(``agents/planner/plan.py``): each agent's steps timed by the cycles, the ``dispose``
method each object's steps belong to, and the links between the streams. The expected
values are worked by hand from the layouts below and ``test_planner_hand.py``'s durations
(a cycle lasts its longer action; the robot's step starts with the cycle) and from the
rules the module's docstrings state; the links are also checked on hand-made streams where
each clause of the rule decides the answer.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from test_planner_hand import HANDOVER as TO_THE_ROBOT
from test_planner_hand import world as layout

from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.plan import NO_ACTION, Link, PlanResult, Step, _label_methods, _links, build_plan, failure
from hg_marl.core import Agent, State, World

R, H = Agent.ROBOT, Agent.HUMAN

TO_THE_HUMAN = """
name = "to_the_human"
description = "one tape only the robot reaches; the bin only the human reaches"
robot_locations = ["table", "human_side"]
handover_locations = ["human_side"]
robot_start = ["table"]
[[objects]]
name = "tape"
[[bins]]
name = "bin"
robot_reach = []
human_reach = true
[[spots]]
name = "mat"
robot_reach = ["table"]
human_reach = false
[[layout]]
count = 1
spots = ["mat"]
"""


def named(world: World, stream: tuple[Step, ...]) -> list[tuple[str, int, float, float, int, str]]:
    return [(s.name, s.cycle, s.start, s.end, s.obj, s.method) for s in stream]


def test_a_handover_to_the_robot_is_timed_labelled_and_linked(tmp_path: Path) -> None:
    # the optimal plan (worked in test_planner_hand.py): cycles of 3, 1, 1.5, 3, 2, 1 s
    # starting at 0, 3, 4, 5.5, 8.5, 10.5; each step starts with its cycle and lasts its
    # own duration. The tape is given by the human: every step on it is "handover_h2r".
    world = layout(tmp_path, TO_THE_ROBOT)
    plan = Planner(world).plan(State((0,), 0)).plan
    assert plan is not None
    robot, human = plan.streams
    assert named(world, robot) == [
        ("goto(human)", 0, 0.0, 3.0, -1, ""),
        ("wait", 1, 3.0, 4.0, -1, ""),
        ("take(tape)", 2, 4.0, 5.5, 0, "handover_h2r"),
        ("goto(bin)", 3, 5.5, 8.5, -1, ""),
        ("throw(tape)", 4, 8.5, 10.5, 0, "handover_h2r"),
        ("wait", 5, 10.5, 11.5, -1, ""),
    ]
    assert named(world, human) == [
        ("pick(tape)", 0, 0.0, 2.0, 0, "handover_h2r"),
        ("give(tape)", 1, 3.0, 4.0, 0, "handover_h2r"),
        ("wait", 2, 4.0, 5.0, -1, ""),
        ("wait", 3, 5.5, 6.5, -1, ""),
        ("wait", 4, 8.5, 9.5, -1, ""),
        ("wait", 5, 10.5, 11.5, -1, ""),
    ]
    # the human's give (its step 1, cycle 1) is taken in the next cycle by the robot's step 2;
    # the robot's wait in cycle 1 waits for that give (its next step, the take, needs it)
    assert plan.links == (
        Link("handover", (H, 1), (R, 2)),
        Link("waits_for", (H, 1), (R, 1)),
    )
    assert len(plan) == 6 and plan.duration == pytest.approx(11.5)


def test_a_handover_to_the_human_is_timed_labelled_and_linked(tmp_path: Path) -> None:
    # pick 2 s | goto 3 s | give 1 s with the human's take 1.5 s | the human's throw 2 s |
    # the completing wait: cycles of 2, 3, 1.5, 2, 1 s starting at 0, 2, 5, 6.5, 8.5
    world = layout(tmp_path, TO_THE_HUMAN)
    plan = Planner(world).plan(State((0,), 0)).plan
    assert plan is not None
    robot, human = plan.streams
    assert named(world, robot) == [
        ("pick(tape)", 0, 0.0, 2.0, 0, "handover_r2h"),
        ("goto(human)", 1, 2.0, 5.0, -1, ""),
        ("give(tape)", 2, 5.0, 6.0, 0, "handover_r2h"),
        ("wait", 3, 6.5, 7.5, -1, ""),
        ("wait", 4, 8.5, 9.5, -1, ""),
    ]
    assert named(world, human) == [
        ("wait", 0, 0.0, 1.0, -1, ""),
        ("wait", 1, 2.0, 3.0, -1, ""),
        ("take(tape)", 2, 5.0, 6.5, 0, "handover_r2h"),
        ("throw(tape)", 3, 6.5, 8.5, 0, "handover_r2h"),
        ("wait", 4, 8.5, 9.5, -1, ""),
    ]
    # the robot's give is taken in the same cycle; each of the human's first two waits waits
    # for the give, the robot's last step on the tape before the take (the pick in cycle 0 is
    # earlier); the robot's waits and the human's last one have no later step on an object
    assert plan.links == (
        Link("handover", (R, 2), (H, 2)),
        Link("waits_for", (R, 2), (H, 0)),
        Link("waits_for", (R, 2), (H, 1)),
    )


PAPER = World("paper2015")


def step(agent: Agent, name: str, cycle: int) -> Step:
    """A step of ``paper2015`` by its action's name (tape1..3 are objects 0..2)."""
    index = PAPER.action_names[agent].index(name)
    return Step(agent, index, name, cycle, float(cycle), float(cycle) + 1.0, PAPER.actions(agent)[index].obj, "")


def test_a_give_is_linked_to_the_partners_take_of_that_object_in_the_cycle_the_rules_answer_it() -> None:
    # a robot's give is answered by the human in the same cycle; a human's give by the robot
    # in the next one. Takes of another object, or in another cycle, are not handovers.
    robot = (
        step(R, "give(tape1)", 0),
        step(R, "take(tape2)", 1),  # the cycle of the human's give of tape2: too early
        step(R, "take(tape3)", 2),  # the cycle of the human's give of tape3: too early
        step(R, "take(tape3)", 3),  # the cycle after it: the handover
    )
    human = (
        step(H, "take(tape1)", 0),  # the cycle of the robot's give of tape1: the handover
        step(H, "give(tape2)", 1),  # the robot's step in cycle 2 takes another object
        step(H, "give(tape3)", 2),
        step(H, "take(tape2)", 3),  # nobody gave tape2 in this cycle
    )
    links = [link for link in _links(PAPER, robot, human) if link.kind == "handover"]
    assert links == [Link("handover", (R, 0), (H, 0)), Link("handover", (H, 2), (R, 3))]


def test_a_wait_is_linked_to_the_partners_last_step_on_the_object_its_next_step_needs() -> None:
    # The rule: for a wait at cycle c whose agent's next non-wait step n is on an object, the
    # source is the partner's last step on that object from cycle c on that comes before n
    # in execution order (the robot acts first in a cycle: a human's wait may have a robot
    # step of n's own cycle as its source, the robot's may not). The streams are made by hand
    # to let each clause decide (they need not be a plan the rules allow).
    robot = (
        step(R, "goto(human)", 0),  # a step before the waits, on no object
        step(R, "wait", 1),
        step(R, "wait", 2),
        step(R, "take(tape2)", 3),  # the robot waits' next step: on tape2
        step(R, "pick(tape3)", 4),
        step(R, "give(tape3)", 5),
        step(R, "throw(tape3)", 6),  # on tape3, after the human's take of it
    )
    human = (
        step(H, "pick(tape2)", 0),  # on tape2, before both robot waits' cycles
        step(H, "give(tape2)", 1),  # on tape2, in the first robot wait's cycle
        step(H, "wait", 2),  # on no object
        step(H, "place(tape2,mat_left)", 3),  # on tape2, in the cycle of the robot's take
        step(H, "wait", 4),
        step(H, "take(tape3)", 5),  # the second human wait's next step: on tape3
        step(H, "wait", 6),  # nothing after it
    )
    waits = [link for link in _links(PAPER, robot, human) if link.kind == "waits_for"]
    assert waits == [
        # the robot's wait in cycle 1: the human's give of tape2 in cycle 1 (its pick in cycle
        # 0 is before the wait); its wait in cycle 2: no human step on tape2 in cycle 2 (the
        # human's place in cycle 3 comes after the robot's take in that cycle)
        Link("waits_for", (H, 1), (R, 1)),
        # the human's wait in cycle 2: its next step, the place of tape2 in cycle 3, comes
        # after the robot's take of it in that cycle
        Link("waits_for", (R, 3), (H, 2)),
        # the human's wait in cycle 4: the robot's last step on tape3 up to cycle 5 included,
        # its give (not its pick in cycle 4, nor its throw in cycle 6, after the take)
        Link("waits_for", (R, 5), (H, 4)),
    ]


def test_each_objects_steps_are_labelled_with_the_method_its_kinds_say() -> None:
    # a human give: handover_h2r (even with a robot give too); a robot give: handover_r2h;
    # a human place: human_places; only human steps: human_alone; otherwise robot_alone;
    # steps on no object: no method
    robot = [step(R, "give(tape1)", 0), step(R, "pick(tape2)", 1), step(R, "goto(human)", 2)]
    human = [
        step(H, "give(tape1)", 0),
        step(H, "place(tape2,mat_left)", 1),
        step(H, "pick(tape3)", 2),
        step(H, "wait", 3),
    ]
    out = _label_methods(PAPER, (robot, human))
    assert [s.method for s in out[0]] == ["handover_h2r", "human_places", ""]
    assert [s.method for s in out[1]] == ["handover_h2r", "human_places", "human_alone", ""]
    only_robot = _label_methods(PAPER, ([step(R, "give(tape1)", 0), step(R, "throw(tape2)", 1)], []))
    assert [s.method for s in only_robot[0]] == ["handover_r2h", "robot_alone"]


def test_a_human_turn_plan_starts_with_no_robot_step_and_no_robot_time_unless_given() -> None:
    # a plan that starts at the human's turn has no robot action in its first cycle; without
    # the robot's action under way its duration is 0 s, so the cycle lasts the human's action
    world = PAPER
    root = world.initial_state(np.random.default_rng(0))
    wait_h = world.n_actions(H) - 1
    plan = build_plan(world, root, H, [(NO_ACTION, wait_h)])
    assert plan.durations == ((0.0, world.durations.wait),)
    assert plan.terms[0].time == pytest.approx(world.durations.wait)
    robot, human = plan.streams
    assert robot == () and [s.name for s in human] == ["wait"]
    given = build_plan(world, root, H, [(NO_ACTION, wait_h)], robot_part=(6.0, 16))  # goto(human)
    assert given.durations == ((6.0, world.durations.wait),) and given.terms[0].time == pytest.approx(6.0)


def test_a_failure_is_no_plan_at_infinite_cost_never_optimal_with_the_robots_wait() -> None:
    res = failure("budget: 10 nodes", 10, 0.5, 17)
    assert (res.success, res.plan, res.cost, res.breakdown) == (False, None, float("inf"), {})
    assert (res.nodes, res.wall_time, res.reason) == (10, 0.5, "budget: 10 nodes")
    assert res.optimal is False and res.robot_action == 17 and res.human_action == -1


@pytest.mark.parametrize(("action", "planned"), [(0, True), (4, True), (5, False), (-1, False)])
def test_the_action_distribution_puts_the_mass_on_a_planned_action_inside_the_set_else_uniform(
    action: int, planned: bool
) -> None:
    # docs/task.md: 1 - (N - 1) * 0.01 on the planned action, 0.01 elsewhere; an action
    # outside 0..N-1 (none planned: -1; or beyond the set) gives the uniform distribution
    res = PlanResult(True, None, 1.0, {}, 1, 0.0, robot_action=action, human_action=action)
    for agent in Agent:
        dist = res.action_distribution(5, agent)
        if planned:
            expected = np.full(5, 0.01)
            expected[action] = 0.96
        else:
            expected = np.full(5, 0.2)
        assert dist == pytest.approx(expected)


def test_handovers_are_found_by_cycle_number_in_plans_longer_than_256_cycles() -> None:
    # cycle numbers are compared by value: a plan on a large table can run past the few
    # hundred integers Python keeps one object of (each number below is built apart)
    late = int("300")
    robot = (step(R, "give(tape1)", int("300")), step(R, "take(tape2)", int("302")))
    human = (step(H, "take(tape1)", late), step(H, "give(tape2)", int("301")))
    handovers = [link for link in _links(PAPER, robot, human) if link.kind == "handover"]
    assert handovers == [Link("handover", (R, 0), (H, 0)), Link("handover", (H, 1), (R, 1))]


def test_the_humans_wait_is_idle_time_whatever_the_size_of_its_action_set() -> None:
    # on a table with 289 human actions the wait's index (288) is past the integers Python
    # keeps one object of; a wait is still recognised by its index's value: no effort
    world = World("generated:objects=12,spots=20")
    wait_h = int(str(world.n_actions(H) - 1))
    assert wait_h > 256
    root = world.initial_state(np.random.default_rng(0))
    plan = build_plan(world, root, H, [(NO_ACTION, wait_h)])
    assert plan.terms[0].human_effort == 0.0 and plan.terms[0].human_idle == pytest.approx(world.durations.wait)
