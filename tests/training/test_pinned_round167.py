"""Values that round 167's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import hg_marl
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.robots import base as robot_base
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.core import Agent
from hg_marl.training.io import write_json
from hg_marl.wrappers import flatten_v0
from tests.agents.test_pinned_robot_base_gate import WORLD, _state, _turn


def _clock(step: float) -> Iterator[float]:
    """A stand-in ``perf_counter``: 0, step, 2 step, ... (each reading ``step`` seconds after the last)."""
    now = 0.0
    while True:
        yield now
        now += step


def test_the_habit_robot_in_wall_mode_charges_each_decision_its_measured_time(monkeypatch: pytest.MonkeyPatch) -> None:
    # In wall mode a decision costs the wall time measured around the habit's proposal (CostModel's
    # docstring: habit_cost(wall_time) is wall_time in "wall" mode). The stand-in clock advances 0.25 s
    # (exact in binary) per reading and is read twice per decision: 0.25 s charged to each of three
    # decisions, not 0 s.
    readings = _clock(0.25)
    monkeypatch.setattr(robot_base, "time", SimpleNamespace(perf_counter=lambda: next(readings)))
    robot = HabitRobot(cost=CostModel(mode="wall"))
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    for _ in range(3):
        robot.act(_turn(_state()))
        assert robot.last_decision is not None
        assert robot.last_decision.expert == "habit"
        assert robot.last_decision.decision_time == 0.25


def test_write_json_keeps_none_in_lists_and_tuples_as_null(tmp_path: Path) -> None:
    # JSON has null for None: a list keeps its length and its order, a None entry included
    # (the per-seed results of a sweep where one seed has no value), and a tuple likewise.
    path = write_json(tmp_path / "r.json", {"rates": [None, 1.5, None], "pair": (None, 2), "nested": [[None]]})
    assert json.loads(path.read_text()) == {"nested": [[None]], "pair": [None, 2], "rates": [None, 1.5, None]}


@pytest.mark.parametrize(("obs_key", "mask_key"), [("", "mask"), ("facts", "")])
def test_the_flat_wrappers_key_refusal_names_obs_key_then_mask_key(obs_key: str, mask_key: str) -> None:
    # The refusal repeats the two keys in the order the signature takes them (obs_key, then mask_key),
    # so an empty one is shown where it was passed: "got '', 'mask'" and "got 'facts', ''".
    expected = f"got {obs_key!r}, {mask_key!r}"
    with pytest.raises(ValueError, match="two different non-empty names") as info:
        flatten_v0(hg_marl.env(), obs_key=obs_key, mask_key=mask_key)
    assert str(info.value).endswith(expected)
