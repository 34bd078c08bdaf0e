"""The content-addressed results store: keys, reuse, corruption, claims, concurrency."""

from __future__ import annotations

import json
import logging
import os
import stat
import subprocess
import sys
import textwrap
from dataclasses import replace
from importlib import resources
from pathlib import Path

import pytest

import hg_marl
from hg_marl.agents import content
from hg_marl.agents.meta.cost import CostModel
from hg_marl.training.store import Job, Store, StoredRun
from hg_marl.training.sweep import run_jobs

SHORT = 60.0
"""Simulated seconds of the test runs (a few tasks, a fraction of a second each)."""

BASE = Job(robot="planner", seed=0, scenario="paper2015", duration=SHORT, human="cooperative")


def _paper2015_text() -> str:
    return resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()


VARIANTS = {
    "robot": replace(BASE, robot="habit"),
    "robot_params": replace(BASE, robot_params={"cost": CostModel(planner_base=0.1)}),
    "human": replace(BASE, human="lazy"),
    "human_params": replace(BASE, human_params={"p_idle": 0.5}),
    "scenario": replace(BASE, scenario="roboergosum"),
    "duration": replace(BASE, duration=SHORT + 1),
    "seed": replace(BASE, seed=1),
    "charge_decision_time": replace(BASE, charge_decision_time=False),
}


@pytest.mark.parametrize("field", sorted(VARIANTS))
def test_key_changes_with_each_input(field: str) -> None:
    assert VARIANTS[field].key() != BASE.key()


def test_key_ignores_label_and_object_identity() -> None:
    same = Job(robot="planner", seed=0, scenario="paper2015", duration=SHORT, human="cooperative", label="x")
    assert same.key() == BASE.key()
    assert len(BASE.key()) == 64


def test_scenario_is_keyed_by_file_content_not_name(tmp_path: Path) -> None:
    a, b = tmp_path / "a.toml", tmp_path / "b.toml"
    a.write_text(_paper2015_text())
    b.write_text(_paper2015_text())
    assert replace(BASE, scenario=str(a)).key() == replace(BASE, scenario=str(b)).key() == BASE.key()
    b.write_text(_paper2015_text() + "\n# one more line\n")
    assert replace(BASE, scenario=str(b)).key() != BASE.key()


def test_key_changes_with_version_and_code(monkeypatch: pytest.MonkeyPatch) -> None:
    before = BASE.key()
    monkeypatch.setattr(hg_marl, "__version__", "9.9.9")
    assert BASE.key() != before
    monkeypatch.undo()
    monkeypatch.setattr(content, "code_digest", lambda roots: "0" * 64)
    assert BASE.key() != before


def test_changed_duration_runs_again_same_duration_reuses(tmp_path: Path) -> None:
    store = Store(tmp_path)
    _, first = run_jobs([BASE], store)
    assert (first.ran, first.reused) == (1, 0)
    _, again = run_jobs([BASE], store)
    assert (again.ran, again.reused) == (0, 1)
    runs, longer = run_jobs([replace(BASE, duration=2 * SHORT)], store)
    assert (longer.ran, longer.reused) == (1, 0)
    assert runs[0].summary["duration"] == 2 * SHORT


def test_entries_are_readable_by_others(tmp_path: Path) -> None:
    store = Store(tmp_path)
    run_jobs([BASE], store)
    folder = store.entry(BASE.key())
    for name in ("result.json", "log.csv.gz"):
        assert stat.S_IMODE((folder / name).stat().st_mode) == 0o644


def test_claim_files_are_readable_by_others_under_the_usual_umask(tmp_path: Path) -> None:
    old = os.umask(0o022)
    try:
        with Store(tmp_path).claim("k" * 64) as held:
            assert held
            assert stat.S_IMODE((tmp_path / "claims" / f"{'k' * 64}.lock").stat().st_mode) == 0o644
    finally:
        os.umask(old)


@pytest.mark.parametrize("damage", ["truncate_result", "change_log", "drop_result"])
def test_corrupt_entry_is_rerun_with_one_warning(tmp_path: Path, damage: str, caplog: pytest.LogCaptureFixture) -> None:
    store = Store(tmp_path)
    (good,), _ = run_jobs([BASE], store)
    folder = store.entry(BASE.key())
    if damage == "truncate_result":
        text = (folder / "result.json").read_text()
        (folder / "result.json").write_text(text[: len(text) // 2])
    elif damage == "change_log":
        (folder / "log.csv.gz").write_bytes(b"not a log")
    else:
        (folder / "result.json").unlink()
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        (again,), stats = run_jobs([BASE], store)
    warnings = [r for r in caplog.records if r.levelno >= logging.WARNING]
    assert len(warnings) == 1
    assert BASE.key()[:12] in warnings[0].getMessage()
    assert "\n" not in warnings[0].getMessage()
    assert stats.ran == 1
    assert again.summary == good.summary


def test_claim_is_exclusive_and_a_dead_holder_claim_is_taken_over(tmp_path: Path) -> None:
    store = Store(tmp_path)
    key = BASE.key()
    with store.claim(key) as held:
        assert held
        with store.claim(key) as second:
            assert not second
    # A claim file left by a killed process (its pid is gone, so is its lock) is free.
    (tmp_path / "claims" / f"{key}.lock").write_text("999999999\n")
    with store.claim(key) as held:
        assert held


def test_cached_value_is_computed_once_per_key(tmp_path: Path) -> None:
    store = Store(tmp_path)
    calls: list[int] = []

    def compute() -> float:
        calls.append(1)
        return 42.5

    assert store.cached("oracle", {"human": "lazy"}, compute) == 42.5
    assert store.cached("oracle", {"human": "lazy"}, compute) == 42.5
    assert store.cached("oracle", {"human": "cooperative"}, compute) == 42.5
    assert len(calls) == 2


def test_a_cached_file_under_another_key_is_not_served(tmp_path: Path) -> None:
    """A cached value is served only when the key written inside the file is the file's own."""
    store = Store(tmp_path)
    assert store.cached("oracle", {"human": "lazy"}, lambda: 1.0) == 1.0
    (lazy,) = (tmp_path / "cached" / "oracle").glob("*.json")
    assert store.cached("oracle", {"human": "noisy"}, lambda: 2.0) == 2.0
    (noisy,) = [p for p in (tmp_path / "cached" / "oracle").glob("*.json") if p != lazy]
    noisy.write_text(lazy.read_text())  # the lazy human's result copied over the noisy human's entry
    assert store.cached("oracle", {"human": "noisy"}, lambda: 3.0) == 3.0


SWEEP = textwrap.dedent(
    """
    import json, sys
    from hg_marl.training.store import Job, Store
    from hg_marl.training.sweep import run_jobs
    jobs = [Job(robot=r, seed=s, duration=60.0) for r in ("planner", "random") for s in range(4)]
    _, stats = run_jobs(jobs, Store(sys.argv[1]))
    print(json.dumps({"ran": stats.ran, "reused": stats.reused}))
    """
)


def test_two_concurrent_sweeps_share_the_work(tmp_path: Path) -> None:
    env = {**os.environ, "PYTHONHASHSEED": "0"}
    procs = [
        subprocess.Popen([sys.executable, "-c", SWEEP, str(tmp_path)], stdout=subprocess.PIPE, text=True, env=env)
        for _ in range(2)
    ]
    outs = [json.loads(p.communicate(timeout=600)[0]) for p in procs]
    assert all(p.returncode == 0 for p in procs)
    assert sum(o["ran"] for o in outs) == 8  # each job ran exactly once
    assert all(o["ran"] + o["reused"] == 8 for o in outs)
    entries = list((tmp_path / "runs").glob("*/*/result.json"))
    assert len(entries) == 8
    for entry in entries:
        assert json.loads(entry.read_text())["key"] == entry.parent.name


def test_rate_is_tasks_per_simulated_hour(tmp_path: Path) -> None:
    # 3 tasks in 1,800 simulated seconds (half an hour) is 6 tasks per hour
    run = StoredRun("k", {}, {"tasks_solved": 3, "duration": 1800.0}, tmp_path / "log.csv.gz")
    assert run.tasks == 3.0
    assert run.rate == pytest.approx(6.0)
