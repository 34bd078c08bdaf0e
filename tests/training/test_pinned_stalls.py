"""The stall report read from a study's store, worked by hand on a store written here.

Three runs: the planner and the habit with ``picky`` on ``paper`` (the planner solves
tasks, so the cell is solvable), and the planner with ``lazy`` on ``paper`` (no robot
solves a task with it: the cell is left out of the report). Every figure below is counted
from the logs written in this file, not by the code under test.
"""

from __future__ import annotations

import gzip
import json
import runpy
import warnings
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.training.stalls import STALL_SECONDS, longest_gap, report, runs_of


def _store_run(out: Path, name: str, job: dict[str, object], log: pd.DataFrame) -> None:
    folder = out / "store" / "runs" / name[:2] / name
    folder.mkdir(parents=True)
    (folder / "result.json").write_text(json.dumps({"job": job}))
    with gzip.open(folder / "log.csv.gz", "wt") as f:
        log.to_csv(f, index=False)


def _study(tmp_path: Path) -> Path:
    base = {"scenario": "paper", "duration": 1000.0}
    # planner with picky:k=2: tasks at 100 s and 700 s -> stretches 100, 600, 300: longest 600 (> 300: a stall)
    planner = {**base, "robot": "planner", "robot_params": {}, "human": "picky", "human_params": {"k": 2}, "seed": 1}
    log = pd.DataFrame(
        {
            "time": [50.0, 100.0, 400.0, 700.0, 900.0],
            "tasks_solved": [0, 1, 1, 2, 2],
            "reason": ["plan", "no_progress", "plan", "no_progress", "no_progress"],
        }
    )
    _store_run(tmp_path, "aa01", planner, log)
    # habit:alpha=0.5 with the same partner: one task at 250 s -> stretches 250, 750: longest 750, no guard moves
    habit = {**planner, "robot": "habit", "robot_params": {"alpha": 0.5}, "seed": 2}
    log = pd.DataFrame({"time": [250.0, 260.0], "tasks_solved": [1, 1], "reason": ["habit", "habit"]})
    _store_run(tmp_path, "bb02", habit, log)
    # planner with lazy: no task at all (the whole run, 1000 s), a cell no robot solves
    lazy = {**base, "robot": "planner", "robot_params": {}, "human": "lazy", "human_params": {}, "seed": 3}
    log = pd.DataFrame({"time": [10.0, 20.0], "tasks_solved": [0, 0], "reason": ["plan", "plan"]})
    _store_run(tmp_path, "cc03", lazy, log)
    return tmp_path


def test_a_task_solved_on_the_first_row_ends_the_first_stretch() -> None:
    # the first row already shows a task (at 30 s): stretches 30 and 70, not one of 100
    log = pd.DataFrame({"time": [30.0, 60.0], "tasks_solved": [1, 1]})
    assert longest_gap(log, 100.0) == 70.0


def test_runs_of_reads_each_stored_run(tmp_path: Path) -> None:
    rows = runs_of(_study(tmp_path))
    assert rows == [
        {
            "robot": "planner",
            "human": "picky:k=2",
            "scenario": "paper",
            "seed": 1,
            "tasks": 2,
            "gap": 600.0,
            "guard_moves": 3,
        },
        {
            "robot": "habit:alpha=0.5",
            "human": "picky:k=2",
            "scenario": "paper",
            "seed": 2,
            "tasks": 1,
            "gap": 750.0,
            "guard_moves": 0,
        },
        {
            "robot": "planner",
            "human": "lazy",
            "scenario": "paper",
            "seed": 3,
            "tasks": 0,
            "gap": 1000.0,
            "guard_moves": 0,
        },
    ]


def test_report_counts_stalls_over_solvable_cells_only(tmp_path: Path) -> None:
    assert STALL_SECONDS == 300.0
    lines = report(_study(tmp_path)).splitlines()
    assert lines[0] == ("| robot | runs | stalls (> 300 s without a task) | longest stretch (s) | guard moves/run |")
    # the lazy cell (no task by any robot) is not counted: the planner has one run, not two
    assert lines[2:] == [
        "| habit:alpha=0.5 | 1 | 1 | 750 (picky:k=2, paper, seed 2) | 0.0 |",
        "| planner | 1 | 1 | 600 (picky:k=2, paper, seed 1) | 3.0 |",
    ]


def test_the_longest_stretch_is_the_worst_run_and_short_ones_are_not_stalls(tmp_path: Path) -> None:
    out = _study(tmp_path)
    # a second planner run with picky: tasks every 200 s (longest 200 s, no stall), one guard move
    job = {
        "scenario": "paper",
        "duration": 1000.0,
        "robot": "planner",
        "robot_params": {},
        "human": "picky",
        "human_params": {"k": 2},
        "seed": 4,
    }
    times = [200.0, 400.0, 600.0, 800.0, 1000.0]
    log = pd.DataFrame(
        {
            "time": [1.0, *times],
            "tasks_solved": [0, 1, 2, 3, 4, 5],
            "reason": ["no_progress", "plan", "plan", "plan", "plan", "plan"],
        }
    )
    _store_run(out, "dd04", job, log)
    planner = [ln for ln in report(out).splitlines() if ln.startswith("| planner |")]
    # runs 2, stalls 1 (the 600 s one), worst 600 s (seed 1), guard moves (3 + 1) / 2
    assert planner == ["| planner | 2 | 1 | 600 (picky:k=2, paper, seed 1) | 2.0 |"]


def test_the_module_run_as_a_script_prints_the_report_or_its_usage(tmp_path: Path, monkeypatch, capsys) -> None:  # type: ignore[no-untyped-def]
    out = _study(tmp_path / "study")
    monkeypatch.setattr("sys.argv", ["stalls", str(out)])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the module is already imported by this file
        runpy.run_module("hg_marl.training.stalls", run_name="__main__")
    assert capsys.readouterr().out == report(out) + "\n"
    for argv in (["stalls", str(tmp_path)], ["stalls"], ["stalls", str(out), "extra"]):
        monkeypatch.setattr("sys.argv", argv)
        with warnings.catch_warnings(), pytest.raises(SystemExit) as info:
            warnings.simplefilter("ignore", RuntimeWarning)
            runpy.run_module("hg_marl.training.stalls", run_name="__main__")
        assert info.value.code == 2
        assert capsys.readouterr().out.startswith("usage: python -m hg_marl.training.stalls STUDY_OUT_FOLDER")
