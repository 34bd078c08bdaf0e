"""Switching partners: the schedule, the per-phase reference, recovery, the command and its figure."""

from __future__ import annotations

import json
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.training.switching import mean_recovery, reference_tasks, schedule
from tests.cli_helpers import error_lines, run_main
from tests.figure_checks import hidden_lines, overlapping_texts

ROOT = Path(__file__).resolve().parents[2]
POPULATION = ROOT / "populations" / "hard_layouts.toml"


def test_schedule_alternates_every_period() -> None:
    assert schedule(("a", "b"), 600.0, 1800.0) == (["a", "b", "a"], [600.0, 1200.0])
    assert schedule(("a", "b"), 700.0, 1800.0) == (["a", "b", "a"], [700.0, 1400.0])
    assert schedule(("a", "b"), 1800.0, 1800.0) == (["a"], [])


def test_reference_is_each_phase_at_its_members_rate() -> None:
    # A at 60 tasks/h for 600 s, B at 30 for 600 s, A for 600 s: 10 + 5 + 10
    assert reference_tasks((60.0, 30.0), 600.0, 1800.0) == pytest.approx(25.0)
    # 700 s phases: 60 * 700 + 30 * 700 + 60 * 400 task-seconds per hour
    assert reference_tasks((60.0, 30.0), 700.0, 1800.0) == pytest.approx((42000 + 21000 + 24000) / 3600)


def test_recovery_is_read_after_each_long_phase_change() -> None:
    """Member rates 360 and 360 tasks/h (one task per 10 s). After the change at 600 s the
    robot solves nothing for 100 s, then one task every 10 s: it keeps the pace from 700 s
    on (within one task), so it recovered in 100 s; before the change it kept the pace."""
    times = [float(t) for t in range(10, 601, 10)] + [float(t) for t in range(700, 1201, 10)]
    log = pd.DataFrame({"time": times, "reward": [1.0] * len(times)})
    got = mean_recovery(log, (360.0, 360.0), 600.0, 1200.0, min_phase=120.0)
    assert got == pytest.approx(100.0, abs=10.0)
    # changes into phases shorter than min_phase are not read
    assert mean_recovery(log, (360.0, 360.0), 600.0, 1200.0, min_phase=1000.0) is None


@pytest.mark.parametrize(
    ("args", "option"),
    [
        (["--pairs", "h_giver_only"], "--pairs"),
        (["--pairs", "h_giver_only/nobody"], "--pairs"),
        (["--pairs", "h_giver_only/h_giver_only"], "--pairs"),
        (["--pairs", "h_giver_only/h_hesitant", "--periods", "nan"], "--periods"),
        (["--pairs", "h_giver_only/h_hesitant", "--periods", "0"], "--periods"),
        (["--pairs", "h_giver_only/h_hesitant", "--periods", "ten"], "--periods"),
        (["--pairs", "h_giver_only/h_hesitant", "--periods", "0.01"], "--periods"),
        (["--pairs", "h_giver_only/h_hesitant", "--baseline", "oracle"], "--baseline"),
        (["--pairs", "h_giver_only/h_hesitant", "--seeds", "0"], "--seeds"),
        (["--pairs", "h_giver_only/h_hesitant", "--duration", "inf"], "--duration"),
        (["--pairs", "h_giver_only/h_hesitant", "--robots", "planner,bogus"], "--robots"),
        (["--pairs", "h_giver_only/h_hesitant", "--robots", "planner,planner:partner_aware=maybe"], "--robots"),
    ],
)
def test_bad_arguments_are_one_line(args: list[str], option: str, tmp_path: Path) -> None:
    code, _, err = run_main(["switching", "--population", str(POPULATION), *args, "--out", str(tmp_path / "o")])
    lines = error_lines(err)
    assert code == 2 and len(lines) == 1 and option in lines[0], err
    assert not (tmp_path / "o").exists()


def test_the_sweep_runs_and_draws_every_robot(tmp_path: Path) -> None:
    out = tmp_path / "sw"
    args = ["switching", "--population", str(POPULATION), "--pairs", "h_giver_only/h_soft_counter"]
    args += ["--periods", "20,120", "--seeds", "2", "--duration", "240", "--out", str(out)]
    code, stdout, err = run_main(args)
    assert code == 0, err
    summary = json.loads((out / "switching.json").read_text())
    cells = summary["cells"]
    # 1 pair x 2 periods x the 2 default robots (planner and belief over the population)
    assert [(c["period"], c["robot"].partition(":")[0]) for c in cells] == [
        (20.0, "planner"),
        (20.0, "belief"),
        (120.0, "planner"),
        (120.0, "belief"),
    ]
    for c in cells:
        assert c["regret"]["mean"] == pytest.approx(c["reference_tasks"] - c["tasks"]["mean"])
    assert all(c["difference"]["mean"] == 0.0 for c in cells if c["robot"] == "planner")
    assert "cells where a robot loses to planner" in stdout
    assert (out / "switching.png").stat().st_size > 0
    # a second run reuses every stored run
    code, _, err = run_main(args)
    assert code == 0 and "0 runs made, 8 reused" in err


def test_the_figure_shows_every_robot_and_the_reference() -> None:
    from hg_marl.training.plots import switching_figure

    def cell(pair: str, period: float, robot: str, mean: float, loses: bool = False) -> dict:
        ci = {"mean": mean, "low": mean - 1, "high": mean + 1}
        return {"pair": pair, "period": period, "robot": robot, "reference_tasks": 30.0, "tasks": ci, "loses": loses}

    cells = [
        cell(p, t, r, m)
        for p in ("a/b", "c/d")
        for t in (5.0, 60.0, 600.0)
        for r, m in (("planner", 20.0), ("belief", 25.0))
    ]
    cells[-1]["loses"] = True
    fig = switching_figure({"cells": cells, "baseline": "planner", "duration": 1800.0, "scenario": "s", "seeds": 3})
    labels = [t.get_text() for legend in fig.legends for t in legend.get_texts()]
    assert labels == ["per-phase best response", "planner", "belief", "belief: loses to planner"]
    assert [ax.get_title() for ax in fig.axes] == ["partner switches a <-> b", "partner switches c <-> d"]
    for ax in fig.axes:
        assert hidden_lines(ax) == []
        assert [t.get_text() for t in ax.get_xticklabels()] == ["5", "60", "600"]
    assert overlapping_texts(fig) == []


def test_robot_specs_are_typed_as_a_study_types_them() -> None:
    from hg_marl.training.switching import SwitchingConfig, switching_jobs

    config = SwitchingConfig(
        scenario="forced_coordination",
        pairs=(("a", "b"),),
        periods=(600.0,),
        robots=("planner", "planner:partner_aware=true"),
        seeds=1,
        members=(("a", "preference"), ("b", "preference:handover=1.0,shared=-0.5")),
    )
    jobs = switching_jobs(config)
    assert [dict(j.robot_params) for j in jobs] == [{}, {"partner_aware": True}]
    assert jobs[0].human_params == {
        "humans": ["preference", "preference:handover=1.0,shared=-0.5", "preference"],
        "at": [600.0, 1200.0],
        "by": "time",
    }


def test_each_robot_spec_is_parsed_once_per_config(monkeypatch: pytest.MonkeyPatch) -> None:
    from hg_marl.core.spec import AgentSpec
    from hg_marl.training.switching import SwitchingConfig, check_config, switching_jobs

    parsed: list[str] = []
    real = AgentSpec.parse.__func__  # type: ignore[attr-defined]

    def counting(cls: type[AgentSpec], text: str, what: str = "spec", where: str | None = None) -> AgentSpec:
        parsed.append(text)
        return real(cls, text, what, where)

    monkeypatch.setattr(AgentSpec, "parse", classmethod(counting))
    config = SwitchingConfig(
        scenario="forced_coordination",
        pairs=(("a", "b"),),
        periods=(600.0, 1200.0),
        robots=("planner", "planner:partner_aware=true"),
        seeds=3,
        duration=1800.0,
        members=(("a", "preference"), ("b", "preference:handover=1.0,shared=-0.5")),
    )
    check_config(config)
    jobs = switching_jobs(config)
    assert len(jobs) == 1 * 2 * 2 * 3  # pairs x periods x robots x seeds
    assert parsed == ["planner", "planner:partner_aware=true"]  # the check and all 12 jobs share one parse each
