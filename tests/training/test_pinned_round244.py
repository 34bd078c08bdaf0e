"""Values that round 244's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.planner import Planner
from hg_marl.agents.robots import HybridRobot
from hg_marl.core import Agent, World
from hg_marl.core.errors import ModelFileError
from hg_marl.training.baselines import convert
from tests.agents.test_pinned_hybrid_robot_gate import _record, _start, _turn
from tests.training.test_pinned_baselines_convert_gate import _zip


def test_the_hybrid_remembers_the_action_it_executed_not_the_habits_proposal() -> None:
    # With the ``planner`` criterion the planner's move is executed. At paper2015's seeded start
    # (seed 0) the untrained habit proposes another action than the plan's first move, so the
    # partner bookkeeping (``partnering.previous``: what the human's next move is read against,
    # and what the partner model's verdicts observe) must hold the state and the *returned* action.
    robot = HybridRobot(criterion="planner")
    state = _start(robot)
    action = robot.act(_turn(state))
    record = _record(robot)
    assert record.expert == "planner" and record.habit_action != action  # the case the rule is about
    assert robot.partnering.previous == (state, action)


def test_a_human_first_plan_caches_the_suffix_from_the_robots_next_turn() -> None:
    # Module docstring: after a search the plan's suffix is cached for every state it passes
    # through. A plan asked with the human to move first has cycle 0 without a robot action
    # (NO_ACTION) and cycles after it; the robot-turn state starting cycle 1 is on the plan, so
    # asking from it is a dictionary look-up: served from the cache, 0 nodes expanded, the same
    # cost as a cold search from that state by a fresh planner.
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    planner = Planner(world)
    first = planner.plan(state, Agent.HUMAN)
    assert first.plan is not None and len(first.plan.cycles) > 1 and not first.cached
    nxt = first.plan.states[1]
    again = planner.plan(nxt, Agent.ROBOT)
    assert again.cached and again.nodes == 0
    assert again.cost == pytest.approx(Planner(world).plan(nxt, Agent.ROBOT).cost)


def test_a_zip_sb3_cannot_read_for_an_os_error_is_one_line(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # Any failure of SB3's loader (an unreadable file included, an OSError) is the one-line
    # ModelFileError "<zip>: SB3 could not load it (<why>)", never a traceback.
    def fake_algo_class(name: str) -> Any:
        class Loader:
            @staticmethod
            def load(path: Path, device: str) -> Any:
                raise OSError("disk read failed")

        return Loader

    monkeypatch.setattr(convert, "algo_class", fake_algo_class)
    zip_path = _zip(tmp_path)
    with pytest.raises(ModelFileError, match=r"model\.zip: SB3 could not load it \(disk read failed\)$"):
        convert.convert_zip(zip_path, trust=True, algo="PPO")
