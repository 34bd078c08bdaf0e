"""The ``hybrid`` robot's choices and records (agents/robots/hybrid.py), pinned for the mutation gate.

Expected values follow from the module's docstrings and the default decision-cost model,
worked by hand: by default the habit learns on canonical states and the planner plans
against a fixed model of the human (no partner type in the record); with the partner
model's features the habit reads two verdicts after the facts; a habit decision costs
1 ms, a planner call 50 ms plus 0.5 ms per expanded node, and a decision's time is the
habit's cost plus, when the planner was consulted, the planner's; a decision that did not
consult the planner records no planner action, no nodes and no expectation of the human
(-1); the criterion hears the reward of each executed transition; ``end`` is a terminal
update unless told otherwise; the progress guard decides once the state has stood still
for ``PROGRESS_AFTER`` (12) robot turns, and the habit's best feasible move is taken once
the human keeps not doing what the plan expected (``PartnerMonitor``'s run of misses).
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.progress import PROGRESS_AFTER
from hg_marl.agents.robots import HybridRobot
from hg_marl.agents.robots.base import Robot
from hg_marl.core import WAIT, Agent, State, World
from hg_marl.policy import Decision, Turn

WORLD = World("paper2015")
ROBOT_WAIT = WORLD.index(Agent.ROBOT, WAIT)
HUMAN_WAIT = WORLD.index(Agent.HUMAN, WAIT)


def _turn(state: State, reward: float = 0.0, last: tuple[int, int] = (-1, -1)) -> Turn:
    obs = {"observation": WORLD.facts(state), "action_mask": WORLD.mask(state, Agent.ROBOT)}
    return Turn(WORLD, state, Agent.ROBOT, obs, reward=reward, last_actions=last)


def _start(robot: HybridRobot) -> State:
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    return WORLD.initial_state(np.random.default_rng(0))


def _record(robot: Robot) -> Decision:
    assert robot.last_decision is not None
    return robot.last_decision


STALLED = State((4, 6, 6), 3)
"""paper2015: tape1 on human_mat_1 (spot 4), the others in the bin (6), the robot at human_side
(location 3): the plan needs the human."""


def stall_partner(robot: Robot) -> tuple[int, list[str]]:
    """Ask ``robot`` at :data:`STALLED` while the human only waits, until it decides for a
    stalled partner (at most 8 turns): its last move and every decision's reason."""
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    robot.act(_turn(STALLED))
    assert _record(robot).expected_human_action not in (-1, HUMAN_WAIT)
    reasons: list[str] = []
    move = -1
    for _ in range(8):
        move = robot.act(_turn(STALLED, last=(ROBOT_WAIT, HUMAN_WAIT)))
        reasons.append(_record(robot).reason)
        if reasons[-1] == "partner_stalled":
            break
    return move, reasons


def test_the_default_hybrid_learns_on_canonical_states() -> None:
    assert HybridRobot().share_objects is True
    assert HybridRobot(share_objects=False).share_objects is False


def test_the_default_hybrid_plans_against_a_fixed_model_of_its_partner() -> None:
    robot = HybridRobot(criterion="planner")
    assert robot.partner_aware is False
    robot.act(_turn(_start(robot)))
    assert _record(robot).partner == ""  # no partner type guessed, nothing blocked
    aware = HybridRobot(criterion="planner", partner_aware=True)
    aware.act(_turn(_start(aware)))
    assert _record(aware).partner in aware.partnering.posterior.types


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum"])  # 24 and 47 facts (bit 1 clear and set)
def test_the_habit_reads_the_partner_models_two_verdicts_after_the_facts(scenario: str) -> None:
    world = World(scenario)
    robot = HybridRobot(criterion="habit", partner_features=True, q_config={"features": "facts"}, share_objects=False)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    assert robot.habit.n_facts == world.n_facts + 2  # does the partner refuse to take, to give
    assert robot.habit.weights.shape == (world.n_actions(Agent.ROBOT), world.n_facts + 2)
    state = world.initial_state(np.random.default_rng(0))
    obs = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
    action = robot.act(Turn(world, state, Agent.ROBOT, obs))
    assert 0 <= action < world.n_actions(Agent.ROBOT)


def test_a_decision_without_the_planner_records_no_planner_part() -> None:
    robot = HybridRobot(criterion="habit")
    state = _start(robot)
    robot.act(_turn(state))
    record = _record(robot)
    assert record.expert == "habit" and not record.planner_consulted
    assert (record.planner_action, record.planner_nodes, record.expected_human_action) == (-1, 0, -1)
    assert record.decision_time == pytest.approx(0.001)  # the habit's cost alone


def test_a_planned_decision_costs_the_habit_plus_the_planner() -> None:
    robot = HybridRobot(criterion="planner")
    state = _start(robot)
    robot.act(_turn(state))
    record = _record(robot)
    assert record.planner_consulted and record.planner_success and record.planner_nodes > 0
    assert record.decision_time == pytest.approx(0.001 + 0.05 + 0.0005 * record.planner_nodes)


def test_the_criterion_is_told_each_reward_of_an_executed_transition_and_the_last_at_the_end() -> None:
    """The first turn has no transition behind it; ``end`` passes the last reward only if one is pending."""
    robot = HybridRobot(criterion="habit")
    state = _start(robot)
    seen: list[float] = []
    robot.meta.observe = seen.append
    robot.end(_turn(state, reward=9.0))  # nothing pending yet
    robot.act(_turn(state, reward=5.0))
    robot.act(_turn(state, reward=2.0))
    robot.end(_turn(state, reward=1.0))
    robot.end(_turn(state, reward=4.0))  # the end forgot the pending transition
    assert seen == [2.0, 1.0]


def test_the_end_is_a_terminal_update_unless_told_otherwise() -> None:
    """With every Q-value 3 and reward 1, a terminal step's TD error is 1 - 3; bootstrapping adds 0.9 * 3."""
    robot = HybridRobot(criterion="habit", q_config={"features": "facts"}, share_objects=False)
    state = _start(robot)
    robot.habit.bias[:] = 3.0
    robot.act(_turn(state))
    robot.end(_turn(state, reward=1.0))
    assert robot.last_td_error == pytest.approx(1.0 - 3.0)


def test_a_state_standing_still_is_left_by_the_progress_guard() -> None:
    robot = HybridRobot(criterion="habit")
    state = _start(robot)
    for _ in range(PROGRESS_AFTER):
        robot.act(_turn(state))
        assert _record(robot).expert == "habit"
    move = robot.act(_turn(state))
    record = _record(robot)
    assert (record.expert, record.reason) == ("guard", "no_progress")
    assert move != ROBOT_WAIT and WORLD.mask(state, Agent.ROBOT)[move]


def test_a_partner_who_keeps_not_doing_what_was_expected_gets_a_feasible_move_of_the_habits() -> None:
    """Tape1 on the human's mat, the others in the bin: the plan needs the human, who only waits."""
    robot = HybridRobot(criterion="planner")
    move, reasons = stall_partner(robot)
    assert reasons[-1] == "partner_stalled" and "no_progress" not in reasons
    record = _record(robot)
    assert record.expert == "habit" and not record.planner_consulted
    assert move == record.action and move != ROBOT_WAIT and WORLD.mask(STALLED, Agent.ROBOT)[move]
