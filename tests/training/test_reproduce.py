"""Smoke runs of the paper's experiment and of the adaptation experiment."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from hg_marl.training import adaptation
from hg_marl.training.adaptation import AdaptationConfig, Switch, rate_curve, run_adaptation
from hg_marl.training.cli import app


def test_reproduce_smoke(tmp_path: Path) -> None:
    out = tmp_path / "paper"
    args = ["reproduce", "--seeds", "2", "--duration", "240", "--out", str(out), "--no-adaptation", "--workers", "1"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    conditions = summary["conditions"]
    assert {"planner", "habit", "random", "entropy", "entropy_and_cost", "vpi", "learning_state"} <= set(conditions)
    for name, row in conditions.items():
        assert row["seeds"] == 2
        assert row["actions_mean"] > 0
        assert 0.0 <= row["planner_share"] <= 1.0, name
        # a task takes at least 7 robot actions (3 picks or takes, 3 throws: only the robot
        # reaches the bin; the completing wait)
        assert 7 * row["tasks_solved_mean"] <= row["actions_mean"], name
    assert conditions["planner"]["planner_share"] == 1.0 and conditions["habit"]["planner_share"] == 0.0
    assert conditions["planner"]["tasks_solved_mean"] >= 5, "240 s is several tasks for the planner"
    assert conditions["planner"]["tasks_solved_mean"] > conditions["habit"]["tasks_solved_mean"]
    assert conditions["random"]["final_weight_amplitude_mean"] > 0, "the planner's transitions teach the habit"
    for key in ("fig3", "fig4", "fig5"):
        png = Path(summary["figures"][key])
        assert png.exists() and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # drawing the figures is a stage with its own bar: the wait is never silent
    assert "paper figures: 100%" in result.output and "3/3" in result.output
    assert "paper" in result.output and "planner" in result.output
    # resuming finds every run done and reproduces the same summary
    again = CliRunner().invoke(app, args)
    assert again.exit_code == 0
    assert json.loads((out / "summary.json").read_text())["conditions"] == conditions


def test_rate_on_a_constructed_log() -> None:
    times = np.concatenate([np.arange(30, 601, 30.0), np.arange(900, 1801, 60.0)])
    log = pd.DataFrame({"time": times, "reward": 1.0})
    grid = np.array([600.0, 1800.0])
    assert rate_curve(log, grid, window=300.0).tolist() == [120.0, 60.0]


def test_rate_is_continuous_between_completions() -> None:
    """One task every 120 s: the interpolated count solves 2.5 tasks in any 300 s window
    (30 tasks/h) wherever the window lies, where whole-task counts jump between 2 and 3
    (24 and 36 tasks/h)."""
    log = pd.DataFrame({"time": np.arange(120.0, 2401.0, 120.0), "reward": 1.0})
    grid = np.arange(400.0, 2200.0, 7.0)
    assert rate_curve(log, grid, window=300.0) == pytest.approx(np.full(len(grid), 30.0))
    # before the first completion the count rises from 0 at t = 0: half a task by 60 s
    assert rate_curve(log, np.array([60.0]), window=300.0)[0] == pytest.approx(0.5 * 3600 / 300)


def test_adaptation_smoke(tmp_path: Path) -> None:
    short = Switch(("cooperative", "no_handover"), (300.0,))
    config = AdaptationConfig(
        seeds=2, duration=600.0, switches=("short",), robots=("planner", "habit"), custom={"short": short}
    )
    summary, figures = run_adaptation(tmp_path, config)
    oracle = summary["oracle_rate_per_hour"]
    assert oracle["cooperative"] > oracle["no_handover"] > 0
    rows = summary["results"]["short"]["robots"]
    assert set(rows) == {"planner", "habit"}
    planner, habit = rows["planner"]["tasks_lost"], rows["habit"]["tasks_lost"]
    assert planner["low"] <= planner["mean"] <= planner["high"]
    assert planner["mean"] < habit["mean"], "the planner keeps solving tasks after the switch, the habit barely"
    assert rows["planner"]["recovered_runs"] >= rows["habit"]["recovered_runs"]
    assert figures["adaptation_short"].exists() and figures["adaptation_regret"].exists()
    assert "planner" in adaptation.adaptation_table(summary)


def test_reproduce_with_a_new_duration_never_reuses_the_old_runs(tmp_path: Path) -> None:
    from hg_marl.training.reproduce import ReproduceConfig, reproduce

    base = ReproduceConfig(out=tmp_path / "a", seeds=1, duration=120.0, paper_only=True, adaptation=False)
    reproduce(base)
    longer = reproduce(replace(base, duration=240.0))
    fresh = reproduce(replace(base, out=tmp_path / "b", duration=240.0))
    assert longer["duration"] == 240.0
    assert longer["conditions"] == fresh["conditions"]  # same as never having run 120 s before
    assert (
        longer["conditions"]["planner"]["tasks_solved_mean"]
        > reproduce(base)["conditions"]["planner"]["tasks_solved_mean"]
    )
