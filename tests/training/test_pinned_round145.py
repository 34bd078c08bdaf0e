"""Values that round 145's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.model_format import load_model_file
from hg_marl.agents.planner.plan import PlanResult
from hg_marl.agents.progress import PROGRESS_AFTER
from hg_marl.agents.robots import HybridRobot
from hg_marl.core import Agent, State
from hg_marl.policy import Turn
from tests.agents.test_belief_planner_follow import _members_drive
from tests.agents.test_pinned_hybrid_robot_gate import WORLD, _record, _turn
from tests.training.test_pinned_round37 import train_clocked


def test_a_hybrid_decision_records_the_planners_own_wall_time_as_its_planning_time() -> None:
    # The "planner" criterion consults the planner at every decision. A stand-in around the real
    # planner reports each of its calls as taking 0.25 s of wall time (its plan otherwise the
    # real one), so the record's planning_time is 0.25, whatever the machine's clock says.
    robot = HybridRobot(criterion="planner")
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    real = robot.partnering.planner

    class TimedPlanner:
        def plan(self, state: State, to_move: Agent = Agent.ROBOT, **kwargs: Any) -> PlanResult:
            return dataclasses.replace(real.plan(state, to_move, **kwargs), wall_time=0.25)

    robot.planner = robot.partnering.planner = TimedPlanner()
    robot.act(_turn(WORLD.initial_state(np.random.default_rng(0))))
    record = _record(robot)
    assert record.planner_consulted and record.planner_success
    assert record.planning_time == 0.25


def test_a_recurrent_model_file_counts_the_steps_run_not_the_steps_asked(tmp_path: Path) -> None:
    # 8 tables x 3 cycles: an update every 24 steps. Asked for 50, the run stops at the first
    # update at or past 50: 24, 48, 72, so 72 steps were run and the model file says 72 (not 50).
    result = train_clocked(tmp_path, steps=50)
    assert result.num_timesteps == 72
    assert load_model_file(result.path).header["num_timesteps"] == 72


def test_a_belief_guard_decision_names_the_most_probable_member(monkeypatch: pytest.MonkeyPatch) -> None:
    # The posterior is all on the first member (weights 1, 0, 0, ...). The guard has seen the same
    # state K times, so at the next turn at that state it decides (K unchanged turns in a row), and
    # its record names the partner the belief holds: the first member, not one with no weight.
    world, robot = _members_drive(monkeypatch)
    state = world.initial_state(np.random.default_rng(0))
    for _ in range(PROGRESS_AFTER):
        robot.progress.observe(state)
    robot.act(Turn(world, state, Agent.ROBOT, {}))
    record = robot.last_decision
    assert record is not None and record.expert == "guard" and record.reason == "no_progress"
    assert record.partner == robot.member_names[0]
    assert len(robot.member_names) > 1
