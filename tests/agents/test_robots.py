"""Robot agents driven by the task core directly (no environment): a robot turn, then a
cooperative human that follows the planner's human stream."""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.habit import QLearner
from hg_marl.agents.planner import Planner
from hg_marl.agents.robots import HybridRobot, Robot, available_robots, make_robot
from hg_marl.core import WAIT, Agent, State, World
from hg_marl.core.errors import CriterionError, RobotError
from hg_marl.policy import Actor, Turn

KEYS = {
    "expert",
    "action",
    "planner_action",
    "habit_action",
    "planning_time",
    "planner_nodes",
    "planner_success",
    "decision_time",
    "expected_human_action",
}


@pytest.fixture(scope="module")
def world() -> World:
    return World("paper2015")


def robot_turn(world: World, state: State, reward: float = 0.0) -> Turn:
    obs = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
    return Turn(world, state, Agent.ROBOT, obs, reward=reward)


@dataclass
class Run:
    solved: int
    records: list[dict[str, Any]]
    human_actions: list[int]
    failed: int


def drive(robot: Robot, world: World, cycles: int, seed: int = 0) -> Run:
    """Continuing mode: the table is re-drawn after each success (the paper's protocol)."""
    rng = np.random.default_rng(seed)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(seed))
    human = Planner(world)
    human_wait = world.index(Agent.HUMAN, WAIT)
    state = world.initial_state(rng)
    reward, solved, failed = 0.0, 0, 0
    records, human_actions = [], []
    for _ in range(cycles):
        action = robot.act(robot_turn(world, state, reward))
        records.append(asdict(robot.last_decision))
        out = world.step(state, Agent.ROBOT, action)
        state, reward, failed = out.state, out.reward, failed + (not out.ok)
        if reward > 0:
            solved += 1
            state = world.initial_state(rng)
            human_actions.append(-1)
            continue
        plan = human.plan(state, to_move=Agent.HUMAN, robot_action=action)
        h = plan.human_action if plan.success and plan.human_action >= 0 else human_wait
        human_actions.append(h)
        state = world.step(state, Agent.HUMAN, h).state
    return Run(solved, records, human_actions, failed)


ALL = [
    ("planner", {}),
    ("habit", {}),
    ("random", {}),
    *[("hybrid", {"criterion": c}) for c in ("random", "entropy", "entropy_and_cost", "vpi", "learning_state")],
]


@pytest.mark.parametrize("name, params", ALL, ids=lambda x: x if isinstance(x, str) else str(x.get("criterion", "")))
def test_robot_protocol_and_record(world: World, name: str, params: dict[str, Any]) -> None:
    robot = make_robot(name, **params)
    assert isinstance(robot, Actor)
    run = drive(robot, world, cycles=60)
    n = world.n_actions(Agent.ROBOT)
    for rec in run.records:
        assert rec.keys() >= KEYS
        assert 0 <= rec["action"] < n and rec["decision_time"] >= 0
        assert rec["expert"] in ("planner", "habit", "random")
        if name in ("habit", "hybrid"):
            assert "weight_amplitude" in rec
        if rec["expert"] == "planner":
            assert rec["action"] == rec["planner_action"] and rec["planner_success"]
        if rec["expert"] == "habit" and name == "hybrid":
            assert rec["action"] == rec["habit_action"]


def test_planner_robot_solves_and_predicts_the_cooperative_human(world: World) -> None:
    run = drive(make_robot("planner"), world, cycles=200)
    assert run.solved >= 10
    assert run.failed == 0
    expected = [r["expected_human_action"] for r in run.records]
    pairs = [(e, h) for e, h in zip(expected, run.human_actions, strict=True) if e >= 0 and h >= 0]
    assert pairs and sum(e == h for e, h in pairs) / len(pairs) > 0.9
    # the default decision-cost model: 50 ms per planner call + 0.5 ms per expanded node
    # (a cached plan reports 0 nodes and costs the 50 ms alone)
    for rec in run.records:
        assert rec["decision_time"] == pytest.approx(0.05 + 0.0005 * rec["planner_nodes"])
    assert run.records[0]["planner_nodes"] > 0 and any(r["planner_nodes"] == 0 for r in run.records)


def test_random_robot_only_feasible(world: World) -> None:
    run = drive(make_robot("random"), world, cycles=200)
    assert run.failed == 0 and {r["expert"] for r in run.records} == {"random"}


def test_habit_robot_explores_infeasible_actions(world: World) -> None:
    run = drive(make_robot("habit"), world, cycles=200)
    assert run.failed > 20  # no mask: it has to learn what fails, as in the paper


def test_habit_robot_td_step_matches_learner(world: World) -> None:
    robot = make_robot("habit")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    twin = QLearner(world.n_facts, world.n_actions(Agent.ROBOT))
    s0 = world.initial_state(np.random.default_rng(1))
    a0 = robot.act(robot_turn(world, s0))
    s1 = world.step(s0, Agent.ROBOT, a0).state
    robot.act(robot_turn(world, s1, reward=1.0))
    delta = twin.update(world.facts(s0), a0, 1.0, world.facts(s1))
    assert robot.last_td_error == pytest.approx(delta)  # type: ignore[attr-defined]
    assert robot.learner.weights == pytest.approx(twin.weights)  # type: ignore[attr-defined]


def test_end_is_a_terminal_update(world: World) -> None:
    robot = make_robot("habit")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    learner: QLearner = robot.learner  # type: ignore[attr-defined]
    learner.bias[:] = 3.0
    s0 = world.initial_state(np.random.default_rng(1))
    a0 = robot.act(robot_turn(world, s0))
    q_before = learner.q_values(world.facts(s0))[a0]
    robot.end(robot_turn(world, s0, reward=1.0))
    assert robot.last_td_error == pytest.approx(1.0 - q_before)  # type: ignore[attr-defined]
    robot.end(robot_turn(world, s0, reward=1.0))  # nothing pending: no second update
    assert learner.n_updates == 1


def test_planner_transitions_bootstrap_the_habit(world: World) -> None:
    """The paper's Fig. 5: weights grow faster when the planner drives than alone."""
    alone = drive(make_robot("habit"), world, cycles=300).records[-1]["weight_amplitude"]
    guided = drive(make_robot("hybrid", criterion="planner"), world, cycles=300)
    amplitude = [r["weight_amplitude"] for r in guided.records]
    assert amplitude[-1] > 2 * alone and amplitude[-1] > amplitude[30]
    assert {r["expert"] for r in guided.records} == {"planner"}


def test_hybrid_random_mixes_and_learns(world: World) -> None:
    run = drive(make_robot("hybrid", criterion="random"), world, cycles=300)
    experts = [r["expert"] for r in run.records]
    assert 0.35 < experts.count("planner") / len(experts) < 0.65
    assert run.solved >= 5
    not_consulted = [r for r in run.records if not r["planner_consulted"]]
    assert all(r["planner_action"] == -1 and r["planning_time"] == 0.0 for r in not_consulted)


def test_hybrid_falls_back_to_habit_when_planning_fails(world: World) -> None:
    robot = make_robot("hybrid", criterion="planner")
    assert isinstance(robot, HybridRobot)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    real = robot.planner

    class Failing:
        def plan(self, state: State, to_move: Agent = Agent.ROBOT) -> Any:
            result = real.plan(state, to_move=to_move)
            wait = world.index(Agent.ROBOT, WAIT)
            return replace(result, success=False, plan=None, nodes=42, reason="no plan: test", robot_action=wait)

    robot.planner = Failing()
    action = robot.act(robot_turn(world, world.initial_state(np.random.default_rng(0))))
    rec = asdict(robot.last_decision)
    assert rec["expert"] == "habit" and action == rec["habit_action"]
    assert rec["planner_success"] is False and rec["reason"] == "planner_failed" and rec["planner_nodes"] == 42


def test_same_seed_same_decisions(world: World) -> None:
    def actions(seed: int) -> list[tuple[str, int]]:
        run = drive(make_robot("hybrid", criterion="random"), world, cycles=150, seed=seed)
        return [(r["expert"], r["action"]) for r in run.records]

    assert actions(3) == actions(3)
    assert actions(3) != actions(4)


def test_learner_fresh_per_reset_unless_given(world: World) -> None:
    # the planner solves tasks, so the habit learns from rewards (the habit alone earns none
    # in 100 cycles and its weights would stay 0, which would make the reset check empty)
    robot = make_robot("hybrid", criterion="planner")
    drive(robot, world, cycles=100)
    assert robot.learner.weight_amplitude > 0  # type: ignore[attr-defined]
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    assert robot.learner.weight_amplitude == 0.0  # type: ignore[attr-defined]
    given = QLearner(world.n_facts, world.n_actions(Agent.ROBOT))
    given.bias[:] = 0.5
    kept = make_robot("hybrid", criterion="planner", learner=given)
    drive(kept, world, cycles=50)
    kept.reset(world, Agent.ROBOT, np.random.default_rng(1))
    assert kept.learner is given and given.n_updates == 49  # type: ignore[attr-defined]


def test_registry_lists_and_rejects() -> None:
    assert set(available_robots()) == {"planner", "habit", "hybrid", "random", "sb3", "belief", "memory"}
    listing = r"unknown robot 'oracle'; available: planner, habit, hybrid, random, sb3, belief, memory"
    with pytest.raises(ValueError, match=listing):
        make_robot("oracle")
    with pytest.raises(RobotError, match=r"robot 'habit' has no parameter 'beta'; its parameters: q_config"):
        make_robot("habit", beta=3)
    with pytest.raises(CriterionError, match=r"unknown criterion 'nope'"):
        make_robot("hybrid", criterion="nope")
    with pytest.raises(CriterionError, match=r"criterion 'vpi' has no parameter 'kappa'"):
        make_robot("hybrid", criterion="vpi", criterion_params={"kappa": 1.0})


def test_specs_read_alike_and_values_are_typed() -> None:
    """``make_robot("hybrid:criterion=vpi")`` is ``make_robot("hybrid", criterion="vpi")``, values checked by type."""
    robot = make_robot("hybrid:criterion=vpi,learn=false")
    assert type(robot.meta.criterion).__name__ == "VPICriterion" and robot.learn is False
    with pytest.raises(RobotError, match="parameter 'learn': expected true or false, got 'no'"):
        make_robot("hybrid:learn=no")
    with pytest.raises(RobotError, match="parameter 'q_config': not valid JSON"):
        make_robot("hybrid:q_config={bad json}")
    with pytest.raises(CriterionError, match="parameter 'tau': expected a finite number"):
        make_robot("hybrid", criterion="vpi:tau=nan")
    with pytest.raises(RobotError, match="parameter 'cost': takes a Python object"):
        make_robot("planner:cost=3")  # found by the fuzz suite: it failed later inside the robot
    with pytest.raises(RobotError, match="parameter 'q_config': expected a JSON object"):
        make_robot("habit:q_config=[1]")  # found by the fuzz suite


def test_q_config_as_plain_dict() -> None:
    """Sweeps and the CLI pass the habit's settings as JSON: a dict of QLearnerConfig fields."""
    robot = make_robot("hybrid", criterion="entropy", q_config={"features": "tabular", "beta": 20.0})
    assert robot.q_config.features == "tabular" and robot.q_config.beta == 20.0
    with pytest.raises(ValueError, match="bad q_config"):
        make_robot("habit", q_config={"temperature": 3})
