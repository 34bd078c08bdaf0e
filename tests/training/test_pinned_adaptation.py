"""The adaptation summary's reference after a switch, on logs whose metrics are worked by hand.

After the *last* change the robot is measured against the oracle's rate for the human it
then faces (the switch's final human), from the time of that last change. The sweep, the
oracle and the figures are replaced by stand-ins here, so the summary's numbers follow
from the constructed logs alone.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest

from hg_marl.training import adaptation
from hg_marl.training.adaptation import (
    ROBOTS,
    SWITCHES,
    AdaptationConfig,
    Switch,
    adaptation_jobs,
    adaptation_table,
    rate_curve,
    summarise_switch,
)

THERE_AND_BACK = Switch(("cooperative", "lazy", "noisy"), (100.0, 400.0))


def _log(completions: list[float], end: float = 1000.0) -> pd.DataFrame:
    """A decision every 10 s up to ``end``; reward 1 at each completion time."""
    times = np.arange(10.0, end + 1.0, 10.0)
    return pd.DataFrame({"time": times, "reward": np.isin(times, completions).astype(float)})


SLOW = _log([50.0, 200.0, 600.0, 700.0, 800.0, 900.0, 1000.0])
"""Two tasks before the last change (at 400 s), then one at 600 s and every 100 s after."""


def test_switch_last_and_final_are_the_last_change_and_human() -> None:
    assert THERE_AND_BACK.last == 400.0 and THERE_AND_BACK.final == "noisy"
    assert SWITCHES["adversarial_and_back"].final == "cooperative"
    assert SWITCHES["adversarial_and_back"].last == SWITCHES["lazy"].last + 300.0


def test_summary_is_measured_from_the_last_change() -> None:
    # oracle 36 tasks/h = 0.01 task/s from 400 s: D(t) = 0.01 (t - 400) - tasks in (400, t].
    # At 1000 s: 6 expected, 5 solved: 1 task lost (from the first change, 100 s, it would be 9 - 6 = 3).
    # Recovery: D peaks at 2 just before each completion (600, 700, ...); at tau = 500 D = 1, so the
    # robot never falls more than one task further behind from there: 100 s (at 490, D = 0.9: 1.1 > 1).
    row = summarise_switch([SLOW, SLOW], THERE_AND_BACK, 36.0, 1000.0)
    assert row["tasks_lost"] == pytest.approx({"mean": 1.0, "low": 1.0, "high": 1.0})
    assert row["time_to_recover"] == pytest.approx({"mean": 100.0, "low": 100.0, "high": 100.0})
    assert (row["recovered_runs"], row["runs"]) == (2, 2)


def test_summary_counts_the_runs_that_never_recover() -> None:
    never = _log([50.0])  # nothing after the change: 6 tasks lost, D only grows
    row = summarise_switch([SLOW, never], THERE_AND_BACK, 36.0, 1000.0)
    assert row["tasks_lost"]["mean"] == pytest.approx((1.0 + 6.0) / 2)
    assert row["time_to_recover"]["mean"] == pytest.approx(100.0)  # over the run that recovered
    assert (row["recovered_runs"], row["runs"]) == (1, 2)
    none = summarise_switch([never], THERE_AND_BACK, 36.0, 1000.0)
    assert none["time_to_recover"] == {"mean": None, "low": None, "high": None} and none["recovered_runs"] == 0


def test_rate_curve_by_hand() -> None:
    # completions at 100 and 200 s (and a zero-reward decision at 150 s): in (0, 300] two tasks in 300 s
    log = pd.DataFrame({"time": [100.0, 150.0, 200.0], "reward": [1.0, 0.0, 1.0]})
    assert rate_curve(log, np.array([300.0]), window=300.0).tolist() == [24.0]
    # in (50, 250] with a 200 s window: 2 - 0.5 (half of the first task counted by 50 s) = 1.5 -> 27/h
    assert rate_curve(log, np.array([250.0]), window=200.0).tolist() == pytest.approx([27.0])


def test_jobs_name_the_switching_human_and_its_schedule() -> None:
    config = AdaptationConfig(seeds=2, switches=("back",), robots=("planner", "habit"), custom={"back": THERE_AND_BACK})
    jobs = adaptation_jobs(config)
    assert [(j.label, j.robot, j.seed) for j in jobs] == [
        ("adapt_back_planner", "planner", 0),
        ("adapt_back_planner", "planner", 1),
        ("adapt_back_habit", "habit", 0),
        ("adapt_back_habit", "habit", 1),
    ]
    assert jobs[0].human == "switching"
    assert jobs[0].human_params == {"humans": ["cooperative", "lazy", "noisy"], "at": [100.0, 400.0], "by": "time"}
    assert jobs[2].robot_params == ROBOTS["habit"][1] and jobs[0].duration == config.duration


def test_robots_compared_leave_entropy_to_the_hybrid_default() -> None:
    assert "entropy" not in ROBOTS and ROBOTS["hybrid_partner_aware"] == ("hybrid", {"partner_aware": True})


def test_run_adaptation_measures_against_the_final_humans_oracle(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    rates = {"cooperative": 72.0, "lazy": 18.0, "noisy": 36.0}
    drawn: dict[str, Any] = {}

    class Rate:
        def __init__(self, value: float) -> None:
            self.rate_per_hour = value

    def fake_figure(grid: np.ndarray, curves: dict[str, np.ndarray], phases: list[Any], title: str, path: Path) -> Path:
        drawn["phases"], drawn["curves"], drawn["grid"] = phases, curves, grid
        return path

    monkeypatch.setattr("hg_marl.agents.oracle.oracle_rate", lambda scenario, human: Rate(rates[human]))
    monkeypatch.setattr(adaptation, "run_sweep", lambda jobs, out, workers=1, on_done=None: None)
    monkeypatch.setattr(adaptation, "load_log", lambda job, out: SLOW)
    monkeypatch.setattr("hg_marl.training.plots.adaptation", fake_figure)
    monkeypatch.setattr("hg_marl.training.plots.regret_bars", lambda results, path: path)
    seen: list[Path] = []
    config = AdaptationConfig(
        seeds=2, duration=1000.0, switches=("back",), robots=("planner",), custom={"back": THERE_AND_BACK}, window=300.0
    )
    summary, figures = adaptation.run_adaptation(tmp_path, config, on_figure=lambda _, p: seen.append(p))
    assert summary["oracle_rate_per_hour"] == {"cooperative": 72.0, "lazy": 18.0, "noisy": 36.0, "adversarial": 0.0}
    row = summary["results"]["back"]["robots"]["planner"]
    assert row["tasks_lost"]["mean"] == pytest.approx(1.0)  # noisy's 36/h from 400 s, as worked above
    assert row["time_to_recover"]["mean"] == pytest.approx(100.0)
    assert summary["results"]["back"]["humans"] == ["cooperative", "lazy", "noisy"]
    assert summary["results"]["back"]["at"] == [100.0, 400.0]
    assert drawn["phases"] == [(0.0, 72.0), (100.0, 18.0), (400.0, 36.0)]
    assert drawn["grid"][0] == 300.0 and drawn["grid"][-1] == 1000.0 and len(drawn["grid"]) == 71
    assert drawn["curves"]["planner"].shape == (2, 71)
    assert seen == [figures["adaptation_back"], figures["adaptation_regret"]]
    assert figures["adaptation_back"] == tmp_path / "adaptation_back.png"


def test_table_prints_never_for_no_recovery() -> None:
    ci = {"mean": 1.25, "low": 1.0, "high": 1.5}
    none = {"mean": None, "low": None, "high": None}
    summary = {
        "seeds": 2,
        "duration": 1000.0,
        "oracle_rate_per_hour": {"noisy": 36.0},
        "results": {
            "back": {"robots": {"planner": {"tasks_lost": ci, "time_to_recover": none, "recovered_runs": 0, "runs": 2}}}
        },
    }
    lines = adaptation_table(summary).splitlines()
    assert lines[0] == "adaptation: 2 seeds, 1000 s runs; oracle tasks/h: noisy 36.0"
    assert len(lines[2]) == len(lines[1]) and set(lines[2]) == {"-"}
    assert lines[3].split() == ["back", "planner", "1.2", "[1.0,", "1.5]", "never", "0/2"]


def test_a_switch_whose_times_and_humans_do_not_pair_is_refused(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Three humans need two change times; with one the phases cannot be drawn: an error, not a short figure."""

    class Rate:
        rate_per_hour = 36.0

    monkeypatch.setattr("hg_marl.agents.oracle.oracle_rate", lambda scenario, human: Rate())
    monkeypatch.setattr(adaptation, "run_sweep", lambda jobs, out, workers=1, on_done=None: None)
    monkeypatch.setattr(adaptation, "load_log", lambda job, out: SLOW)
    monkeypatch.setattr("hg_marl.training.plots.adaptation", lambda *a: tmp_path / "x.png")
    monkeypatch.setattr("hg_marl.training.plots.regret_bars", lambda results, path: path)
    bad = Switch(("cooperative", "lazy", "noisy"), (100.0,))
    config = AdaptationConfig(seeds=1, duration=1000.0, switches=("bad",), robots=("planner",), custom={"bad": bad})
    with pytest.raises(ValueError):
        adaptation.run_adaptation(tmp_path, config)
