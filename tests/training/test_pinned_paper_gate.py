"""The paper experiment's conditions, per-condition summary, targets and printed table, pinned for the mutation gate.

Every expected value is worked by hand from the module's docstrings on logs small enough
to add up on paper: a condition's means over seeds (spreads with ``ddof=1``, 0 for one
seed), the planner's share of the last third (decisions at or after 2/3 of the last
decision's time), Fig. 5's mean curve (a short run held at its last value) and the first
decision at which it reaches the threshold, the three qualitative targets with their
strict and non-strict inequalities, and the printed table's columns.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from hg_marl.training import paper
from hg_marl.training.paper import ConditionLogs, check_targets, conditions, crossing, jobs, mean_amplitude
from hg_marl.training.paper import summarise_condition as summarise

HABIT_LINEAR = {"features": "facts"}
COST_AWARE = "a cost-aware criterion keeps >= 95% of the planner's tasks with <= 25% planner decisions late"


def _log(
    times: list[float], reward: list[float], failed: list[bool], expert: list[str], amp: list[float]
) -> pd.DataFrame:
    return pd.DataFrame({"time": times, "reward": reward, "failed": failed, "expert": expert, "weight_amplitude": amp})


def _empty() -> pd.DataFrame:
    return _log([], [], [], [], [])


# A: decisions at 3, 6, 9 s; two tasks; one failure; planner, habit, planner; amplitude 0.5, 1, 2.
# The last third starts at 9 * 2/3 = 6 s: the decisions at 6 and 9 s, one of them the planner's.
LOG_A = _log([3.0, 6.0, 9.0], [0.0, 1.0, 1.0], [False, True, False], ["planner", "habit", "planner"], [0.5, 1.0, 2.0])
# B: one habit decision at 3 s solving a task; amplitude 0.25 (held at 0.25 beside A's longer run).
LOG_B = _log([3.0], [1.0], [False], ["habit"], [0.25])


def test_the_paper_conditions_come_first_and_the_further_criteria_are_hybrids_with_their_defaults() -> None:
    assert conditions(further=False) == {
        "planner": ("planner", {}),
        "habit": ("habit", {"q_config": HABIT_LINEAR}),
        "random": ("hybrid", {"criterion": "random", "q_config": HABIT_LINEAR, "share_objects": False}),
    }
    full = conditions()
    assert list(full) == ["planner", "habit", "random", "entropy", "entropy_and_cost", "vpi", "learning_state"]
    assert full["vpi"] == ("hybrid", {"criterion": "vpi"})


def test_jobs_are_every_condition_then_every_seed_with_the_options_given() -> None:
    """Two seeds of the paper's three conditions: six jobs, seeds innermost."""
    made = jobs(seeds=2, duration=50.0, scenario="roboergosum", further=False, human="lazy")
    assert [(j.label, j.robot, j.seed) for j in made] == [
        ("planner", "planner", 0),
        ("planner", "planner", 1),
        ("habit", "habit", 0),
        ("habit", "habit", 1),
        ("random", "hybrid", 0),
        ("random", "hybrid", 1),
    ]
    assert {(j.scenario, j.duration, j.human) for j in made} == {("roboergosum", 50.0, "lazy")}
    assert made[2].robot_params == {"q_config": HABIT_LINEAR}
    assert len(jobs(seeds=1)) == 7  # the documented defaults: every criterion, one job each
    assert len(jobs(further=False)) == 30  # ten seeds by default (the paper's figures are means over 10)
    assert {(j.scenario, j.duration, j.human) for j in jobs(seeds=1)} == {("paper2015", 1100.0, "cooperative")}


def test_a_condition_of_two_seeds_is_summarised_by_its_means_and_sample_spreads() -> None:
    """A and B by hand: tasks 2 and 1 (mean 1.5, sample std sqrt(0.5)), actions 3 and 1 (2, sqrt 2),
    failures 1 and 0, planner shares 2/3 and 0, last thirds 1/2 and 0, final amplitudes 2 and 0.25;
    the mean curve (0.5+0.25)/2, (1+0.25)/2, (2+0.25)/2 = 0.375, 0.625, 1.125 first reaches 1 at decision 2."""
    row = summarise(ConditionLogs("hybrid", [LOG_A, LOG_B]))
    assert row["seeds"] == 2
    assert row["tasks_solved"] == [2.0, 1.0]
    assert row["tasks_solved_mean"] == pytest.approx(1.5)
    assert row["tasks_solved_std"] == pytest.approx(math.sqrt(0.5))
    assert row["actions_mean"] == pytest.approx(2.0)
    assert row["actions_std"] == pytest.approx(math.sqrt(2.0))
    assert row["failed_actions_mean"] == pytest.approx(0.5)
    assert row["planner_share"] == pytest.approx(1 / 3)
    assert row["planner_share_last_third"] == pytest.approx(0.25)
    assert row["final_weight_amplitude_mean"] == pytest.approx(1.125)
    assert row["amplitude_rise_decision"] == 2


def test_one_seed_has_no_spread_and_an_empty_run_counts_zero_everywhere() -> None:
    """One seed: both spreads 0 (a sample spread of one value is undefined). An empty log beside A:
    its tasks, actions, shares and amplitude are 0; the mean curve ignores it, so it is A's own
    0.5, 1, 2, which reaches 1 exactly at decision 1."""
    one = summarise(ConditionLogs("planner", [LOG_A]))
    assert one["tasks_solved_std"] == 0.0 and one["actions_std"] == 0.0
    assert one["planner_share_last_third"] == pytest.approx(0.5)
    mixed = summarise(ConditionLogs("habit", [LOG_A, _empty()]))
    assert mixed["tasks_solved"] == [2.0, 0.0]
    assert mixed["actions_mean"] == pytest.approx(1.5)
    assert mixed["planner_share"] == pytest.approx(1 / 3)
    assert mixed["planner_share_last_third"] == pytest.approx(0.25)
    assert mixed["final_weight_amplitude_mean"] == pytest.approx(1.0)
    assert mixed["amplitude_rise_decision"] == 1


def test_a_condition_whose_runs_are_all_empty_never_rises() -> None:
    """No decision at all: an empty mean curve, so no crossing; every mean 0."""
    row = summarise(ConditionLogs("habit", [_empty(), _empty()]))
    assert mean_amplitude([_empty()]).shape == (0,)
    assert mean_amplitude([]).shape == (0,)
    assert row["amplitude_rise_decision"] is None
    assert row["actions_mean"] == 0.0 and row["planner_share"] == 0.0 and row["planner_share_last_third"] == 0.0
    assert row["final_weight_amplitude_mean"] == 0.0


def test_the_last_third_begins_at_two_thirds_of_the_last_decisions_time() -> None:
    """Decisions at 0, 3, 6 s: the cut is 4 s, so only the decision at 6 s (the planner's) counts: 1.0.
    A run whose decisions are all at 0 s has its cut at 0: every decision counts (1 of 2)."""
    late = _log([0.0, 3.0, 6.0], [0.0] * 3, [False] * 3, ["habit", "habit", "planner"], [0.0] * 3)
    assert summarise(ConditionLogs("x", [late]))["planner_share_last_third"] == pytest.approx(1.0)
    instant = _log([0.0, 0.0], [0.0] * 2, [False] * 2, ["habit", "planner"], [0.0] * 2)
    assert summarise(ConditionLogs("x", [instant]))["planner_share_last_third"] == pytest.approx(0.5)


def test_crossing_is_the_first_decision_at_or_above_the_threshold() -> None:
    curve = np.array([0.2, 1.0, 3.0, 0.5])
    assert crossing(curve) == 1  # the default threshold is 1.0 (AMPLITUDE_RISE), reached exactly
    assert crossing(np.array([0.99, 0.999])) is None
    assert crossing(curve, 3.0) == 2
    assert crossing(curve, 0.1) == 0
    assert crossing(curve, 5.0) is None


def _row(tasks: float, actions: float = 100.0, rise: int | None = None, late: float = 0.0) -> dict[str, object]:
    return {
        "tasks_solved_mean": tasks,
        "actions_mean": actions,
        "amplitude_rise_decision": rise,
        "planner_share_last_third": late,
    }


def test_the_paper_targets_hold_on_the_papers_own_figures() -> None:
    """34 > 25 > 2 x 3; 250 / 100 = 2.5 >= 2; the mix rises at 5, the habit never: all three hold."""
    out = check_targets({"planner": _row(34.0, 100.0), "random": _row(25.0, 150.0, 5), "habit": _row(3.0, 250.0)})
    assert out["planner > random mix >> habit"] == {"planner": 34.0, "random": 25.0, "habit": 3.0, "holds": True}
    assert out["habit proposes >= 2x the planner's actions"] == {"ratio": 2.5, "holds": True}
    assert out["amplitude rises earlier with the mix"] == {"mix_decision": 5, "habit_decision": None, "holds": True}
    assert COST_AWARE not in out  # no criterion beyond the paper's three


def test_the_paper_targets_fail_at_their_boundaries() -> None:
    """random 25 is not > 2 x 12.5; a ratio of exactly 2 holds (>=) and 1.99 does not; rises at
    the same decision are not earlier; a mix that never rises is never earlier."""
    tie = check_targets({"planner": _row(34.0, 100.0), "random": _row(25.0, 1.0, 7), "habit": _row(12.5, 200.0, 7)})
    assert tie["planner > random mix >> habit"]["holds"] is False
    assert tie["habit proposes >= 2x the planner's actions"] == {"ratio": 2.0, "holds": True}
    assert tie["amplitude rises earlier with the mix"]["holds"] is False
    low = check_targets({"planner": _row(34.0, 100.0), "random": _row(34.0, 1.0), "habit": _row(3.0, 199.0, 9)})
    assert low["planner > random mix >> habit"]["holds"] is False  # 34 is not > 34
    assert low["habit proposes >= 2x the planner's actions"] == {"ratio": pytest.approx(1.99), "holds": False}
    assert low["amplitude rises earlier with the mix"]["holds"] is False
    later = check_targets({"planner": _row(3.0, 100.0), "random": _row(2.0, 1.0, 8), "habit": _row(0.5, 200.0, 4)})
    assert later["planner > random mix >> habit"]["holds"] is True  # 3 > 2 > 1
    assert later["amplitude rises earlier with the mix"]["holds"] is False  # 8 is after 4
    slow_planner = check_targets({"planner": _row(20.0), "random": _row(25.0), "habit": _row(3.0, 200.0)})
    assert slow_planner["planner > random mix >> habit"]["holds"] is False  # 20 < 25, though 25 > 6
    earlier = check_targets({"planner": _row(3.0), "random": _row(2.0, 1.0, 3), "habit": _row(0.5, 200.0, 4)})
    assert earlier["amplitude rises earlier with the mix"]["holds"] is True


def test_a_planner_without_actions_gives_a_huge_ratio_not_a_division_error() -> None:
    """The planner's actions are floored at 1e-9: 1 / 1e-9 = 1e9."""
    out = check_targets({"planner": _row(0.0, 0.0), "random": _row(0.0, 1.0), "habit": _row(0.0, 1.0)})
    assert out["habit proposes >= 2x the planner's actions"]["ratio"] == pytest.approx(1e9)


def test_a_planner_without_tasks_gives_each_criterion_a_ratio_not_a_division_error() -> None:
    """The planner's 0 tasks are floored at 1e-9: a criterion with 0 tasks is at 0 / 1e-9 = 0 of it
    (and holds: 0 >= 0.95 x 0, and no late planner decision)."""
    best = check_targets({"planner": _row(0.0), "vpi": _row(0.0, late=0.0)})[COST_AWARE]
    assert best == {"criterion": "vpi", "tasks_vs_planner": 0.0, "planner_share_last_third": 0.0, "holds": True}


def test_the_tables_action_ratio_divides_by_the_planners_actions_however_few() -> None:
    """The floor 1e-9 only guards a zero: 1.5 actions over 0.5 is 3.0x."""
    row = {
        "tasks_solved_mean": 0.0,
        "tasks_solved_std": 0.0,
        "actions_std": 0.0,
        "failed_actions_mean": 0.0,
        "planner_share": 0.0,
        "planner_share_last_third": 0.0,
    }
    text = paper.table({"planner": {**row, "actions_mean": 0.5}, "habit": {**row, "actions_mean": 1.5}})
    assert text.split("\n")[-1] == "habit proposes 3.0x the planner's actions (paper: 2-3x)"


def test_the_cost_aware_target_picks_the_holding_criterion_with_the_fewest_late_planner_decisions() -> None:
    """Planner 20: a criterion holds with >= 19 tasks (95%) and <= 0.25 late. vpi (19 tasks, 0.25: both
    bounds exactly) and entropy (20, 0.1) hold, entropy with fewer late decisions; learning_state
    (30 tasks, 0.3) does not hold, and a holding one beats it whatever its share."""
    summary = {
        "planner": _row(20.0, late=1.0),
        "habit": _row(0.0, late=0.0),
        "vpi": _row(19.0, late=0.25),
        "learning_state": _row(30.0, late=0.3),
        "entropy": _row(20.0, late=0.1),
    }
    best = check_targets(summary)[COST_AWARE]
    assert best == {"criterion": "entropy", "tasks_vs_planner": 1.0, "planner_share_last_third": 0.1, "holds": True}
    only_vpi = check_targets({k: v for k, v in summary.items() if k != "entropy"})[COST_AWARE]
    assert only_vpi["criterion"] == "vpi" and only_vpi["holds"] is True
    assert only_vpi["tasks_vs_planner"] == pytest.approx(0.95)
    assert "planner > random mix >> habit" not in check_targets(summary)  # no random mix in it


def test_without_a_holding_criterion_the_least_late_one_is_reported_and_the_first_wins_a_tie() -> None:
    """Neither holds (18.9 < 19; 0.26 > 0.25): the lower late share is reported; on an equal share
    the first listed stays."""
    out = check_targets({"planner": _row(20.0), "vpi": _row(18.9, late=0.2), "entropy": _row(25.0, late=0.26)})
    assert out[COST_AWARE]["criterion"] == "vpi" and out[COST_AWARE]["holds"] is False
    tie = check_targets({"planner": _row(20.0), "vpi": _row(20.0, late=0.2), "entropy": _row(20.0, late=0.2)})
    assert tie[COST_AWARE]["criterion"] == "vpi"
    assert check_targets({"planner": _row(20.0), "habit": _row(1.0)}) == {}  # only paper conditions
    assert check_targets({"vpi": _row(20.0)}) == {}  # no planner to compare with


def test_the_table_prints_each_condition_beside_the_papers_figure_and_the_action_ratio() -> None:
    """Columns by hand: name left in 18, tasks mean right in 9 (one decimal) ' ± ' std left in 4,
    the paper's figure right in 8 (habit '<=3', a criterion without one '-'), actions right in 9
    (no decimal) ' ± ' std left in 4, failures right in 9, shares right in 15 and 12 (two decimals);
    the ratio 250 / 100 = 2.5."""

    def row(tasks: float, std: float, actions: float, share: float, late: float) -> dict[str, float]:
        return {
            "tasks_solved_mean": tasks,
            "tasks_solved_std": std,
            "actions_mean": actions,
            "actions_std": 2.0,
            "failed_actions_mean": 3.0,
            "planner_share": share,
            "planner_share_last_third": late,
        }

    summary = {"planner": row(34.0, 1.5, 100.0, 1.0, 0.5), "habit": row(3.0, 0.5, 250.0, 0.0, 0.0)}
    summary["vpi"] = row(30.0, 2.5, 120.0, 0.25, 0.125)
    lines = paper.table(summary).split("\n")
    head = (
        "condition".ljust(18)
        + "tasks solved".rjust(16)
        + "paper".rjust(8)
        + "actions".rjust(16)
        + "failed".rjust(9)
        + "planner share".rjust(15)
        + "last third".rjust(12)
    )
    assert lines[0] == head and lines[1] == "-" * len(head)

    def expected(name: str, tasks: str, std: str, paper_text: str, actions: str, share: str, late: str) -> str:
        return (
            name.ljust(18)
            + tasks.rjust(9)
            + " ± "
            + std.ljust(4)
            + paper_text.rjust(8)
            + actions.rjust(9)
            + " ± "
            + "2".ljust(4)
            + "3".rjust(9)
            + share.rjust(15)
            + late.rjust(12)
        )

    assert lines[2] == expected("planner", "34.0", "1.5", "34", "100", "1.00", "0.50")
    assert lines[3] == expected("habit", "3.0", "0.5", "<=3", "250", "0.00", "0.00")
    assert lines[4] == expected("vpi", "30.0", "2.5", "-", "120", "0.25", "0.12")
    assert lines[5] == "habit proposes 2.5x the planner's actions (paper: 2-3x)"
    assert len(lines) == 6
    no_habit = paper.table({"planner": summary["planner"]}).split("\n")
    assert len(no_habit) == 3  # no ratio line without both the habit and the planner
