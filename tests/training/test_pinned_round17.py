"""Values that round 17's planted bugs changed unseen, each stated by hand.

User-facing parts outside the mutation gate: the mask audit's totals across resets, the
decision time a planner or hybrid decision charges (the cost model's constants: habit
1e-3 s, a planner call 0.05 s plus 5e-4 s per node), the adversarial and lazy humans'
documented tactics, the play session's handover counts and the reproduce command's verdicts.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import hg_marl
from hg_marl.agents.humans import make_human
from hg_marl.agents.planner import PlannerConfig
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Turn
from hg_marl.training.play.session import PlaySession
from hg_marl.wrappers.audit import audit_v0
from tests.cli_helpers import run_main


def test_the_audit_keeps_counting_across_resets() -> None:
    env = audit_v0(hg_marl.env())
    env.reset(seed=0)
    world = World("paper2015")
    env.step(world.n_actions(Agent.ROBOT) - 1)  # the robot waits: feasible
    human_mask = np.asarray(env.observe("human")["action_mask"])
    infeasible = int(np.flatnonzero(~human_mask.astype(bool))[0])
    env.step(infeasible)
    env.reset(seed=1)
    assert env.sent == {"robot": 1, "human": 1} and env.infeasible == {"robot": 0, "human": 1}


def test_a_failed_plan_is_charged_its_call_and_its_nodes() -> None:
    world = World("paper2015")
    robot = make_robot("planner", planner_config=PlannerConfig(node_budget=5))
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    robot.act(Turn(world, world.initial_state(np.random.default_rng(0)), Agent.ROBOT, {}))
    record = robot.last_decision
    assert not record.planner_success and record.planner_nodes == 5
    assert record.decision_time == pytest.approx(0.05 + 5 * 5e-4)


def test_a_hybrid_decision_that_consults_the_planner_is_charged_both_experts() -> None:
    env = hg_marl.env()
    env.reset(seed=0)
    raw = env.unwrapped
    robot = make_robot("hybrid")
    robot.reset(raw.world, Agent.ROBOT, np.random.default_rng(0))
    robot.act(raw.turn("robot"))
    record = robot.last_decision
    assert record.planner_consulted and record.planner_nodes > 0
    assert record.decision_time == pytest.approx(1e-3 + 0.05 + 5e-4 * record.planner_nodes)


def test_the_adversarial_human_steals_first_what_the_robot_reaches_now() -> None:
    """Tactic 4 on roboergosum: of the objects on spots both reach, the one the robot
    reaches from where it stands is taken first."""
    world = World("roboergosum")
    rng = np.random.default_rng(0)
    human = make_human("adversarial")
    acts = world.actions(Agent.HUMAN)
    checked = 0
    for _ in range(200):
        state = world.initial_state(rng)
        state = state._replace(robot_at=int(rng.integers(len(world.scenario.robot_locations))))
        spots = world.scenario.spots
        both = [
            o
            for o, p in enumerate(state.where)
            if p < world.n_spots and spots[p].reach.human and spots[p].reach.robot_from
        ]
        now = [o for o in both if world.spot_reachable(state, Agent.ROBOT, state.where[o])]
        later = [o for o in both if o not in now]
        if not now or not later:
            continue
        ((action, _),) = human.distribution(world, state)
        assert acts[action].kind is Kind.PICK and acts[action].obj in now, state
        checked += 1
    assert checked >= 10


def test_the_lazy_human_hands_over_at_the_handover_place() -> None:
    """paper2015: the human holds tape3 and the robot stands at the human's side (a handover
    place): the lazy human gives it (with its idling, 0.7 give and 0.3 wait)."""
    world = World("paper2015")
    state = State((6, 6, 8), 3)
    assert world.holding(state, Agent.HUMAN) == 2
    names = world.action_names[Agent.HUMAN]
    assert [(names[a], p) for a, p in make_human("lazy", p_idle=0.0).distribution(world, state)] == [
        ("give(tape3)", 1.0)
    ]


def test_a_failed_robot_handover_is_not_counted() -> None:
    session = PlaySession(robot="habit", seed=0, player="t")
    counted = {"you_gave": 0, "robot_took": 0, "robot_gave": 0, "you_took": 0}
    failed = 0
    for _ in range(6):
        session.play("wait")  # the person never gives nor takes
        move = session.last_robot
        if move.name.startswith(("give(", "take(")):
            if move.failed:
                failed += 1
            else:
                counted["robot_" + ("gave" if move.name.startswith("give(") else "took")] += 1
    assert failed >= 1  # the untrained habit tries a take with nothing offered
    assert session.summary()["handovers"] == counted


def test_reproduce_prints_each_target_as_its_summary_says(tmp_path: Path) -> None:
    args = ["reproduce", "--seeds", "1", "--duration", "60", "--paper-only", "--no-adaptation"]
    code, out, err = run_main([*args, "--workers", "1", "--out", str(tmp_path)])
    assert code == 0, err
    targets = json.loads((tmp_path / "summary.json").read_text())["targets"]
    printed = {
        line.split(":")[1].strip(): line.split(":")[2].split()[0]
        for line in out.splitlines()
        if line.startswith("target: ")
    }
    assert printed == {name: ("holds" if t.get("holds") else "MISSED") for name, t in targets.items()}
    assert "MISSED" in printed.values()  # 60 s of one seed: the paper's targets do not all hold
