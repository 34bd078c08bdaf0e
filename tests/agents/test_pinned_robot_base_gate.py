"""What every robot shares (agents/robots/base.py), pinned for the mutation gate.

Each expected value is read from the module's own rules, worked by hand: a robot must
implement ``act``, knows no actions until it is seated, and draws from a generator seeded 0
until a run hands it one; a planner result becomes a proposal that commits to the planned
action with all but 0.01 on each other action (``1 - (N - 1) * 0.01``), a failed plan
expects nothing of the human (-1); the planner is built with the settings given; the
habit's proposal is timed by the clock read before and after it (a stand-in clock here,
never wall time); a learning robot shares nothing between objects unless asked, has a
transition pending from its first ``act`` until its ``end``, and its TD error reads 0
before any step; the stall move is the habit's best feasible move other than ``wait``,
whatever the draw.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.habit import QLearnerConfig
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.planner import PlannerConfig
from hg_marl.agents.planner.plan import PlanResult
from hg_marl.agents.robots import HabitRobot, HybridRobot, PlannerRobot, RandomRobot, Robot
from hg_marl.agents.robots import base as robot_base
from hg_marl.agents.robots.base import habit_stall_move, make_planner, plan_proposal
from hg_marl.core import WAIT, Agent, State, World
from hg_marl.policy import Turn

WORLD = World("paper2015")
N = WORLD.n_actions(Agent.ROBOT)
ROBOT_WAIT = WORLD.index(Agent.ROBOT, WAIT)


def _turn(state: State, reward: float = 0.0, mask: np.ndarray | None = None) -> Turn:
    obs = {
        "observation": WORLD.facts(state),
        "action_mask": WORLD.mask(state, Agent.ROBOT) if mask is None else mask,
    }
    return Turn(WORLD, state, Agent.ROBOT, obs, reward=reward)


def _state(seed: int = 0) -> State:
    return WORLD.initial_state(np.random.default_rng(seed))


def test_a_robot_knows_no_actions_until_it_is_seated() -> None:
    robot = PlannerRobot()
    assert robot.n_actions == 0
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    assert robot.n_actions == N


def test_a_robot_must_say_how_it_acts() -> None:
    class Silent(Robot):
        name = "silent"

    with pytest.raises(TypeError, match="abstract"):
        Silent()


def test_a_robot_draws_reproducibly_from_a_generator_seeded_0_until_a_run_hands_it_one() -> None:
    state = _state()
    feasible = np.flatnonzero(WORLD.mask(state, Agent.ROBOT))
    rng = np.random.default_rng(0)
    expected = [int(feasible[rng.integers(len(feasible))]) for _ in range(6)]
    robot = RandomRobot()
    assert [robot.act(_turn(state)) for _ in range(6)] == expected


def test_a_habit_learns_on_the_states_as_they_are_unless_asked_to_share_objects() -> None:
    assert HabitRobot().share_objects is False
    assert HabitRobot(share_objects=True).share_objects is True


def test_a_failed_plan_commits_to_its_fallback_action_and_expects_nothing_of_the_human() -> None:
    cost = CostModel()
    failed = PlanResult(False, None, float("inf"), {}, 40, 0.0, "no plan: test", False, ROBOT_WAIT, 5)
    prop = plan_proposal(failed, N, Agent.ROBOT, cost)
    assert not prop.success and prop.action == ROBOT_WAIT and prop.nodes == 40
    assert prop.human_action == -1  # whatever the result says, a failed plan expects nothing
    expected = np.full(N, 0.01)
    expected[ROBOT_WAIT] = 1.0 - (N - 1) * 0.01  # 0.83 on wait for the robot's 18 actions
    assert prop.distribution == pytest.approx(expected)
    assert prop.cost == pytest.approx(0.05 + 0.0005 * 40)  # the default model: 50 ms + 0.5 ms a node


def test_a_successful_plan_commits_to_its_action_and_expects_its_human_action() -> None:
    done = PlanResult(True, None, 2.0, {}, 0, 0.0, "", True, 3, 7)
    prop = plan_proposal(done, N, Agent.ROBOT, CostModel())
    expected = np.full(N, 0.01)
    expected[3] = 1.0 - (N - 1) * 0.01
    assert prop.success and prop.action == 3 and prop.human_action == 7
    assert prop.distribution == pytest.approx(expected)
    assert prop.cost == pytest.approx(0.05)  # a cached plan: no nodes, the call alone


def test_a_planner_is_built_with_the_settings_it_is_given() -> None:
    config = PlannerConfig(node_budget=1234)
    assert make_planner(WORLD, config).config.node_budget == 1234
    assert make_planner(WORLD).config == PlannerConfig()


def test_a_q_config_object_is_used_and_anything_but_a_mapping_or_a_config_is_refused() -> None:
    config = QLearnerConfig(beta=7.0)
    assert HabitRobot(q_config=config).q_config is config
    for bad in ([1], "beta=7", 3.0):
        with pytest.raises(ValueError, match="bad q_config"):
            HabitRobot(q_config=bad)


def test_a_transition_is_pending_from_the_first_act_until_the_end_and_no_td_error_before() -> None:
    robot = HabitRobot()
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    assert robot.has_pending is False and robot.last_td_error == 0.0
    robot.act(_turn(_state()))
    assert robot.has_pending is True and robot.last_td_error == 0.0  # nothing learnt yet
    robot.end(_turn(_state(), reward=1.0))
    assert robot.has_pending is False


def test_a_hybrid_hands_its_criterion_each_reward_of_an_executed_transition() -> None:
    """The first turn has no transition behind it, so its reward is not the criterion's."""
    robot = HybridRobot(criterion="planner")
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    seen: list[float] = []
    robot.meta.observe = seen.append
    robot.act(_turn(_state(), reward=5.0))
    robot.act(_turn(_state(), reward=2.0))
    robot.act(_turn(_state(), reward=0.0))
    assert seen == [2.0, 0.0]


def test_the_habits_decision_time_is_the_clock_read_around_its_proposal(monkeypatch: pytest.MonkeyPatch) -> None:
    reads = iter([0.5, 1.25])  # a stand-in clock: 0.75 s between the two reads
    monkeypatch.setattr(robot_base, "time", SimpleNamespace(perf_counter=lambda: next(reads)))
    robot = HabitRobot(cost=CostModel(mode="wall"))
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    robot.act(_turn(_state()))
    assert robot.last_decision is not None
    assert robot.last_decision.decision_time == pytest.approx(0.75)


def test_the_stall_move_is_the_habits_best_feasible_move_whatever_the_draw() -> None:
    others = [i for i in range(N) if i != ROBOT_WAIT]
    a, b, c = others[:3]
    mask = np.zeros(N, dtype=np.int8)
    mask[[ROBOT_WAIT, a, b, c]] = 1
    q = np.zeros(N)
    q[ROBOT_WAIT], q[a], q[b], q[c] = 9.0, 1.0, 3.0, -2.0
    turn = _turn(_state(), mask=mask)
    assert {habit_stall_move(turn, q, np.random.default_rng(seed)) for seed in range(30)} == {b}
