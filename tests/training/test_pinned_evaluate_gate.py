"""A study's cells, references, score table and wiring, pinned for the mutation gate without running a robot.

Expected values are worked by hand from the module's docstrings on tables of a few
made-up rates: robots outermost and the oracle robot meeting only stationary humans; the
oracle's rate read from the store under a key naming the human, the scenario's content,
the state budget and the solve's budget, refused (None) for a human it cannot model or
over its budget; a score as rate over the reference, ``br_prox`` its value capped at 1
where the reference is the exact best response; the best robot's mean rate (the oracle's
rows left out) where there is no oracle; the headroom over the held-out stationary
partners. The store, the runs, the solves and the outputs are stand-ins.
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pandas as pd
import pytest

import hg_marl.training.evaluate as ev
from hg_marl.agents.oracle import OracleTooLarge
from hg_marl.training.backends import LocalBackend
from hg_marl.training.study import Actor, Study


def _study(robots: list[Actor], humans: list[Actor], **kw: Any) -> Study:
    base: dict[str, Any] = {"scenarios": ("paper2015",), "seeds": (0,), "duration": 360.0}
    base.update(kw)
    return Study("s", Path("s.toml"), tuple(robots), tuple(humans), **base)


@pytest.fixture(autouse=True)
def _no_code_digest(monkeypatch: pytest.MonkeyPatch) -> None:
    """The headroom key's code digest hashes every module it reaches (seconds); its roots are
    pinned by ``test_evaluate.py``'s key test, so here it is a stand-in."""
    from hg_marl.agents import content

    monkeypatch.setattr(content, "code_digest", lambda roots: "digest")


class _Store:
    """Answers ``cached`` from a table by kind (or computes it), recording every key asked."""

    def __init__(self, answers: dict[str, Any] | None = None) -> None:
        self.answers = answers or {}
        self.asked: list[tuple[str, dict[str, Any]]] = []

    def cached(self, kind: str, fields: dict[str, Any], compute: Any) -> Any:
        self.asked.append((kind, fields))
        return self.answers[kind] if kind in self.answers else compute()


def test_only_the_registrys_stationary_humans_are_stationary() -> None:
    assert ev.stationary(Actor("cooperative")) is True
    assert ev.stationary(Actor("switching")) is False
    assert ev.stationary(Actor("no_such_human")) is False


def test_cells_go_robot_human_scenario_seed_and_the_oracle_meets_only_stationary_humans() -> None:
    planner, oracle = Actor("planner", {"x": 1}, "P"), Actor("oracle", {}, "oracle")
    lazy, switching = Actor("lazy", {"p_idle": 0.5}, "L"), Actor("switching", {}, "S")
    study = _study([planner, oracle], [lazy, switching], scenarios=("paper2015", "roboergosum"), seeds=(3, 5))
    made = ev.cells(study)
    assert [(c.robot.label, c.human.label, c.scenario, c.seed) for c in made] == [
        ("P", h, sc, seed) for h in ("L", "S") for sc in ("paper2015", "roboergosum") for seed in (3, 5)
    ] + [("oracle", "L", sc, seed) for sc in ("paper2015", "roboergosum") for seed in (3, 5)]
    job = made[0].job
    assert (job.robot, dict(job.robot_params), job.human, dict(job.human_params)) == (
        "planner",
        {"x": 1},
        "lazy",
        {"p_idle": 0.5},
    )
    assert (job.scenario, job.seed, job.duration, job.label) == ("paper2015", 3, 360.0, "P with L")


def test_the_oracle_rate_of_a_stationary_human_is_read_under_a_key_of_everything_it_depends_on() -> None:
    from hg_marl.agents.content import scenario_content
    from hg_marl.agents.oracle import DEFAULT_MEMORY, DEFAULT_SECONDS

    store = _Store({"oracle": 7})
    assert ev.oracle_rate(store, Actor("lazy", {"p_idle": 0.5}), "paper2015", 123) == 7.0
    assert isinstance(ev.oracle_rate(store, Actor("lazy"), "paper2015", 1), float)
    (kind, fields), _ = store.asked
    assert kind == "oracle"
    assert fields == {
        "human": {"name": "lazy", "params": {"p_idle": 0.5}},
        "scenario": scenario_content("paper2015"),
        "max_states": 123,
        "budget": {"seconds": DEFAULT_SECONDS, "memory": DEFAULT_MEMORY},
    }


def test_a_human_the_oracle_cannot_model_has_no_oracle_rate_and_the_store_is_not_asked() -> None:
    store = _Store({"oracle": 7})
    assert ev.oracle_rate(store, Actor("switching"), "paper2015", 10) is None
    assert store.asked == []
    assert ev.oracle_rate(_Store({"oracle": None}), Actor("lazy"), "paper2015", 10) is None


def test_the_oracle_rate_is_solved_with_the_humans_spec_and_an_over_budget_solve_is_none(
    monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    import hg_marl.agents.oracle as oracle

    seen: list[tuple[Any, ...]] = []

    def solve(scenario: str, human: str, max_states: int, progress: bool) -> Any:
        seen.append((scenario, human, max_states, progress))
        return SimpleNamespace(rate_per_hour=12)

    monkeypatch.setattr(oracle, "oracle_rate", solve)
    assert ev.oracle_rate(_Store(), Actor("lazy", {"p_idle": 0.5}), "roboergosum", 99, progress=True) == 12.0
    assert seen == [("roboergosum", "lazy:p_idle=0.5", 99, True)]

    def too_large(*args: Any, **kw: Any) -> Any:
        raise OracleTooLarge("over")

    monkeypatch.setattr(oracle, "oracle_rate", too_large)
    with caplog.at_level(logging.WARNING, logger=ev.log.name):
        assert ev.oracle_rate(_Store(), Actor("lazy"), "paper2015", 5) is None
    assert "over its budget" in caplog.text


def _runs(rates: dict[tuple[str, str], list[float]], plan: list[ev.Cell]) -> list[Any]:
    """One stand-in run per cell; tasks = rate / 10 (a 360 s run)."""
    it = {k: iter(v) for k, v in rates.items()}
    out = []
    for i, c in enumerate(plan):
        rate = next(it[(c.robot.label, c.human.label)])
        out.append(SimpleNamespace(tasks=int(rate / 10), rate=rate, key=f"k{i}"))
    return out


def test_the_score_table_divides_by_each_references_rate_and_says_which(monkeypatch: pytest.MonkeyPatch) -> None:
    """Four humans, two seeds, robots planner and oracle (stationary humans only):

    - cooperative: oracle rate 40, planner 20 and 60: scores 0.5 and 1.5, br_prox 0.5 and 1 (capped);
    - lazy: oracle 0 (no robot can solve a task): no score, said so;
    - noisy: no oracle rate; best robot mean: planner (10+30)/2 = 20, the oracle's 100s not counted;
    - adversarial: no oracle rate and every robot at 0: no reference.
    """
    planner, oracle = Actor("planner", {}, "planner"), Actor("oracle", {}, "oracle")
    humans = [Actor(h, {}, h) for h in ("cooperative", "lazy", "noisy", "adversarial")]
    study = _study([planner, oracle], humans, seeds=(0, 1))
    given = {"cooperative": 40.0, "lazy": 0.0, "noisy": None, "adversarial": None}
    monkeypatch.setattr(ev, "oracle_rate", lambda store, human, scenario, budget, progress: given[human.name])
    plan = ev.cells(study)
    rates = {("planner", "cooperative"): [20.0, 60.0], ("planner", "lazy"): [10.0, 10.0]}
    rates |= {("planner", "noisy"): [10.0, 30.0], ("planner", "adversarial"): [0.0, 0.0]}
    rates |= {("oracle", h.label): [100.0, 100.0] for h in humans}
    frame = ev.score_table(study, plan, _runs(rates, plan), store=None)
    assert tuple(frame.columns) == ev.SCORE_COLUMNS
    planner_rows = frame[frame["robot"] == "planner"].set_index(["human", "seed"])
    coop = planner_rows.loc["cooperative"]
    assert coop["score"].tolist() == [0.5, 1.5] and coop["br_prox"].tolist() == [0.5, 1.0]
    assert set(coop["reference"]) == {"oracle"} and set(coop["oracle_rate"]) == {40.0}
    lazy = planner_rows.loc["lazy"]
    assert set(lazy["reference"]) == {"oracle: 0 tasks/h, no score"} and lazy["score"].isna().all()
    noisy = planner_rows.loc["noisy"]
    assert set(noisy["reference"]) == {"best robot (planner)"} and set(noisy["oracle_rate"]) == {20.0}
    assert noisy["score"].tolist() == [0.5, 1.5] and noisy["br_prox"].isna().all()
    adv = planner_rows.loc["adversarial"]
    assert set(adv["reference"]) == {"none (no robot solved a task)"} and adv["score"].isna().all()
    assert frame["key"].tolist() == [f"k{i}" for i in range(len(plan))]
    assert frame["tasks"].tolist()[:2] == [2, 6]


def test_an_oracle_rate_below_one_task_an_hour_is_still_the_reference(monkeypatch: pytest.MonkeyPatch) -> None:
    """Any positive oracle rate is a reference (only 0 means "no score"): 0.5 tasks/h, a planner at
    0.25 and 1.0 tasks/h scores 0.5 and 2.0, br_prox 0.5 and 1 (capped)."""
    planner, lazy = Actor("planner", {}, "planner"), Actor("lazy", {}, "lazy")
    study = _study([planner], [lazy], seeds=(0, 1))
    monkeypatch.setattr(ev, "oracle_rate", lambda *a: 0.5)
    plan = ev.cells(study)
    runs = [SimpleNamespace(tasks=0, rate=r, key="k") for r in (0.25, 1.0)]
    frame = ev.score_table(study, plan, runs, store=None)
    assert set(frame["reference"]) == {"oracle"} and set(frame["oracle_rate"]) == {0.5}
    assert frame["score"].tolist() == [0.5, 2.0] and frame["br_prox"].tolist() == [0.5, 1.0]


def test_cells_and_references_cannot_be_changed_once_made() -> None:
    """A cell's labels and job and a reference's rate are what the score table was computed from:
    both are frozen records."""
    import dataclasses

    (cell,) = ev.cells(_study([Actor("planner", {}, "planner")], [Actor("lazy", {}, "lazy")]))
    with pytest.raises(dataclasses.FrozenInstanceError):
        cell.seed = 1
    reference = ev.Reference(2.0, "oracle")
    with pytest.raises(dataclasses.FrozenInstanceError):
        reference.rate = 3.0


def test_the_best_robot_is_the_one_with_the_best_mean_in_its_own_human_and_scenario(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Two scenarios, no oracle rate: on paper2015 the habit's mean 30 beats the planner's 20; on
    roboergosum the planner's 50 beats the habit's 5 (each reference from its own rows only)."""
    planner, habit = Actor("planner", {}, "planner"), Actor("habit", {}, "habit")
    human = Actor("switching", {}, "switching")
    study = _study([planner, habit], [human], scenarios=("paper2015", "roboergosum"))
    monkeypatch.setattr(ev, "oracle_rate", lambda *a: None)
    plan = ev.cells(study)
    by_cell = {("planner", "paper2015"): 20.0, ("planner", "roboergosum"): 50.0}
    by_cell |= {("habit", "paper2015"): 30.0, ("habit", "roboergosum"): 5.0}
    runs = [SimpleNamespace(tasks=1, rate=by_cell[(c.robot.label, c.scenario)], key="k") for c in plan]
    frame = ev.score_table(study, plan, runs, store=None)
    refs = dict(zip(frame["scenario"], frame["reference"], strict=True))
    assert refs == {"paper2015": "best robot (habit)", "roboergosum": "best robot (planner)"}
    assert frame.set_index(["robot", "scenario"])["oracle_rate"].to_dict() == {
        ("planner", "paper2015"): 30.0,
        ("planner", "roboergosum"): 50.0,
        ("habit", "paper2015"): 30.0,
        ("habit", "roboergosum"): 50.0,
    }


def test_the_headroom_is_over_the_held_out_stationary_partners_or_every_stationary_one() -> None:
    """Train cooperative, test lazy and switching: the key names lazy alone (switching cannot be
    modelled); with no test group every stationary partner; with none stationary, no headroom."""
    from hg_marl.agents.content import scenario_content

    humans = [Actor("cooperative", {}, "c"), Actor("lazy", {"p_idle": 0.5}, "l"), Actor("switching", {}, "s")]
    store = _Store({"headroom": 0.25})
    held = _study([Actor("planner")], humans, train=("c",), test=("l", "s"), oracle_max_states=77)
    assert ev.headroom_of(store, held, "paper2015") == 0.25
    kind, fields = store.asked[-1]
    assert kind == "headroom"
    assert fields["humans"] == [{"label": "l", "name": "lazy", "params": {"p_idle": 0.5}}]
    assert fields["scenario"] == scenario_content("paper2015") and fields["max_states"] == 77
    assert fields["code"] == "digest"
    no_groups = _study([Actor("planner")], humans)
    ev.headroom_of(store, no_groups, "paper2015")
    assert [h["label"] for h in store.asked[-1][1]["humans"]] == ["c", "l"]
    only_switching = _study([Actor("planner")], [humans[2]])
    assert ev.headroom_of(store, only_switching, "paper2015") is None
    assert len(store.asked) == 2
    assert ev.headroom_of(_Store({"headroom": None}), held, "paper2015") is None


def test_the_headroom_is_computed_on_the_test_partners_specs_and_nan_or_over_budget_is_none(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import hg_marl.agents.headroom as module

    seen: list[Any] = []
    value: dict[str, float | None] = {"v": 0.125}

    def headroom(scenario: str, partners: list[tuple[str, str]], max_states: int, progress: bool) -> Any:
        seen.append((scenario, partners, max_states, progress))
        if value["v"] is None:
            raise OracleTooLarge("over")
        return SimpleNamespace(headroom=value["v"])

    monkeypatch.setattr(module, "headroom", headroom)
    study = _study([Actor("planner")], [Actor("lazy", {"p_idle": 0.5}, "l")], oracle_max_states=9)
    assert ev.headroom_of(_Store(), study, "roboergosum", progress=True) == 0.125
    assert seen == [("roboergosum", [("l", "lazy:p_idle=0.5")], 9, True)]
    value["v"] = math.nan
    assert ev.headroom_of(_Store(), study, "roboergosum") is None
    value["v"] = None
    assert ev.headroom_of(_Store(), study, "roboergosum") is None


def test_evaluate_runs_every_cell_in_the_store_of_out_and_writes_the_outputs(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """The cells' jobs in order go to the store under ``out`` on one local worker by default; the
    outputs get the score table, the counts ran/reused and one headroom per scenario."""
    import hg_marl.training.report as report
    import hg_marl.training.sweep as sweep

    called: dict[str, Any] = {}
    study = _study([Actor("planner", {}, "planner")], [Actor("lazy", {}, "lazy")], scenarios=("paper2015", "x"))

    def run_jobs(jobs: list[Any], store: Any, backend: Any, on_done: Any) -> Any:
        called["run"] = (jobs, store, backend, on_done)
        return [SimpleNamespace(tasks=1, rate=10.0, key=f"k{i}") for i in range(len(jobs))], SimpleNamespace(
            ran=3, reused=4
        )

    def write_outputs(study_: Study, frame: pd.DataFrame, out: Path, stats: dict[str, int], headrooms: Any) -> Any:
        called["write"] = (study_, frame, out, stats, headrooms)
        return {"done": True}

    monkeypatch.setattr(sweep, "store_of", lambda out: ("store of", out))
    monkeypatch.setattr(sweep, "run_jobs", run_jobs)
    monkeypatch.setattr(report, "write_outputs", write_outputs)
    monkeypatch.setattr(ev, "oracle_rate", lambda *a: 20.0)
    monkeypatch.setattr(ev, "headroom_of", lambda store, study_, scenario, progress: f"{scenario} {progress}")
    done = lambda job, run: None  # noqa: E731
    assert ev.evaluate(study, str(tmp_path), on_done=done, progress=True) == {"done": True}
    jobs, store, backend, on_done = called["run"]
    assert [(j.robot, j.scenario) for j in jobs] == [("planner", "paper2015"), ("planner", "x")]
    assert store == ("store of", tmp_path) and on_done is done
    assert isinstance(backend, LocalBackend) and backend.capacity == 1
    _, frame, out, stats, headrooms = called["write"]
    assert out == tmp_path and stats == {"ran": 3, "reused": 4}
    assert headrooms == {"paper2015": "paper2015 True", "x": "x True"}
    assert frame["score"].tolist() == [0.5, 0.5]
    mine = object()
    ev.evaluate(study, tmp_path, backend=mine)
    assert called["run"][2] is mine and called["write"][4] == {"paper2015": "paper2015 False", "x": "x False"}
