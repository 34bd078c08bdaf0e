"""An interrupted sweep, run again, gives what an uninterrupted sweep gives, in job order.

Written against the sweep's public behaviour (jobs in, one summary per job out, finished
jobs kept on disk) so that it holds for any results store that keeps that promise.
"""

from __future__ import annotations

import logging
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.training import backends
from hg_marl.training.sweep import Job, load_log, run_sweep

JOBS = [Job(robot="random", seed=s, duration=40.0, human="random", label="mix") for s in range(3)]


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list[dict]]:
    """An uninterrupted sweep."""
    out = tmp_path_factory.mktemp("uninterrupted")
    return out, run_sweep(JOBS, out)


def test_rerun_after_a_crash_equals_an_uninterrupted_sweep(
    tmp_path: Path, reference: tuple[Path, list[dict]], monkeypatch: pytest.MonkeyPatch
) -> None:
    ref_out, ref = reference
    real = backends.execute

    def crash_on_second(job: Job):  # type: ignore[no-untyped-def]
        if job.seed == 1:
            raise KeyboardInterrupt("interrupted")
        return real(job)

    monkeypatch.setattr(backends, "execute", crash_on_second)
    with pytest.raises(KeyboardInterrupt):
        run_sweep(JOBS, tmp_path, workers=1)  # in this process, where the patched execute is seen
    monkeypatch.setattr(backends, "execute", real)
    again = run_sweep(JOBS, tmp_path)
    assert [s["job"]["seed"] for s in again] == [0, 1, 2]
    assert again == ref
    for job in JOBS:
        pd.testing.assert_frame_equal(
            load_log(job, tmp_path).drop(columns="planning_time"), load_log(job, ref_out).drop(columns="planning_time")
        )


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


def test_sweep_logs_runs_made_and_reused_whenever_it_did_either(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    def sweep_lines() -> list[str]:
        prefix = f"store {tmp_path / 'store'}: "
        return [r.getMessage().removeprefix(prefix) for r in caplog.records if r.getMessage().startswith(prefix)]

    caplog.set_level(logging.INFO, logger="hg_marl.training.sweep")
    run_sweep(JOBS[:1], tmp_path)  # a fresh store: one run made, none reused
    assert sweep_lines() == ["1 runs made, 0 reused"]
    caplog.clear()
    run_sweep(JOBS[:1], tmp_path)  # the same job again: found in the store
    assert sweep_lines() == ["0 runs made, 1 reused"]
    caplog.clear()
    run_sweep([], tmp_path)  # nothing to do: nothing to say
    assert sweep_lines() == []


def test_a_job_claimed_elsewhere_does_not_hold_back_the_jobs_after_it(
    tmp_path: Path, reference: tuple[Path, list[dict]]
) -> None:
    """Another process holds the first job's claim: the sweep runs the others meanwhile, then that one."""
    import threading
    import time

    from hg_marl.training.sweep import store_of

    _, ref = reference
    store = store_of(tmp_path)
    keys = [job.key() for job in JOBS]
    results: list[list[dict]] = []
    with store.claim(keys[0]) as held:
        assert held
        sweep = threading.Thread(target=lambda: results.append(run_sweep(JOBS, tmp_path)), daemon=True)
        sweep.start()
        deadline = time.monotonic() + 600
        # An entry's result.json is written last (atomically): once each is there, each must read
        # back, so an entry stored unreadable fails here at once rather than at the deadline.
        while not all((store.entry(key) / "result.json").is_file() for key in keys[1:]):
            assert time.monotonic() < deadline, "the jobs after the claimed one were never run"
            assert sweep.is_alive(), "the sweep stopped while a job was still claimed elsewhere"
            time.sleep(0.05)
        assert all(store.get(job, key) for job, key in zip(JOBS[1:], keys[1:], strict=True))
        assert store.get(JOBS[0], keys[0]) is None  # still ours: the sweep waits for it
    sweep.join(timeout=600)
    assert not sweep.is_alive() and results == [ref]
