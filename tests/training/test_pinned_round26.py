"""The values round 26's missed planted bugs changed, pinned after the round.

Round 26 planted 14 bugs in fourteen older gated modules (the set of round 21 and of the
seed-2027 mutation sample), written blind; 9 were caught. Each value below is stated from
the rule the module documents, not read from the code under test:

- the population generator's ``haste`` is 0 or uniform in (0, 0.3), its ``p_idle`` 0 or
  uniform in (0, 0.5);
- a run's key holds the robot's decision-cost model (its ``cost`` parameter, else the
  default), never the human's;
- jobs with one key run once, as the first of them: the stored run and every summary name
  the first job;
- an adaptation switch's tasks lost are counted to the end of the run, not to the last
  logged decision: with nothing solved, the oracle's rate times the seconds since the switch;
- what the human sees of the robot's action is the action when the robot's half
  succeeded, -1 when it failed, whatever the human's own half did.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.meta.cost import CostModel
from hg_marl.core import Action, Agent, Kind, World
from hg_marl.core.cycle import cycle
from hg_marl.training.adaptation import Switch, summarise_switch
from hg_marl.training.population_gen import sample_candidates
from hg_marl.training.store import Job, default_cost_model
from hg_marl.training.sweep import run_sweep

# --- training/population_gen.py ---


def test_haste_and_p_idle_are_drawn_over_their_own_ranges() -> None:
    candidates = sample_candidates("paper2015", 400, seed=7)
    for key, top in (("haste", 0.3), ("p_idle", 0.5)):
        values = np.array([c.get(key, 0.0) for c in candidates])
        drawn = values[values > 0]
        assert 150 < len(drawn) < 250, key  # 0 with probability 1/2
        assert drawn.max() <= top and drawn.max() > 0.9 * top, key


# --- training/store.py ---


def test_a_runs_key_holds_the_robots_cost_model() -> None:
    robot_cost = Job(robot="planner", seed=0, robot_params={"cost": CostModel(planner_base=0.1)})
    assert robot_cost.key_fields()["cost_model"]["planner_base"] == 0.1
    assert Job(robot="planner", seed=0).key_fields()["cost_model"] == default_cost_model()
    human_cost = Job(robot="planner", seed=0, human_params={"cost": CostModel(planner_base=0.1)})
    assert human_cost.key_fields()["cost_model"] == default_cost_model()


# --- training/sweep.py ---


def test_jobs_with_one_key_run_once_as_the_first_of_them(tmp_path: Path) -> None:
    first = Job(robot="random", seed=0, duration=20.0, label="first")
    second = Job(robot="random", seed=0, duration=20.0, label="second")  # the label is not part of the key
    assert first.key() == second.key()
    summaries = run_sweep([first, second], tmp_path / "out")
    assert [s["job"]["label"] for s in summaries] == ["first", "first"]
    assert [s["key"] for s in summaries] == [first.key()] * 2


# --- training/adaptation.py ---


def test_tasks_lost_are_counted_to_the_end_of_the_run() -> None:
    # nothing solved; decisions logged up to 500 s of a 1000 s run; the partner changed at 100 s
    log = pd.DataFrame({"time": [0.0, 100.0, 200.0, 300.0, 400.0, 500.0], "reward": [0.0] * 6})
    out = summarise_switch([log], Switch(("a", "b"), (100.0,)), oracle_rate=36.0, duration=1000.0)
    assert out["tasks_lost"]["mean"] == pytest.approx(36.0 * 900.0 / 3600.0)  # 9 tasks at 36 an hour


# --- hg_marl/core/cycle.py ---


def test_the_human_sees_the_robots_action_when_the_robot_succeeded() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    assert state.offer_by == -1  # nothing is offered: a take fails
    robot_take = world.index(Agent.ROBOT, Action(Kind.TAKE, 0))
    human_take = world.index(Agent.HUMAN, Action(Kind.TAKE, 0))
    robot_wait = world.n_actions(Agent.ROBOT) - 1
    human_wait = world.n_actions(Agent.HUMAN) - 1
    failed_robot = cycle(world, state, robot_take, human_wait)
    assert not failed_robot.robot.ok and failed_robot.human.ok
    assert failed_robot.seen == -1
    failed_human = cycle(world, state, robot_wait, human_take)
    assert failed_human.robot.ok and not failed_human.human.ok
    assert failed_human.seen == robot_wait
