"""Values that round 119's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.humans.trace import TraceWriter, read_trace
from hg_marl.agents.planner.plan import PlanResult
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.core import Agent, State, World
from tests.agents.test_pinned_planner_robot_gate import _started, _turn
from tests.agents.test_population import GOOD


class TimedPlanner:
    """A planner whose every search proposes the robot's first action, expanded 3 nodes and took 0.25 s."""

    def plan(self, state: State, to_move: Agent = Agent.ROBOT, **_: Any) -> PlanResult:
        return PlanResult(True, None, 1.0, {}, 3, 0.25, "", True, 0, -1)


def test_a_planner_decision_logs_the_searchs_wall_time_as_its_planning_time() -> None:
    # planning_time is what the search measured (its wall_time, 0.25 s here); decision_time is
    # what the cost model charges: by default planner_base + planner_per_node x nodes
    # = 0.05 + 5e-4 x 3 = 0.0515 s, a different figure.
    robot = PlannerRobot()
    world, state = _started(robot)
    robot.planner = robot.partnering.planner = TimedPlanner()
    robot.act(_turn(world, state))
    record = robot.last_decision
    assert record is not None and record.expert == "planner"
    assert record.planning_time == pytest.approx(0.25)
    assert record.decision_time == pytest.approx(0.0515)


def test_a_population_generator_table_may_name_its_features(tmp_path: Path) -> None:
    # The [generator] table is informational; its fields are seed, candidates, robots, duration,
    # seeds, method and features (the loader's list): a file naming the features it measured loads
    # and keeps them, as an unknown field (here `temperature`) is refused.
    path = tmp_path / "p.toml"
    generator = '[generator]\nseed = 0\nfeatures = ["give", "throw"]\n\n[[members]]'
    path.write_text(GOOD.replace("[[members]]", generator, 1), encoding="utf-8")
    pop = load_population(path)
    assert pop.generator == {"seed": 0, "features": ["give", "throw"]}
    assert [m.name for m in pop.members()] == ["m00", "m01"]


def test_a_robot_reset_for_a_new_run_has_no_last_decision() -> None:
    # last_decision is "None before the first" decision of a run: a robot that decided in one
    # run and is reset for the next holds none until it decides again.
    robot = RandomRobot()
    world, state = _started(robot)
    robot.act(_turn(world, state))
    assert robot.last_decision is not None
    robot.reset(World("roboergosum"), Agent.ROBOT, np.random.default_rng(1))
    assert robot.last_decision is None


def test_a_trace_writer_truncates_the_file_it_opens(tmp_path: Path) -> None:
    # "path: the file; truncated when the writer opens it": a second writer on the same path
    # leaves only its own episode (one header, numbered 0), not the first writer's before it.
    world = World("paper2015")
    path = tmp_path / "t.jsonl"
    for seed in (1, 2):
        with TraceWriter(path) as writer:
            writer.header(world, Agent.HUMAN, seed=seed)
    episodes = read_trace(path)
    assert [(e.header["episode"], e.header["seed"]) for e in episodes] == [(0, 2)]
