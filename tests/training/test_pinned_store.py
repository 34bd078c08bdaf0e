"""The store's entries by hand: where ``put`` files a run, and what ``get`` gives back.

A run put without its key is filed under the job's own key (``runs/<first two>/<key>``),
so a later ``get`` of the same job finds it; the summary and log come back unchanged.
An entry whose seal matches but whose summary lacks one of the runner's fields, or holds
something other than a number there, is not used: skipped without the claim, reported in
one warning line and removed with it (the store's docstring).
"""

from __future__ import annotations

import json
import logging
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.training.runner import COLUMNS, RunConfig, RunResult, summarise
from hg_marl.training.store import Job, Store, seal

JOB = Job(robot="planner", seed=0, scenario="paper2015", duration=60.0, human="cooperative")


def _result() -> RunResult:
    log = pd.DataFrame({c: [] for c in COLUMNS})
    return RunResult(RunConfig(duration=60.0), log, summarise(log, 60.0))


def test_a_run_put_without_its_key_is_filed_under_the_jobs_key(tmp_path: Path) -> None:
    store = Store(tmp_path)
    stored = store.put(JOB, _result())
    key = JOB.key()
    assert stored.key == key
    assert (tmp_path / "runs" / key[:2] / key / "result.json").is_file()
    again = store.get(JOB)
    assert again is not None and again.key == key and again.summary == stored.summary
    assert again.summary["duration"] == 60.0 and again.tasks == 0.0 and len(again.log()) == 0


def test_a_run_put_with_its_key_is_the_same_entry(tmp_path: Path) -> None:
    store = Store(tmp_path)
    store.put(JOB, _result(), key=JOB.key())
    assert [p.name for p in (tmp_path / "runs").rglob("result.json")] == ["result.json"]
    assert store.get(JOB, JOB.key()) is not None


def _reseal_summary(store: Store, edit: dict[str, object], drop: str = "") -> Path:
    """Rewrite the stored entry of ``JOB`` with its summary edited, sealed again as ``put`` seals it."""
    path = store.entry(JOB.key()) / "result.json"
    record = json.loads(path.read_text())
    summary = {k: v for k, v in record["summary"].items() if k != drop}
    record["summary"] = {**summary, **edit}
    path.write_text(json.dumps(seal(record)))
    return path


def skipped_then_removed(store: Store, problem: str, caplog: pytest.LogCaptureFixture) -> None:
    """``JOB``'s unusable entry: skipped without the claim, removed with one warning naming ``problem`` with it."""
    assert store.get(JOB) is None
    assert store.entry(JOB.key()).exists()  # without the claim it is only skipped
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        assert store.get(JOB, repair=True) is None
    assert [problem in r.getMessage() for r in caplog.records] == [True]
    assert not store.entry(JOB.key()).exists()


def test_a_resealed_entry_with_the_same_summary_is_still_used(tmp_path: Path) -> None:
    # The control for the two tests below: sealing again by itself does not make an entry unusable.
    store = Store(tmp_path)
    store.put(JOB, _result())
    _reseal_summary(store, {})
    again = store.get(JOB)
    assert again is not None and again.summary["actions"] == 0 and again.summary["human_as_expected"] is None


@pytest.mark.parametrize(
    ("edit", "drop", "problem"),
    [
        ({}, "tasks_solved", "incomplete (summary lacks 'tasks_solved')"),
        ({"actions": "3"}, "", "corrupt (summary 'actions' is '3', not a finite number)"),
        ({"duration": None}, "", "corrupt (summary 'duration' is None, not a finite number)"),
        ({"planner_share": True}, "", "corrupt (summary 'planner_share' is True, not a finite number)"),
    ],
)
def test_a_sealed_entry_whose_summary_is_not_the_runners_is_not_used(
    tmp_path: Path, edit: dict[str, object], drop: str, problem: str, caplog: pytest.LogCaptureFixture
) -> None:
    # The seal matches, so only the summary check can refuse it: the runner writes every one
    # of its summary fields, each a number (only `human_as_expected` may be None).
    store = Store(tmp_path)
    store.put(JOB, _result())
    _reseal_summary(store, edit, drop)
    skipped_then_removed(store, problem, caplog)
