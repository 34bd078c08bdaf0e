"""The store's entries by hand: where ``put`` files a run, and what ``get`` gives back.

A run put without its key is filed under the job's own key (``runs/<first two>/<key>``),
so a later ``get`` of the same job finds it; the summary and log come back unchanged.
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from hg_marl.training.runner import COLUMNS, RunConfig, RunResult, summarise
from hg_marl.training.store import Job, Store

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
