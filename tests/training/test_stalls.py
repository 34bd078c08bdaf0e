"""The stall measure: the longest stretch without a task, worked by hand."""

from __future__ import annotations

import pandas as pd

from hg_marl.training.stalls import longest_gap


def test_longest_gap_counts_from_start_between_tasks_and_to_the_end() -> None:
    # tasks at 100 s and 150 s, run of 1000 s: stretches 100, 50, 850
    log = pd.DataFrame({"time": [50.0, 100.0, 120.0, 150.0, 400.0], "tasks_solved": [0, 1, 1, 2, 2]})
    assert longest_gap(log, 1000.0) == 850.0
    # a first task late: the start counts
    log = pd.DataFrame({"time": [10.0, 700.0, 800.0], "tasks_solved": [0, 1, 2]})
    assert longest_gap(log, 900.0) == 700.0


def test_no_task_at_all_is_the_whole_run() -> None:
    log = pd.DataFrame({"time": [10.0, 20.0], "tasks_solved": [0, 0]})
    assert longest_gap(log, 600.0) == 600.0
    assert longest_gap(log.iloc[:0], 600.0) == 600.0
