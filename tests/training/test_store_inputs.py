"""The store's keys cover every input of a run, and its entries are checked before they are used.

- files a spec names (a learned human's folder, a replay trace, an SB3 model's header
  and weights, a file named inside a nested spec) are keyed by content;
- the code digest covers the modules a run imports (found by a static import walk);
- a tampered, non-finite or incomplete entry is reported in one warning line and re-run;
- worker counts and Ray addresses are checked before anything starts.
"""

from __future__ import annotations

import json
import logging
import shutil
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents import content
from hg_marl.agents.humans.learned import save_learned_policy
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.training.backends import make_backend, max_workers
from hg_marl.training.store import Job, Store, code_roots, content_key, seal
from hg_marl.training.sweep import run_jobs
from tests.cli_helpers import error_lines, run_main
from tests.source_copy import copy_sources, write

SHORT = 60.0
PAPER = World("paper2015")


def _uniform(folder: Path) -> Path:
    """A linear-softmax human with zero weights: uniform over its feasible actions."""
    return save_learned_policy(folder, PAPER, weights=np.zeros((PAPER.n_actions(Agent.HUMAN), PAPER.n_facts)))


def _waiter(folder: Path) -> Path:
    """A table human with no rows: every observation is unseen, so it always waits."""
    return save_learned_policy(folder, PAPER, table={})


def _learned_job(folder: Path) -> Job:
    return Job(robot="planner", seed=0, duration=SHORT, human="learned", human_params={"path": str(folder)})


# -- files named by a spec --------------------------------------------------------------------


def test_replacing_the_learned_policy_runs_again_and_matches_a_fresh_store(tmp_path: Path) -> None:
    policy = _uniform(tmp_path / "policy")
    store = Store(tmp_path / "store")
    _, first = run_jobs([_learned_job(policy)], store)
    assert (first.ran, first.reused) == (1, 0)
    shutil.rmtree(policy)
    _waiter(policy)  # another policy behind the same path
    (after,), second = run_jobs([_learned_job(policy)], store)
    assert (second.ran, second.reused) == (1, 0)
    (fresh,), _ = run_jobs([_learned_job(policy)], Store(tmp_path / "fresh"))
    assert after.summary == fresh.summary
    _, third = run_jobs([_learned_job(policy)], store)
    assert (third.ran, third.reused) == (0, 1)  # unchanged content: reused


def test_a_changed_weights_file_changes_the_key_in_every_form_of_the_path(tmp_path: Path) -> None:
    folder = _uniform(tmp_path / "m")
    forms = [folder, folder / "policy.json", folder / "policy", folder / "policy.npz"]
    robot = [Job(robot="sb3", seed=0, robot_params={"path": str(f)}) for f in forms]
    before = [job.key() for job in robot]
    weights = folder / "policy.npz"
    weights.write_bytes(weights.read_bytes() + b"\0")  # the header is untouched
    assert all(job.key() != key for job, key in zip(robot, before, strict=True))


def test_a_changed_replay_trace_changes_the_key(tmp_path: Path) -> None:
    trace = tmp_path / "game.jsonl"
    trace.write_text('{"a": 1}\n')
    job = Job(robot="planner", seed=0, human="replay", human_params={"path": str(trace)})
    before = job.key()
    trace.write_text('{"a": 2}\n')  # same size, written within the same second
    assert job.key() != before
    trace.write_text('{"a": 1}\n')
    assert job.key() == before  # keyed by content: the same bytes, the same key


def test_a_file_named_inside_a_nested_spec_is_keyed_by_content(tmp_path: Path) -> None:
    folder = _uniform(tmp_path / "m")
    job = Job(
        robot="planner",
        seed=0,
        human="switching",
        human_params={"humans": ["cooperative", f"learned:path={folder},deterministic=true"], "at": [30.0]},
    )
    as_text = Job(robot="planner", seed=0, human=f"switching:humans=cooperative|learned:path={folder},at=[30]")
    before = job.key(), as_text.key()
    shutil.rmtree(folder)
    _waiter(folder)
    assert job.key() != before[0]
    assert as_text.key() != before[1]


def test_a_cached_oracle_of_a_learned_human_is_keyed_by_its_policy(tmp_path: Path) -> None:
    folder = _uniform(tmp_path / "m")
    fields = {"human": {"name": "learned", "params": {"path": str(folder)}}, "max_states": 10}
    before = content_key("oracle", fields)
    shutil.rmtree(folder)
    _waiter(folder)
    assert content_key("oracle", fields) != before


# -- code ---------------------------------------------------------------------------------------


def test_the_code_digest_covers_what_plays_a_run_and_not_the_reporting() -> None:
    from hg_marl.agents.humans.registry import HUMANS

    modules, outside = content.code_modules(code_roots())
    for name in (
        "hg_marl.training.backends",  # builds the actors (it was outside the old hand list)
        "hg_marl.training.runner",
        "hg_marl.agents.oracle",  # imported only inside backends' functions
        "hg_marl.agents.model_file",
        *(spec.target.partition(":")[0] for spec in HUMANS.values()),  # imported by name
    ):
        assert name in modules, name
    for name in ("hg_marl.training.report", "hg_marl.training.plots", "hg_marl.training.cli", "hg_marl.training.sweep"):
        assert name not in modules, name
    assert {"numpy", "pandas"} <= outside


def test_a_changed_module_changes_every_key_but_a_docstring_does_not(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    base = Job(robot="planner", seed=0, duration=SHORT)
    real = base.key()
    sources = copy_sources(tmp_path / "src", monkeypatch)
    backends = sources / "training/backends.py"
    source = backends.read_text()

    def key_with(text: str) -> str:
        write(backends, text)
        return base.key()

    same = key_with(source)
    assert same == real  # the copy is the checkout's code
    assert key_with(source.replace('"""Where runs execute', '"""Where the runs execute', 1)) == same
    assert key_with(source + "\n# a comment\n") == same
    assert key_with(source.replace("max_retries=2", "max_retries=3")) != same
    monkeypatch.undo()
    assert base.key() == same  # back to the real sources


# -- entries ------------------------------------------------------------------------------------


def _tasks_up_by_ten(record: dict) -> dict:
    record["summary"]["tasks_solved"] += 10
    return record


def _drop_and_reseal(record: dict) -> dict:
    del record["summary"]["tasks_solved"]
    return seal(record)  # a valid hash: the missing key itself must be caught


DAMAGE = {
    "tasks_edited": (lambda text: json.dumps(_tasks_up_by_ten(json.loads(text))), "tampered"),
    "nan": (lambda text: text.replace('"planner_share":', '"planner_share":NaN,"x":', 1), "non-finite"),
    "missing_key": (lambda text: json.dumps(_drop_and_reseal(json.loads(text))), "lacks 'tasks_solved'"),
    "no_hash": (lambda text: json.dumps({k: v for k, v in json.loads(text).items() if k != "sha256"}), "sha256"),
}


@pytest.mark.parametrize("damage", sorted(DAMAGE))
def test_an_edited_result_is_reported_in_one_line_and_run_again(
    tmp_path: Path, damage: str, caplog: pytest.LogCaptureFixture
) -> None:
    store = Store(tmp_path)
    job = Job(robot="planner", seed=0, duration=SHORT)
    (good,), _ = run_jobs([job], store)
    result = store.entry(job.key()) / "result.json"
    edit, phrase = DAMAGE[damage]
    result.write_text(edit(result.read_text()))
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        (again,), stats = run_jobs([job], store)
    warnings = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert len(warnings) == 1 and "\n" not in warnings[0]
    assert phrase in warnings[0] and job.key()[:12] in warnings[0]
    assert (stats.ran, stats.reused) == (1, 0)
    assert again.summary == good.summary


def _double_value(text: str) -> str:
    record = json.loads(text)
    record["value"] *= 2
    return json.dumps(record)


CACHED_DAMAGE = {
    "doubled_rate": (_double_value, "tampered"),
    "nan": (lambda text: text.replace('"value":118.0', '"value":NaN'), "non-finite"),
    "missing_value": (
        lambda text: json.dumps(seal({k: v for k, v in json.loads(text).items() if k != "value"})),
        "no 'value'",
    ),
}


@pytest.mark.parametrize("damage", sorted(CACHED_DAMAGE))
def test_an_edited_cached_value_is_reported_and_computed_again(
    tmp_path: Path, damage: str, caplog: pytest.LogCaptureFixture
) -> None:
    store = Store(tmp_path)
    calls: list[int] = []

    def compute() -> float:
        calls.append(1)
        return 118.0

    fields = {"human": {"name": "cooperative", "params": {}}}
    assert store.cached("oracle", fields, compute) == 118.0
    (path,) = (tmp_path / "cached" / "oracle").glob("*.json")
    edit, phrase = CACHED_DAMAGE[damage]
    path.write_text(edit(path.read_text().replace(" ", "")))
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        assert store.cached("oracle", fields, compute) == 118.0
    warnings = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert len(warnings) == 1 and phrase in warnings[0] and "\n" not in warnings[0]
    assert len(calls) == 2
    assert store.cached("oracle", fields, compute) == 118.0
    assert len(calls) == 2  # the recomputed value is sound again


# -- workers and addresses ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("backend", "workers", "address", "named"),
    [
        ("ray", 0, None, "--workers"),
        ("local", 0, None, "--workers"),
        ("local", -3, None, "--workers"),
        ("ray", "many", None, "--workers"),
        ("local", "max+1", None, "--workers"),
        ("ray", 1, "not an address", "--address"),
        ("ray", 1, "head:99999", "--address"),
        ("ray", 1, "ray://", "--address"),
    ],
)
def test_bad_workers_or_address_are_refused_before_anything_starts(
    backend: str, workers: object, address: str | None, named: str
) -> None:
    count = max_workers() + 1 if workers == "max+1" else workers
    with pytest.raises(ConfigError, match=named) as info:
        make_backend(backend, count, address)  # type: ignore[arg-type]
    assert "\n" not in str(info.value)


def test_evaluate_with_no_ray_workers_exits_2_in_one_line(tmp_path: Path) -> None:
    study = tmp_path / "tiny.toml"
    study.write_text('robots = ["planner"]\nhumans = ["cooperative"]\nseeds = 1\nduration = 10.0\n')
    out = tmp_path / "out"
    code, _, err = run_main(["evaluate", str(study), "--out", str(out), "--backend", "ray", "--workers", "0"])
    lines = error_lines(err)
    assert code == 2, err
    assert len(lines) == 1 and "--workers" in lines[0], err
    assert not out.exists()
