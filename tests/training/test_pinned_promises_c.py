"""Pins documented promises of the switching sweep, the population generator, the study aggregates,
the study report, the results store, the sweep driver and the stall report that no other test
checked: bounds (a period giving exactly ``MAX_PHASES`` phases is accepted; a stretch of exactly
``STALL_SECONDS`` is no stall; three scores trim nothing from an IQM), tie-breaking (the
lexicographically first subset, the lowest index, the first run read), orders (jobs by pair, then
period; the report's sections; a population file's behaviour keys), defaults and edge cases (no
pair, no score, no ``reason`` column, no run in the store) and what a summary shows. Every expected
value is worked by hand from the rule the module states, comes from a simpler reference written
here (a plain SHA-256 of sorted-key JSON, the mean over every subset), or is a property (a seal
sealed again is unchanged); stores and study folders are written by hand under ``tmp_path``, and
the sweep's runs are stand-ins from a recording backend, so nothing is simulated.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import logging
import math
import re
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.meta.cost import CostModel
from hg_marl.core.errors import ConfigError
from hg_marl.training.aggregate import aggregate, iqm, score_matrix, seeds_per_task
from hg_marl.training.population_gen import (
    RIDGE,
    Generated,
    GeneratorConfig,
    local_search,
    random_spread,
    rbf_kernel,
    render,
    select,
)
from hg_marl.training.report import crossplay_table, markdown
from hg_marl.training.runner import COLUMNS, RunConfig, RunResult, summarise
from hg_marl.training.stalls import report as stall_report
from hg_marl.training.stalls import runs_of
from hg_marl.training.store import Job, Store, content_key, seal
from hg_marl.training.study import Study
from hg_marl.training.sweep import load_log, run_jobs
from hg_marl.training.switching import SwitchingConfig, check_config, switching_jobs, switching_table
from tests.training.test_pinned_report import _study as report_study
from tests.training.test_pinned_stalls import _store_run

# ---- training/switching.py ---------------------------------------------------------------


def _switching(**changes: Any) -> SwitchingConfig:
    fields: dict[str, Any] = {
        "scenario": "paper2015",
        "pairs": (("A", "B"),),
        "periods": (400.0,),
        "robots": ("planner",),
        "seeds": 1,
        "duration": 1200.0,
        "members": (("A", "lazy"), ("B", "cooperative"), ("C", "random")),
    }
    return SwitchingConfig(**{**fields, **changes})


def test_a_period_giving_exactly_max_phases_is_accepted_and_a_shorter_one_is_refused() -> None:
    # MAX_PHASES = 10,000: 10,000 s / 1 s is exactly 10,000 phases (allowed: "over" is refused),
    # 10,000 s / 0.5 s is 20,000 phases
    check_config(_switching(duration=10_000.0, periods=(1.0,)))
    with pytest.raises(ConfigError, match=r"^--periods 0\.5: .* is over 10000 phases"):
        check_config(_switching(duration=10_000.0, periods=(0.5,)))


def test_a_robot_named_twice_is_refused() -> None:
    with pytest.raises(ConfigError, match=r"^--robots: a robot is named twice$"):
        check_config(_switching(robots=("planner", "planner")))


def test_min_phase_must_be_positive_and_is_named_as_its_option() -> None:
    with pytest.raises(ConfigError, match="--min-phase"):
        check_config(_switching(min_phase=0.0))
    check_config(_switching(min_phase=0.5))  # any positive value is fine


def test_jobs_go_by_pair_then_period_then_robot_then_seed() -> None:
    # the docstring's (pair, period, robot, seed): the pair varies slowest
    config = _switching(pairs=(("A", "B"), ("C", "A")), periods=(400.0, 600.0), seeds=1)
    assert [j.label for j in switching_jobs(config)] == [
        "switch_A_B_400_planner",
        "switch_A_B_600_planner",
        "switch_C_A_400_planner",
        "switch_C_A_600_planner",
    ]


def test_the_table_shows_a_missing_recovery_as_a_dash_and_recovery_in_whole_seconds() -> None:
    def ci(mean: float | None, low: float | None = None, high: float | None = None) -> dict[str, float | None]:
        return {"mean": mean, "low": low, "high": high}

    cell: dict[str, Any] = {
        "pair": "A/B",
        "period": 400.0,
        "robot": "planner",
        "tasks": ci(4.0, 3.0, 5.0),
        "regret": ci(1.25, 0.5, 2.0),
        "difference": ci(0.0, 0.0, 0.0),
        "loses": False,
        "recovery": ci(150.4, 120.2, 180.6),
    }
    summary = {"baseline": "planner", "cells": [cell, {**cell, "recovery": ci(None)}]}
    rows = switching_table(summary).splitlines()[2:]
    # tasks and regret with one decimal; recovery rounded to whole seconds (150.4 -> 150, 180.6 -> 181)
    assert "4.0 [3.0, 5.0]" in rows[0] and "1.2 [0.5, 2.0]" in rows[0]
    assert rows[0].endswith("150 [120, 181]")
    # no recovery read: a dash, right-aligned in the 20-character column
    assert rows[1].endswith(" " * 19 + "-")


# ---- training/population_gen.py ----------------------------------------------------------


def test_select_ties_go_to_the_lexicographically_first_subset() -> None:
    # an identity kernel: every 2-subset has the same spread, so the first of the *sorted* pool wins
    kernel = np.eye(4)
    assert select(kernel, 2, [3, 1, 2, 0]) == [0, 1]
    assert select(kernel, 0, [3, 1]) == []
    with pytest.raises(ConfigError, match="cannot select 3 members from 2 candidates"):
        select(kernel, 3, [3, 1])


def test_local_search_ties_go_to_the_lowest_index() -> None:
    # every item adds the same spread to an identity kernel: the greedy build takes the lowest
    # index first, and no swap improves on a tie
    assert local_search(np.eye(5), 2, [4, 3, 2, 1, 0]) == [0, 1]


def test_the_kernel_width_is_the_median_of_the_nonzero_distances() -> None:
    # points 0, 0, 0, 2 on a line: distances 0 (three pairs) and 2 (three pairs); the nonzero
    # ones have median h = 2, so K between 0 and 2 is exp(-4 / (2 * 4)) = exp(-1/2)
    # (with the zeros counted the median would be 1 and K = exp(-2))
    kernel = rbf_kernel(np.array([[0.0], [0.0], [0.0], [2.0]]))
    assert kernel[0, 3] == pytest.approx(math.exp(-0.5))
    assert kernel[0, 1] == 1.0
    # no nonzero distance at all: h = 1, every entry exp(0) = 1 (never 0 / 0)
    assert rbf_kernel(np.zeros((3, 2))).tolist() == [[1.0] * 3] * 3


def test_random_spread_is_the_mean_over_every_subset_when_there_are_at_most_200() -> None:
    # 200 one-item subsets (exactly RANDOM_SUBSETS): all of them, each once; spread of {i} is log(d_i + RIDGE)
    d = np.linspace(0.1, 5.0, 200)
    expected = float(np.mean(np.log(d + RIDGE)))
    got = random_spread(np.diag(d), 1, range(200), np.random.default_rng(0))
    assert got == pytest.approx(expected, rel=1e-12)


def _generated(spread: dict[str, dict[str, float]], behaviour: dict[str, float]) -> Generated:
    member = {"name": "m00", "split": "train", "spec": "preference:handover=1.0", "behaviour": behaviour}
    return Generated(members=[member], spread=spread, dropped=[], n_candidates=1)


def test_render_leaves_out_a_spread_that_is_not_finite() -> None:
    text = render(GeneratorConfig(), _generated({"train": {"selected": -math.inf, "random": -2.5}}, {}), "t")
    lines = text.splitlines()
    at = lines.index("[spread.train]")
    assert lines[at + 1 : at + 3] == ["random = -2.5000", ""]
    assert not any(line.startswith("selected") for line in lines)


def test_render_writes_the_behaviour_keys_in_sorted_order() -> None:
    text = render(GeneratorConfig(), _generated({}, {"random.wait": 0.25, "planner.pick": 0.5}), "t")
    assert 'behaviour = { "planner.pick" = 0.5, "random.wait" = 0.25 }' in text.splitlines()


# ---- training/aggregate.py ---------------------------------------------------------------


def _scores(rows: list[tuple[str, str, int, float]]) -> pd.DataFrame:
    """(robot, human, seed, score) rows on one scenario."""
    return pd.DataFrame([{"robot": r, "human": h, "scenario": "s", "seed": s, "score": v} for r, h, s, v in rows])


def test_seeds_per_task_is_the_fewest_any_scored_cell_has() -> None:
    # A has 3 seeds against h, B 2: the fewest is 2
    frame = _scores(
        [("A", "h", 0, 0.1), ("A", "h", 1, 0.2), ("A", "h", 2, 0.3), ("B", "h", 0, 0.4), ("B", "h", 1, 0.5)]
    )
    assert seeds_per_task(frame) == 2
    assert "only 2 seeds" in aggregate(frame, reps=20, poi_reps=5)["bootstrap"]["flag"]
    frame["score"] = float("nan")
    assert seeds_per_task(frame) == 0  # no score at all


def test_a_robot_without_any_score_is_listed_in_study_order_with_nothing() -> None:
    frame = _scores([("B", "h", 0, float("nan")), ("B", "h", 1, float("nan")), ("A", "h", 0, 0.2), ("A", "h", 1, 0.4)])
    agg = aggregate(frame, reps=20, poi_reps=5)
    assert list(agg["robots"]) == ["B", "A"]  # study (first-seen) order
    assert agg["robots"]["B"] == {"iqm": None, "iqm_ci": None, "mean": None, "mean_ci": None, "runs": 0}
    assert agg["improvement"] == {}  # no pair with a robot that has no score


def test_score_matrix_rows_are_in_seed_order_whatever_the_table_order() -> None:
    frame = _scores([("A", "h", 2, 0.3), ("A", "h", 0, 0.1), ("A", "h", 1, 0.2)])
    assert score_matrix(frame, "A").tolist() == [[0.1], [0.2], [0.3]]


def test_the_iqm_of_fewer_than_four_scores_trims_nothing() -> None:
    # int(0.25 * 3) = 0 scores cut from each end: mean(0, 1, 5) = 2; with 4 scores one is cut
    # from each end: mean(1, 5) = 3
    assert float(iqm(np.array([[0.0], [1.0], [5.0]]))) == pytest.approx(2.0)
    assert float(iqm(np.array([[0.0], [1.0], [5.0], [9.0]]))) == pytest.approx(3.0)


def test_one_seed_records_zero_replications_and_two_seeds_the_ones_asked() -> None:
    one = _scores([("A", "h", 0, 0.2), ("B", "h", 0, 0.4)])
    boot = aggregate(one, reps=30, poi_reps=7)["bootstrap"]
    assert (boot["reps"], boot["poi_reps"]) == (0, 0)
    two = _scores([("A", "h", 0, 0.2), ("A", "h", 1, 0.3), ("B", "h", 0, 0.4), ("B", "h", 1, 0.1)])
    boot = aggregate(two, reps=30, poi_reps=7)["bootstrap"]
    assert (boot["reps"], boot["poi_reps"]) == (30, 7)


def test_the_generalisation_gap_needs_both_train_and_test_partners() -> None:
    frame = _scores([("A", "h", 0, 0.2), ("A", "h", 1, 0.3), ("A", "k", 0, 0.4), ("A", "k", 1, 0.1)])
    assert "generalisation" not in aggregate(frame, {"h": "train", "k": "validation"}, reps=10, poi_reps=5)
    assert "generalisation" in aggregate(frame, {"h": "train", "k": "test"}, reps=10, poi_reps=5)


# ---- training/report.py ------------------------------------------------------------------


def _study() -> Study:
    """The report tests' two-robot, two-human study, with h for training and k for testing."""
    return dataclasses.replace(report_study(), train=("h",), test=("k",))


def _frame(rows: list[tuple[str, str, float]]) -> pd.DataFrame:
    return pd.DataFrame(
        [
            {"robot": r, "human": h, "scenario": "paper2015", "seed": 0, "score": v}
            | {"oracle_rate": 100.0, "reference": "oracle"}
            for r, h, v in rows
        ]
    )


def _agg(improvement: dict[str, Any], flag: str = "") -> dict[str, Any]:
    return {
        "robots": {"A": {"iqm": 0.5, "iqm_ci": None, "mean": 0.5, "mean_ci": None, "runs": 2}},
        "improvement": improvement,
        "bootstrap": {"reps": 10, "poi_reps": 10, "seed": 0, "ci": 0.95, "seeds_per_task": 5, "flag": flag},
        "br_prox": [{"robot": "A", "scenario": "paper2015", "split": "all", "iqm": 1.0, "ci": None, "runs": 2}],
        "generalisation": {"A": {"train_iqm": 0.9, "test_iqm": 0.6, "gap": 0.3, "gap_ci": [0.2, 0.4]}},
    }


def test_the_generalisation_section_names_the_partners_and_each_robots_gap() -> None:
    text = markdown(_study(), _frame([("A", "h", 0.9), ("A", "k", 0.6)]), _agg({}), {"ran": 2, "reused": 0})
    lines = text.splitlines()
    at = lines.index("## Generalisation to held-out partners")
    assert lines[at + 2] == "Train partners: h. Test partners: k."
    assert lines[at + 6] == "| A | 0.90 | 0.60 | 0.30 | [0.20, 0.40] |"


def test_the_reports_sections_come_in_order_and_no_caution_without_a_flag() -> None:
    text = markdown(_study(), _frame([("A", "h", 0.9), ("A", "k", 0.6)]), _agg({}), {"ran": 2, "reused": 0})
    assert [line for line in text.splitlines() if line.startswith("## ")] == [
        "## Per robot",
        "## Mean score, robots x humans",
        "## BR-Prox (score against each partner's exact best response)",
        "## Generalisation to held-out partners",
        "## Probability of improvement",
    ]
    assert "Caution" not in text


def test_a_study_without_any_pair_reports_zero_of_zero_pairs() -> None:
    # no pair at all is not "every pair without an interval": the clear-pairs sentence, 0 of 0
    text = markdown(_study(), _frame([("A", "h", 0.9)]), _agg({}), {"ran": 1, "reused": 0})
    assert "0 of 0 pairs have a 95% CI that excludes 0.5 (all pairs in aggregate.json):" in text
    assert "No interval with" not in text


def test_a_robot_that_never_met_a_human_reads_na_in_the_crossplay_table() -> None:
    # B played h only: its k cell has no score at all
    frame = _frame([("A", "h", 0.5), ("A", "k", 0.25), ("B", "h", 0.75)])
    assert crossplay_table(frame).splitlines()[2:4] == ["| A | 0.50 | 0.25 |", "| B | 0.75 | n/a |"]


# ---- training/store.py -------------------------------------------------------------------


def test_a_seal_is_the_sha256_of_the_sorted_compact_json_without_the_seal() -> None:
    record = {"b": [1, 2], "a": "x"}
    body = json.dumps(record, sort_keys=True, separators=(",", ":"))
    sealed = seal(record)
    assert sealed == {**record, "sha256": hashlib.sha256(body.encode()).hexdigest()}
    assert seal(sealed) == sealed  # an old seal is not part of what is hashed


def _run_result(duration: float = 60.0) -> RunResult:
    log = pd.DataFrame({c: [] for c in COLUMNS})
    return RunResult(RunConfig(duration=duration), log, summarise(log, duration))


JOB = Job(robot="random", seed=0, scenario="paper2015", duration=40.0, human="random", label="gate")


def test_a_nan_in_an_entry_is_reported_as_non_finite_and_removed(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    store = Store(tmp_path)
    store.put(JOB, _run_result())
    path = store.entry(JOB.key()) / "result.json"
    record = json.loads(path.read_text())
    record["summary"]["actions"] = float("nan")
    path.write_text(json.dumps(record))  # Python writes the NaN as a bare NaN
    assert store.get(JOB) is None and path.exists()  # without the claim: skipped, kept
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        assert store.get(JOB, repair=True) is None
    assert ["non-finite (result.json holds a NaN)" in r.getMessage() for r in caplog.records] == [True]
    assert not store.entry(JOB.key()).exists()


def test_a_job_without_a_cost_is_keyed_by_the_default_cost_model_and_a_whole_duration_as_a_float() -> None:
    assert JOB.key_fields()["cost_model"] == json.loads(json.dumps(asdict(CostModel())))
    # duration 40 and 40.0 are one run
    same = Job(robot="random", seed=0, scenario="paper2015", duration=40, human="random")
    assert same.key() == JOB.key()


def test_a_cached_entry_without_a_value_is_reported_and_computed_again(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    store = Store(tmp_path)
    fields = {"human": "lazy"}
    key = content_key("oracle", fields)
    path = tmp_path / "cached" / "oracle" / f"{key}.json"
    path.parent.mkdir(parents=True)
    path.write_text(json.dumps(seal({"key": key, "kind": "oracle", "fields": fields})))  # sealed, but no value
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        assert store.cached("oracle", fields, lambda: 7.5) == 7.5
    assert ["incomplete (no 'value')" in r.getMessage() for r in caplog.records] == [True]
    assert json.loads(path.read_text())["value"] == 7.5


# ---- training/sweep.py -------------------------------------------------------------------


class Recording:
    """A backend whose runs finish at the next wait, each an empty run; it records what it was asked."""

    def __init__(self, capacity: int) -> None:
        self.capacity = capacity
        self.flight: dict[str, Job] = {}
        self.submitted: list[str] = []
        self.most = 0
        self.closed = False

    def submit(self, key: str, job: Job) -> None:
        self.flight[key] = job
        self.submitted.append(key)
        self.most = max(self.most, len(self.flight))

    def wait(self, timeout: float) -> list[tuple[str, Any]]:
        done = [(k, _run_result(j.duration)) for k, j in self.flight.items()]
        self.flight.clear()
        return done

    def close(self) -> None:
        self.closed = True


JOBS = [Job(robot="random", seed=s, duration=40.0, human="random", label="gate") for s in range(5)]


def test_load_log_names_the_run_it_cannot_find(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError, match=rf"^no finished run of gate seed 3 in {re.escape(str(tmp_path))}$"):
        load_log(JOBS[3], tmp_path)
    unlabelled = Job(robot="random", seed=4, duration=40.0, human="random")
    with pytest.raises(FileNotFoundError, match=r"^no finished run of random seed 4 "):  # no label: the robot
        load_log(unlabelled, tmp_path)


def test_jobs_sharing_a_key_are_run_once_and_counted_once(tmp_path: Path) -> None:
    backend = Recording(capacity=4)
    runs, stats = run_jobs([JOBS[0], JOBS[1], JOBS[0]], Store(tmp_path), backend)
    assert backend.submitted == [JOBS[0].key(), JOBS[1].key()]
    assert (stats.ran, stats.reused) == (2, 0)
    assert [r.key for r in runs] == [JOBS[0].key(), JOBS[1].key(), JOBS[0].key()]


def test_no_more_jobs_are_in_flight_than_the_backend_holds(tmp_path: Path) -> None:
    backend = Recording(capacity=2)
    runs, stats = run_jobs(JOBS, Store(tmp_path), backend)
    assert backend.most == 2 and len(backend.submitted) == 5 and stats.ran == 5
    assert [r.job["seed"] for r in runs] == [0, 1, 2, 3, 4]


def test_the_backend_is_closed_on_return_even_without_jobs(tmp_path: Path) -> None:
    backend = Recording(capacity=1)
    runs, stats = run_jobs([], Store(tmp_path), backend)
    assert runs == [] and (stats.ran, stats.reused) == (0, 0) and backend.closed
    backend = Recording(capacity=1)
    run_jobs(JOBS[:1], Store(tmp_path), backend)
    assert backend.closed


# ---- training/stalls.py ------------------------------------------------------------------


def _job(seed: int, human_params: dict[str, Any] | None = None, scenario: str = "paper") -> dict[str, Any]:
    return {
        "robot": "planner",
        "robot_params": {},
        "human": "picky",
        "human_params": human_params or {},
        "scenario": scenario,
        "duration": 600.0,
        "seed": seed,
    }


def test_a_stretch_of_exactly_stall_seconds_is_not_a_stall(tmp_path: Path) -> None:
    # one task at 300 s of a 600 s run: stretches 300 and 300, neither over 300
    _store_run(tmp_path, "aa01", _job(1), pd.DataFrame({"time": [10.0, 300.0], "tasks_solved": [0, 1]}))
    assert stall_report(tmp_path).splitlines()[2] == "| planner | 1 | 0 | 300 (picky, paper, seed 1) | 0.0 |"


def test_the_worst_run_on_a_tie_is_the_first_one_read(tmp_path: Path) -> None:
    # seeds 1 and 2 both go without a task for 400 s (tasks at 400 s, run of 600 s); runs are read
    # in folder order (aa01 before bb02), so seed 1 is named
    log = pd.DataFrame({"time": [10.0, 400.0], "tasks_solved": [0, 1]})
    _store_run(tmp_path, "bb02", _job(2), log)
    _store_run(tmp_path, "aa01", _job(1), log)
    assert stall_report(tmp_path).splitlines()[2] == "| planner | 2 | 2 | 400 (picky, paper, seed 1) | 0.0 |"


def test_a_log_without_reasons_has_no_guard_moves_and_an_empty_log_no_task(tmp_path: Path) -> None:
    _store_run(tmp_path, "aa01", _job(1), pd.DataFrame({"time": [10.0, 100.0], "tasks_solved": [0, 1]}))
    _store_run(tmp_path, "bb02", _job(2), pd.DataFrame({"time": [], "tasks_solved": []}))
    rows = runs_of(tmp_path)
    assert [(r["seed"], r["tasks"], r["gap"], r["guard_moves"]) for r in rows] == [(1, 1, 500.0, 0), (2, 0, 600.0, 0)]


def test_the_worst_partner_is_cut_to_40_characters_and_cells_are_solvable_per_scenario(tmp_path: Path) -> None:
    params = {"weights": "x" * 50}  # the partner reads "picky:weights=xxx...", 64 characters
    _store_run(tmp_path, "aa01", _job(1, params), pd.DataFrame({"time": [10.0, 100.0], "tasks_solved": [0, 1]}))
    # the same partner on another scenario where no robot solves a task: not a solvable cell, left out
    _store_run(tmp_path, "bb02", _job(2, params, "other"), pd.DataFrame({"time": [10.0], "tasks_solved": [0]}))
    lines = stall_report(tmp_path).splitlines()
    assert lines[2:] == [f"| planner | 1 | 1 | 500 (picky:weights={'x' * 26}, paper, seed 1) | 0.0 |"]
