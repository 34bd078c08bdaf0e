"""Which member a switching study's recovery is measured against, worked by hand on unequal rates.

After a change the robot must keep the pace of the member who *takes over*, not the one
who leaves; with equal member rates the two cannot be told apart, so the rates here
differ: A at 0 tasks/h (nothing to keep up with), B at 36 tasks/h (0.01 task/s).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest

from hg_marl.training import switching
from hg_marl.training.switching import (
    SwitchingConfig,
    _short,
    mean_recovery,
    reference_tasks,
    schedule,
    switching_jobs,
    switching_table,
)


def _idle_log(end: float) -> pd.DataFrame:
    """A decision every 10 s, no task ever solved."""
    times = np.arange(10.0, end + 1.0, 10.0)
    return pd.DataFrame({"time": times, "reward": np.zeros(len(times))})


def test_recovery_is_measured_against_the_member_who_takes_over() -> None:
    # Period 400 s over 1100 s: A [0, 400), B [400, 800), A [800, 1100]; changes at 400 and 800.
    # Into B at 400 (phase to 800, min_tail 100): D(t) = 0.01 (t - 400) reaches 4 at 800; the robot
    # keeps within one task of it from tau = 700 on (4 - 3 = 1): 300 s.
    # Into A at 800: A's rate is 0, D never rises: recovered at once, 0 s. Mean (300 + 0) / 2 = 150.
    # (Against the leaving member instead: 0 s into B, and 200 s into A: a mean of 100.)
    got = mean_recovery(_idle_log(1100.0), (0.0, 36.0), 400.0, 1100.0, min_phase=200.0)
    assert got == pytest.approx(150.0)
    # the rates the other way round: into B (0/h) at 400: 0 s; into A (36/h) at 800, phase to 1100:
    # D reaches 3, tau >= 1000 (the last candidate the 100 s tail allows): 200 s. Mean 100.
    assert mean_recovery(_idle_log(1100.0), (36.0, 0.0), 400.0, 1100.0, min_phase=200.0) == pytest.approx(100.0)


def test_a_phase_as_long_as_min_phase_is_read_and_a_shorter_one_is_not() -> None:
    # 1000 s: the last phase, 800 -> 1000, lasts exactly min_phase = 200 s: read (into A at 0/h: 0 s)
    assert mean_recovery(_idle_log(1000.0), (0.0, 36.0), 400.0, 1000.0, min_phase=200.0) == pytest.approx(150.0)
    # min_phase 250: that phase is left out; into B needs tau >= 700 but the tail of 125 s
    # allows tau <= 675: no recovery read at all
    assert mean_recovery(_idle_log(1000.0), (0.0, 36.0), 400.0, 1000.0, min_phase=250.0) is None


def test_reference_with_a_short_last_phase() -> None:
    # A 36/h for 400 s (4), B 72/h for 400 s (8), A for 200 s (2)
    assert reference_tasks((36.0, 72.0), 400.0, 1000.0) == pytest.approx(14.0)
    assert reference_tasks((36.0, 72.0), 1000.0, 1000.0) == pytest.approx(10.0)  # one phase, no change


def test_schedule_thresholds_are_whole_periods() -> None:
    assert schedule(("x", "y"), 400.0, 1000.0) == (["x", "y", "x"], [400.0, 800.0])
    assert schedule(("x", "y"), 250.0, 1000.0) == (["x", "y", "x", "y"], [250.0, 500.0, 750.0])


def test_short_keeps_both_ends_within_the_width() -> None:
    assert _short("abcdefghij", 7) == "ab...ij"  # 4 characters kept: 2 from the start, 2 from the end
    assert _short("abcdefghij", 8) == "ab...hij"
    assert _short("abcdefghij", 10) == "abcdefghij"
    assert all(len(_short("x" * 40, w)) == w for w in range(4, 40))


CONFIG = SwitchingConfig(
    scenario="paper2015",
    pairs=(("A", "B"),),
    periods=(400.0,),
    robots=("planner", "other"),
    seeds=2,
    duration=1100.0,
    min_phase=200.0,
    members=(("A", "lazy"), ("B", "cooperative")),
)


def test_jobs_play_the_members_specs_on_the_schedule() -> None:
    jobs = switching_jobs(CONFIG)
    assert [(j.robot, j.seed) for j in jobs] == [("planner", 0), ("planner", 1), ("other", 0), ("other", 1)]
    assert jobs[0].human_params == {"humans": ["lazy", "cooperative", "lazy"], "at": [400.0, 800.0], "by": "time"}
    assert jobs[0].label == "switch_A_B_400_planner"


def _stand_ins(monkeypatch: pytest.MonkeyPatch, solved: dict[tuple[str, int], list[float]]) -> None:
    """Runs replaced by logs that solve a task at each of ``solved[(robot, seed)]``'s times (one
    at 1050 s where a pair is not listed); A at 0 tasks/h, B at 36."""

    def log_of(job: Any, out: Path) -> pd.DataFrame:
        log = _idle_log(1100.0)
        done = solved.get((job.robot, job.seed), [1050.0])
        log.loc[log["time"].isin(done), "reward"] = 1.0
        return log

    class Rate:
        def __init__(self, value: float) -> None:
            self.rate_per_hour = value

    monkeypatch.setattr(switching, "check_config", lambda config: None)
    monkeypatch.setattr(switching, "run_sweep", lambda jobs, out, workers=1, on_done=None: None)
    monkeypatch.setattr(switching, "load_log", log_of)
    monkeypatch.setattr(
        "hg_marl.agents.oracle.oracle_rate", lambda s, spec: Rate({"lazy": 0.0, "cooperative": 36.0}[spec])
    )


def test_run_switching_pairs_each_robot_with_the_baseline_by_seed(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Stand-ins: the planner solves 3 tasks on seed 0 and 5 on seed 1; "other" solves 1 on each seed."""
    _stand_ins(
        monkeypatch, {("planner", 0): [500.0, 600.0, 900.0], ("planner", 1): [100.0, 200.0, 500.0, 600.0, 900.0]}
    )
    summary = switching.run_switching(CONFIG, tmp_path)
    assert summary["oracle_rate_per_hour"] == {"A": 0.0, "B": 36.0} and summary["baseline"] == "planner"
    cells = {c["robot"]: c for c in summary["cells"]}
    # reference: A 0/h, B 36/h for 400 s: 4 tasks
    assert cells["other"]["reference_tasks"] == pytest.approx(4.0)
    assert cells["planner"]["tasks"]["mean"] == pytest.approx(4.0)
    assert cells["other"]["regret"]["mean"] == pytest.approx(3.0)
    # paired by seed: 1 - 3 = -2 and 1 - 5 = -4; the baseline against itself is exactly 0
    assert cells["other"]["difference"]["mean"] == pytest.approx(-3.0)
    assert cells["other"]["difference"]["high"] == pytest.approx(-2.0) and cells["other"]["loses"] is True
    assert (
        cells["planner"]["difference"] == {"mean": 0.0, "low": 0.0, "high": 0.0} and cells["planner"]["loses"] is False
    )
    assert cells["other"]["recovered_runs"] == 2 and cells["other"]["recovery"]["mean"] == pytest.approx(150.0)
    table = switching_table(summary).splitlines()
    assert len(table) == 4 and len(table[1]) == len(table[0]) and set(table[1]) == {"-"}
    assert "vs planner" in table[0] and table[3].endswith("  LOSES") and not table[2].endswith("LOSES")


def test_a_robot_loses_only_when_its_whole_difference_ci_is_below_zero(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """The planner solves 3 tasks on each seed; "other" 1 and 5: paired differences -2 and +2,
    a CI from -2 to +2 that holds 0, so "other" is not marked as losing (its low end is below 0)."""
    _stand_ins(
        monkeypatch,
        {
            ("planner", 0): [500.0, 600.0, 900.0],
            ("planner", 1): [500.0, 600.0, 900.0],
            ("other", 1): [100.0, 200.0, 500.0, 600.0, 900.0],
        },
    )
    summary = switching.run_switching(CONFIG, tmp_path)
    cells = {c["robot"]: c for c in summary["cells"]}
    other = cells["other"]["difference"]
    assert other["mean"] == pytest.approx(0.0)
    assert other["low"] == pytest.approx(-2.0) and other["high"] == pytest.approx(2.0)
    assert cells["other"]["loses"] is False
    assert "LOSES" not in switching_table(summary)
