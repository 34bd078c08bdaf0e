"""The sweep's waiting, checked by counting waits instead of waiting.

A sweep sleeps only when every job it has left is claimed by another process and none
of its own is running: a lone sweep never sleeps, and a sweep that finds its first job
claimed elsewhere runs every other job before its first sleep. Each test replaces the
sweep's clock with one that records (and checks) each sleep, so a sweep that would wait
for ever fails at its first wrong sleep instead of hanging.
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from types import SimpleNamespace

import pytest

from hg_marl.training import sweep as sweep_module
from hg_marl.training.backends import LocalBackend
from hg_marl.training.sweep import Job, run_sweep, store_of

JOBS = [Job(robot="random", seed=s, duration=40.0, human="random", label="gate") for s in range(3)]


@pytest.mark.parametrize("workers", [1, 2])
def test_a_lone_sweep_never_sleeps(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, workers: int) -> None:
    def no_sleep(seconds: float) -> None:
        raise AssertionError(f"a sweep with no other process slept {seconds} s")

    monkeypatch.setattr(sweep_module, "time", SimpleNamespace(sleep=no_sleep))
    results = run_sweep(JOBS, tmp_path, workers=workers)
    assert [r["job"]["seed"] for r in results] == [0, 1, 2]


def test_the_jobs_after_a_claimed_one_all_run_before_the_first_sleep(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    store = store_of(tmp_path)
    keys = [job.key() for job in JOBS]
    held = contextlib.ExitStack()
    assert held.enter_context(store.claim(keys[0]))  # "another process" holds the first job
    sleeps: list[float] = []

    def first_sleep_releases(seconds: float) -> None:
        # by the first sleep, jobs 1 and 2 are done and job 0 is still the other process's
        assert [store.get(job, key) is not None for job, key in zip(JOBS, keys, strict=True)] == [False, True, True]
        sleeps.append(seconds)
        held.close()  # the other process lets go: the sweep takes job 0 on its next pass

    monkeypatch.setattr(sweep_module, "time", SimpleNamespace(sleep=first_sleep_releases))
    results = run_sweep(JOBS, tmp_path)
    assert [r["job"]["seed"] for r in results] == [0, 1, 2]
    assert sleeps == [sweep_module.POLL]  # one wait, then job 0 was free


def test_by_default_a_sweep_runs_its_jobs_in_this_process(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    asked: list[int] = []

    class Recording(LocalBackend):
        def __init__(self, workers: int = 1) -> None:
            asked.append(workers)
            if workers != 1:
                raise AssertionError(f"a pool of {workers} processes was started for a default sweep")
            super().__init__(workers)

    monkeypatch.setattr(sweep_module, "LocalBackend", Recording)
    run_sweep(JOBS[:1], tmp_path)
    assert asked == [1]


def test_each_job_is_reported_once_even_when_two_jobs_share_a_key(tmp_path: Path) -> None:
    # job 0 listed twice (equal keys: run once); on_done hears of every job of the list, once
    # each, whether the run was made now or found in the store, and the results keep job order
    jobs = [JOBS[0], JOBS[1], JOBS[0], JOBS[2]]
    for attempt in ("run", "found"):
        heard: list[int] = []
        out = run_sweep(jobs, tmp_path, on_done=lambda job, _, heard=heard: heard.append(job.seed))
        assert sorted(heard) == [0, 0, 1, 2], attempt
        assert [s["job"]["seed"] for s in out] == [0, 1, 0, 2] and out[0] == out[2], attempt
