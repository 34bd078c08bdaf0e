"""The runner, sweeps (resume, atomic results) and the ``hg-marl run`` command."""

from __future__ import annotations

import json
from dataclasses import fields
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.core.errors import ConfigError
from hg_marl.policy import Decision, Turn
from hg_marl.training import backends, sweep
from hg_marl.training.cli import app
from hg_marl.training.io import atomic_write
from hg_marl.training.runner import COLUMNS, MAX_CYCLES, RunConfig, check_cycles, run, summarise
from hg_marl.training.sweep import Job, run_sweep


def test_planner_run_is_logged_and_charged() -> None:
    result = run(make_robot("planner"), make_human("cooperative"), RunConfig(duration=200.0, seed=1))
    log = result.log
    assert list(log.columns) == list(COLUMNS)
    assert result.summary["tasks_solved"] == int(log["reward"].sum()) >= 5
    assert (log["expert"] == "planner").all() and not log["failed"].any()
    assert (log["decision_time"] > 0).all(), "planning is charged to the clock"
    assert log["time"].is_monotonic_increasing and log["time"].iloc[-1] >= 200.0
    assert log["human_as_expected"].dropna().mean() > 0.9, "the cooperative human follows the shared plan"


class _PlainRobot:
    """An Actor from outside the package: no decision record of its own."""

    def reset(self, world: object, agent: object, rng: np.random.Generator) -> None:
        self.rng = rng

    def act(self, turn: Turn) -> int:
        return int(np.flatnonzero(turn.mask)[-1])  # wait is the last action


def test_log_columns_are_the_decision_fields() -> None:
    names = {f.name for f in fields(Decision)} - {"stats"}
    assert set(COLUMNS) >= names | {"decision", "time", "human_action", "reward"}
    log = run(_PlainRobot(), make_human("cooperative"), RunConfig(duration=20.0, seed=0)).log
    assert (log["expert"] == "_PlainRobot").all(), "a robot without a record is logged under its class name"
    assert (log["expected_human_action"] == -1).all() and log["human_as_expected"].isna().all()
    assert (log["action_name"] == "wait").all()


def test_same_seed_same_trajectory() -> None:
    def once(seed: int) -> pd.DataFrame:
        robot = make_robot("hybrid", criterion="random")
        return run(robot, make_human("noisy"), RunConfig(duration=150.0, seed=seed)).log

    a, b, c = once(3), once(3), once(4)
    pd.testing.assert_frame_equal(a.drop(columns="planning_time"), b.drop(columns="planning_time"))
    assert not a[["action", "human_action"]].equals(c[["action", "human_action"]])


def test_charging_decision_time_costs_tasks() -> None:
    charged = run(make_robot("planner"), make_human("cooperative"), RunConfig(duration=300.0, seed=0))
    free = run(
        make_robot("planner"), make_human("cooperative"), RunConfig(duration=300.0, seed=0, charge_decision_time=False)
    )
    # the decisions' time (modelled: 50 ms + 0.5 ms/node per plan) is recorded either way, and
    # only the charged run loses it: the free run fits more cycles and at least as many tasks
    assert free.log["decision_time"].sum() > 1.0 and charged.log["decision_time"].sum() > 1.0
    assert len(free.log) > len(charged.log)
    assert free.summary["tasks_solved"] >= charged.summary["tasks_solved"]


def test_sweep_resumes_without_rerunning(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    jobs = [Job(robot="random", seed=s, duration=60.0, human="random", label="random") for s in range(2)]
    first = run_sweep(jobs, tmp_path)
    assert [s["job"]["seed"] for s in first] == [0, 1]
    for job, summary in zip(jobs, first, strict=True):
        entry = sweep.store_of(tmp_path).entry(job.key())
        assert json.loads((entry / "result.json").read_text())["summary"]["actions"] == summary["actions"]
        assert summary["actions"] == len(sweep.load_log(job, tmp_path))

    def boom(job: Job) -> None:
        raise AssertionError("a finished job was run again")

    monkeypatch.setattr(backends, "execute", boom)
    assert run_sweep(jobs, tmp_path) == first


def test_sweep_in_two_processes_matches_in_process(tmp_path: Path) -> None:
    jobs = [Job(robot="planner", seed=s, duration=80.0) for s in range(2)]
    serial = run_sweep(jobs, tmp_path / "a", workers=1)
    parallel = run_sweep(jobs, tmp_path / "b", workers=2)
    assert [s["tasks_solved"] for s in serial] == [s["tasks_solved"] for s in parallel]
    assert [s["actions"] for s in serial] == [s["actions"] for s in parallel]


def test_atomic_write_leaves_nothing_on_failure(tmp_path: Path) -> None:
    target = tmp_path / "out.csv"

    def fail(tmp: Path) -> None:
        tmp.write_text("half")
        raise RuntimeError("interrupted")

    with pytest.raises(RuntimeError):
        atomic_write(target, fail)
    assert not target.exists() and list(tmp_path.iterdir()) == []


def test_cli_run_prints_summary_and_writes_log(tmp_path: Path) -> None:
    out = tmp_path / "log.csv"
    args = ["run", "--robot", "planner", "--human", "cooperative", "--duration", "120", "--out", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "tasks solved" in result.output and out.exists()
    assert len(pd.read_csv(out)) > 10


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--robot", "dog"], "unknown robot 'dog'"),
        (["--human", "cat"], "unknown human"),
        (["--scenario", "kitchen"], "unknown scenario"),
        (["--robot", "hybrid", "--criterion", "astrology"], "astrology"),
    ],
)
def test_cli_run_rejects_unknown_names_clearly(args: list[str], message: str) -> None:
    result = CliRunner().invoke(app, ["run", "--duration", "10", *args])
    assert result.exit_code == 2
    assert message in result.output
    assert "Traceback" not in result.output


def test_summary_reads_the_last_row_for_time_and_weight_amplitude() -> None:
    # three decisions by hand: the summary's time and weight amplitude are the LAST row's,
    # counts are sums, the planner's share is 2 of 3, human_as_expected the mean of the known ones
    log = pd.DataFrame(
        {
            "reward": [0.0, 1.0, 1.0],
            "failed": [False, True, False],
            "time": [2.0, 5.0, 9.0],
            "expert": ["planner", "habit", "planner"],
            "weight_amplitude": [0.5, 0.25, 0.125],
            "human_as_expected": [True, None, False],
        }
    )
    summary = summarise(log, 100.0)
    assert summary["tasks_solved"] == 2 and summary["actions"] == 3 and summary["failed_actions"] == 1
    assert summary["simulated_time"] == 9.0
    assert summary["final_weight_amplitude"] == 0.125
    assert summary["planner_share"] == pytest.approx(2 / 3)
    assert summary["human_as_expected"] == pytest.approx(0.5)
    assert summary["duration"] == 100.0


class _ExpectingRobot:
    """Waits every decision and announces the human action it expects: 0, then wait, then none."""

    expectations = (0, -2, -1)  # -2 stands for "the human's wait" (the last human action)

    def reset(self, world: object, agent: object, rng: np.random.Generator) -> None:
        self.k = 0

    def act(self, turn: Turn) -> int:
        wait = int(np.flatnonzero(turn.mask)[-1])
        expected = self.expectations[self.k % 3]
        if expected == -2:
            expected = len(turn.world.action_names[1]) - 1
        self.last_decision = Decision(expert="stub", action=wait, expected_human_action=expected)
        self.k += 1
        return wait


class _WaitingHuman:
    def reset(self, world: object, agent: object, rng: np.random.Generator) -> None:
        pass

    def act(self, turn: Turn) -> int:
        return int(np.flatnonzero(turn.mask)[-1])  # the human's wait, its last action


def test_human_as_expected_compares_with_every_expected_action_including_index_0() -> None:
    # the human always waits: expected action 0 (a pick) -> False, expected wait -> True,
    # no expectation (-1) -> None
    result = run(_ExpectingRobot(), _WaitingHuman(), RunConfig(duration=100.0, seed=0, max_decisions=3))
    log = result.log
    assert log["expected_human_action"].iloc[0] == 0
    assert log["human_as_expected"].tolist() == [False, True, None]


def test_a_run_needing_exactly_the_cycle_limit_is_accepted_and_one_more_is_refused() -> None:
    assert MAX_CYCLES == 50_000_000
    check_cycles(10_000_000.0, 0.2)  # 1e7 s at 0.2 s a cycle: 5e7 cycles, the limit itself
    check_cycles(float(MAX_CYCLES), 1.0)
    with pytest.raises(ConfigError, match=r"over the limit 50,000,000"):
        check_cycles(float(MAX_CYCLES) + 1.0, 1.0)


def test_human_as_expected_compares_values_not_objects_past_the_small_integers() -> None:
    """On a scenario of 1,921 human actions the human's wait is action 1920: the robot's
    expectation and the human's answer are equal numbers made separately, so the comparison
    must be by value (Python keeps one object only for the integers up to 256)."""
    config = RunConfig(scenario="generated:objects=30,spots=60", duration=100.0, seed=0, max_decisions=3)
    result = run(_ExpectingRobot(), _WaitingHuman(), config)
    assert result.log["expected_human_action"].tolist() == [0, 1920, -1]
    assert result.log["human_as_expected"].tolist() == [False, True, None]
