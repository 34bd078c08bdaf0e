"""An interrupted sweep, run again, gives what an uninterrupted sweep gives, in job order.

Written against the sweep's public behaviour (jobs in, one summary per job out, finished
jobs kept on disk) so that it holds for any results store that keeps that promise.
"""

from __future__ import annotations

import os
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.training import sweep
from hg_marl.training.sweep import Job, load_log, run_sweep

JOBS = [Job("mix", "random", seed=s, duration=40.0, human="random") for s in range(3)]


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list[dict]]:
    """An uninterrupted sweep."""
    out = tmp_path_factory.mktemp("uninterrupted")
    return out, run_sweep(JOBS, out)


def test_rerun_after_a_crash_equals_an_uninterrupted_sweep(
    tmp_path: Path, reference: tuple[Path, list[dict]], monkeypatch: pytest.MonkeyPatch
) -> None:
    ref_out, ref = reference
    real = sweep.execute

    def crash_on_second(job: Job):  # type: ignore[no-untyped-def]
        if job.seed == 1:
            raise KeyboardInterrupt("interrupted")
        return real(job)

    monkeypatch.setattr(sweep, "execute", crash_on_second)
    with pytest.raises(KeyboardInterrupt):
        run_sweep(JOBS, tmp_path)
    assert JOBS[0].paths(tmp_path)[1].exists() and not JOBS[1].paths(tmp_path)[1].exists()
    monkeypatch.setattr(sweep, "execute", real)
    again = run_sweep(JOBS, tmp_path)
    assert [s["job"]["seed"] for s in again] == [0, 1, 2]
    assert again == ref
    for job in JOBS:
        pd.testing.assert_frame_equal(
            load_log(job, tmp_path).drop(columns="planning_time"), load_log(job, ref_out).drop(columns="planning_time")
        )


def test_a_log_without_its_summary_is_not_a_finished_job(tmp_path: Path, reference: tuple[Path, list[dict]]) -> None:
    # killed between writing the log and writing the summary: the job must run again
    _, ref = reference
    log_path, summary_path = JOBS[2].paths(tmp_path)
    log_path.parent.mkdir(parents=True)
    log_path.write_text("decision,time\n0,0.0\n")  # a stale, truncated log
    again = run_sweep(JOBS, tmp_path)
    assert again == ref
    assert summary_path.exists() and len(pd.read_csv(log_path)) == ref[2]["actions"]


@pytest.mark.parametrize("workers", [1, 2])
def test_results_keep_job_order_when_later_jobs_finished_first(
    tmp_path: Path, reference: tuple[Path, list[dict]], workers: int
) -> None:
    _, ref = reference
    run_sweep(JOBS[2:], tmp_path)  # the last job finished in an earlier session
    done: list[int] = []
    again = run_sweep(JOBS, tmp_path, workers=workers, on_done=lambda job, _: done.append(job.seed))
    assert again == ref
    assert [s["job"]["seed"] for s in again] == [0, 1, 2]
    assert sorted(done) == [0, 1, 2]


def test_one_worker_runs_in_this_process_two_in_others(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    calls: list[tuple[int, int]] = []
    real = sweep.execute

    def spy(job: Job):  # type: ignore[no-untyped-def]
        calls.append((os.getpid(), job.seed))
        return real(job)

    monkeypatch.setattr(sweep, "execute", spy)
    run_sweep(JOBS[:2], tmp_path / "one", workers=1)
    assert calls == [(os.getpid(), 0), (os.getpid(), 1)]  # in-process, in order
    calls.clear()
    out = run_sweep(JOBS[:2], tmp_path / "two", workers=2)
    assert calls == []  # the jobs ran in worker processes (their calls are recorded there)
    assert [s["job"]["seed"] for s in out] == [0, 1]
