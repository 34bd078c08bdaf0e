"""Values that round 181's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
import json
from importlib import resources
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.agents.progress import PROGRESS_AFTER
from hg_marl.agents.robots import HybridRobot
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn
from hg_marl.training.store import Job
from tests.agents.test_pinned_promises_b import PAPER, ROBOT_WAIT, _off_model_robot
from tests.training.test_pinned_round37 import train_clocked
from tests.training.test_pinned_round163 import saved_dqn
from tests.training.test_pinned_round173 import oracle_inputs


def _turn(state: State) -> Turn:
    obs = {"observation": PAPER.facts(state), "action_mask": PAPER.mask(state, Agent.ROBOT)}
    return Turn(PAPER, state, Agent.ROBOT, obs, reward=0.0, last_actions=(-1, -1))


def test_a_hybrid_guard_move_is_remembered_as_the_move_made() -> None:
    # The state stands still: after K = PROGRESS_AFTER turns the guard moves, taking the first
    # feasible robot action other than wait (no guard move taken yet). The partner's next move is
    # read against what the robot did, so the robot's previous (state, action) is that move, not
    # the habit's proposal (seeded: the habit proposed another action at that turn).
    robot = HybridRobot(criterion="habit")
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    state = PAPER.initial_state(np.random.default_rng(0))
    for _ in range(PROGRESS_AFTER):
        robot.act(_turn(state))
    move = robot.act(_turn(state))
    first_move = min(a for a in PAPER.feasible_indices(state, Agent.ROBOT) if a != ROBOT_WAIT)
    record = robot.last_decision
    assert record is not None and (record.expert, record.reason) == ("guard", "no_progress")
    assert move == first_move != record.habit_action
    assert robot.partnering.previous == (state, first_move)


def test_an_sb3_model_with_a_named_activation_is_stored_by_its_name_and_loads(tmp_path: Path) -> None:
    # policy_kwargs.activation_fn is stored as one of the documented names ("relu" for
    # torch.nn.ReLU, model_format.ACTIVATIONS), which is what loading accepts: the rebuilt model
    # has the same activation class.
    pytest.importorskip("stable_baselines3")
    import torch

    from hg_marl.agents.model_format import load_model_file
    from hg_marl.agents.model_sb3 import build_sb3

    path = saved_dqn(tmp_path / "model.json", net_arch=[8], activation_fn=torch.nn.ReLU)
    assert json.loads(path.read_text())["policy_kwargs"]["activation_fn"] == "relu"
    again = build_sb3(load_model_file(path))
    assert again.policy_kwargs["activation_fn"] is torch.nn.ReLU


def test_off_its_model_a_failed_plan_is_logged_as_a_failure() -> None:
    # The planner stand-in finds no plan: the robot waits, and the record says the planner was
    # consulted and did not succeed, with no planner action and no expected human action.
    robot, state = _off_model_robot()
    robot._planner = SimpleNamespace(
        world=PAPER, intent=lambda s, a: SimpleNamespace(success=False, robot_action=0, human_action=0)
    )
    assert robot.act(Turn(PAPER, state, Agent.ROBOT, {})) == ROBOT_WAIT
    record = robot.last_decision
    assert record is not None
    assert record.planner_consulted and not record.planner_success
    assert (record.planner_action, record.expected_human_action) == (-1, -1)


def test_a_plan_read_from_the_cache_is_kept_as_the_most_recently_used() -> None:
    # A cache of two plans (no suffixes): plan A, plan B, read A again (a hit), plan C. The
    # least recently used is B, so C replaces B and A is still served from the cache.
    planner = Planner(PAPER, PlannerConfig(cache_size=2, cache_suffixes=False))
    rng = np.random.default_rng(1)
    tables: list[State] = []
    while len(tables) < 3:
        table = PAPER.initial_state(rng)
        if table not in tables:
            tables.append(table)
    a, b, c = tables
    assert [planner.plan(s).cached for s in (a, b, a, c)] == [False, False, True, False]
    assert planner.plan(a).cached
    assert not planner.plan(b).cached


def test_a_recurrent_model_file_names_the_memory_it_was_trained_with(tmp_path: Path) -> None:
    # The header says who trained it and with which memory: "ppo_recurrent (mlp)".
    result = train_clocked(tmp_path)
    assert json.loads(result.path.read_text())["trained_by"] == "ppo_recurrent (mlp)"


def test_an_oracle_job_keys_its_solution_by_the_scenario_files_content(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A scenario given as a TOML path is part of what the worker's oracle solution is kept by:
    # the bundled paper2015 file, then the same with a comment line added, give two sets of
    # inputs, each holding the SHA-256 of the bytes the file held (worked here with hashlib).
    bundled = resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_bytes()
    path = tmp_path / "table.toml"
    job = Job(robot="oracle", seed=0, duration=20.0, scenario=str(path))
    contents = (bundled, bundled + b"\n# the same table, edited\n")
    seen = oracle_inputs(monkeypatch, job, path, contents)
    assert all(hashlib.sha256(c).hexdigest() in inputs for c, inputs in zip(contents, seen, strict=True))
    assert len(seen) == 2 and seen[0] != seen[1]
    assert World(str(path)).n_actions(Agent.ROBOT) == PAPER.n_actions(Agent.ROBOT)
