"""The runner's clock and columns, checked against numbers stated in the test.

The scenario is ``paper2015`` with a ``[durations]`` table written here, each duration a
distinct binary fraction, so the expected clock is rebuilt from the per-decision log and
these numbers alone (not from the environment's or the planner's duration/cost code):

    clock after cycle k = clock after cycle k-1
                          + decision_time_k      (when charge_decision_time)
                          + max(duration of the robot's action, duration of the human's)

with a failed robot action lasting ``failed`` (the precondition check).
"""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.training.runner import COLUMNS, RunConfig, run, summarise

DURATIONS = {
    "pick": 2.5,
    "throw": 1.75,
    "give": 1.25,
    "take": 0.75,
    "place": 2.25,
    "goto": 3.5,
    "wait": 0.5,
    "failed": 0.125,
}


@pytest.fixture(scope="module")
def scenario(tmp_path_factory: pytest.TempPathFactory) -> str:
    """paper2015 with the durations above."""
    text = resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()
    body = "\n".join(f"{k} = {v}" for k, v in DURATIONS.items())
    path = tmp_path_factory.mktemp("scenario") / "timed.toml"
    path.write_text(f"{text}\n[durations]\n{body}\n")
    assert tomllib.loads(path.read_text())["durations"]["goto"] == 3.5
    return str(path)


def duration(name: str, failed: bool = False) -> float:
    """Duration of an action from its readable name, e.g. ``pick(tape1)`` -> pick."""
    return DURATIONS["failed"] if failed else DURATIONS[name.split("(")[0]]


def expected_clock(log: pd.DataFrame, charged: bool) -> list[float]:
    clock, out = 0.0, []
    for row in log.itertuples():
        robot = duration(str(row.action_name), bool(row.failed))
        human = duration(str(row.human_action_name))
        clock += (float(row.decision_time) if charged else 0.0) + max(robot, human)
        out.append(clock)
    return out


def hybrid_run(scenario: str, charge: bool, seed: int = 2) -> pd.DataFrame:
    robot = make_robot("hybrid", criterion="random")
    config = RunConfig(scenario=scenario, duration=120.0, seed=seed, charge_decision_time=charge)
    log = run(robot, make_human("cooperative"), config).log
    return log[log["human_action"] >= 0]  # the last decision may be cut by the time budget


@pytest.mark.parametrize("charge", [True, False])
def test_clock_is_sum_of_longer_durations_plus_charged_decisions(scenario: str, charge: bool) -> None:
    log = hybrid_run(scenario, charge)
    # the sample must exercise every term: failed habit actions, both experts, real decision times
    assert log["failed"].any() and set(log["expert"]) == {"planner", "habit"}
    assert (log["decision_time"] > 0).all()
    assert log["time"].tolist() == pytest.approx(expected_clock(log, charged=charge), abs=1e-9)


def test_uncharged_run_differs_from_charged_run_by_the_decision_times(scenario: str) -> None:
    # Same seed, same decisions (decision time is modelled, not measured): the clocks differ
    # by exactly the running sum of the decision times.
    charged, free = hybrid_run(scenario, True), hybrid_run(scenario, False)
    n = min(len(charged), len(free))
    assert charged["action"].iloc[:n].tolist() == free["action"].iloc[:n].tolist()
    gap = (charged["time"].iloc[:n] - free["time"].iloc[:n]).tolist()
    assert gap == pytest.approx(charged["decision_time"].iloc[:n].cumsum().tolist(), abs=1e-9)


def test_tasks_column_counts_rewards_so_far(scenario: str) -> None:
    result = run(make_robot("planner"), make_human("cooperative"), RunConfig(scenario=scenario, duration=150.0, seed=0))
    log = result.log
    counted, running = [], 0
    for reward in log["reward"]:
        running += int(reward == 1.0)
        counted.append(running)
    assert running >= 3, "the run must solve several tasks for the column to be tested"
    assert log["tasks_solved"].tolist() == counted
    assert result.summary["tasks_solved"] == running
    # a reward comes only on a robot wait (the robot's completing wait on a clean table)
    assert set(log.loc[log["reward"] == 1.0, "action_name"]) == {"wait"}


def test_summary_fields_from_the_log(scenario: str) -> None:
    robot, human = make_robot("hybrid", criterion="random"), make_human("cooperative")
    result = run(robot, human, RunConfig(scenario=scenario, duration=80.0, seed=1))
    log, s = result.log, result.summary
    assert s["actions"] == len(log)
    assert s["failed_actions"] == int(log["failed"].sum()) > 0
    assert s["simulated_time"] == log["time"].iloc[-1] >= 80.0
    assert s["planner_share"] == pytest.approx((log["expert"] == "planner").sum() / len(log))
    assert s["duration"] == 80.0


def test_run_stops_at_duration_not_before(scenario: str) -> None:
    result = run(make_robot("planner"), make_human("cooperative"), RunConfig(scenario=scenario, duration=60.0, seed=0))
    times = result.log["time"].tolist()
    assert times[-1] >= 60.0 > times[-2]


def test_max_decisions_caps_the_log(scenario: str) -> None:
    config = RunConfig(scenario=scenario, duration=1e6, seed=0, max_decisions=7)
    assert len(run(make_robot("planner"), make_human("cooperative"), config).log) == 7


def test_progress_hook_sees_each_cycles_clock_and_log_round_trips(scenario: str, tmp_path: Path) -> None:
    seen: list[float] = []
    config = RunConfig(scenario=scenario, duration=40.0, seed=0)
    result = run(make_robot("planner"), make_human("cooperative"), config, on_decision=seen.append)
    finished = result.log[result.log["human_action"] >= 0]
    assert seen == finished["time"].tolist()
    path = result.save(tmp_path / "log.csv")
    back = pd.read_csv(path)
    assert list(back.columns) == list(result.log.columns) and len(back) == len(result.log)
    assert back["action_name"].tolist() == result.log["action_name"].tolist()


def test_human_as_expected_only_where_a_plan_predicted_the_human(scenario: str) -> None:
    robot = make_robot("hybrid", criterion="random")
    log = run(robot, make_human("cooperative"), RunConfig(scenario=scenario, duration=60.0, seed=3)).log
    log = log[log["human_action"] >= 0]
    no_prediction = log["expected_human_action"] < 0
    assert no_prediction.any() and (~no_prediction).any()
    assert log.loc[no_prediction, "human_as_expected"].isna().all()
    predicted = log.loc[~no_prediction]
    assert (predicted["human_as_expected"] == (predicted["human_action"] == predicted["expected_human_action"])).all()


def test_habit_robot_logs_no_planner_fields(scenario: str) -> None:
    log = run(make_robot("habit"), make_human("cooperative"), RunConfig(scenario=scenario, duration=20.0, seed=0)).log
    assert set(log["expert"]) == {"habit"}
    assert (log["planner_action"] == -1).all() and (log["expected_human_action"] == -1).all()
    assert (log["planner_nodes"] == 0).all() and log["human_as_expected"].isna().all()
    assert (log["decision_time"] == 0.001).all()  # the habit's modelled 1 ms


def test_empty_log_summary() -> None:
    assert summarise(pd.DataFrame(columns=list(COLUMNS)), 10.0) == {
        "tasks_solved": 0,
        "actions": 0,
        "failed_actions": 0,
        "simulated_time": 0.0,
        "duration": 10.0,
        "planner_share": 0.0,
        "final_weight_amplitude": 0.0,
        "human_as_expected": None,
    }


class _Waiter:
    """A minimal actor (no decision record): always the last action, wait."""

    name = "waiter"

    def reset(self, world, agent, rng) -> None:  # type: ignore[no-untyped-def]
        self.n = world.n_actions(agent)

    def act(self, turn) -> int:  # type: ignore[no-untyped-def]
        return self.n - 1


def test_actor_without_a_record_gets_the_documented_defaults(scenario: str) -> None:
    log = run(_Waiter(), make_human("cooperative"), RunConfig(scenario=scenario, duration=10.0, seed=0)).log
    assert set(log["expert"]) == {"waiter"} and set(log["action_name"]) == {"wait"}
    for column in ("planner_action", "habit_action", "expected_human_action"):
        assert (log[column] == -1).all(), column
    assert (log["decision_time"] == 0.0).all() and (log["planner_nodes"] == 0).all()
