"""The reproduce driver's wiring, pinned for the mutation gate without running a single simulation.

The runs, the store, the figures and the adaptation experiment are stand-ins recording
what they are handed (the real ones are covered by ``test_reproduce.py``'s smoke runs,
which take tens of seconds). Expected values follow from the module's docstrings: one job
per (condition, seed) in ``paper.jobs``'s order, grouped by label in the summary; every
stage reports its own total to the progress factory (the runs, the three figures, the
adaptation runs, its figures: one per switch and the regret figure); ``summary.json``
holds what is returned; the adaptation gets the config's scenario, its own seeds and the
workers.
"""

from __future__ import annotations

import functools
import json
from pathlib import Path
from typing import Any

import pandas as pd
import pytest

import hg_marl.training.adaptation as adaptation
import hg_marl.training.reproduce as reproduce_module
from hg_marl.training import plots
from hg_marl.training.backends import LocalBackend
from hg_marl.training.reproduce import ReproduceConfig, reproduce

PAPER_LABELS = ["planner", "habit", "random"]


class _Run:
    """A stored run's stand-in: its key names its job; the planner solves ``seed + 1`` tasks."""

    def __init__(self, job: Any) -> None:
        self.key = f"{job.label}-{job.seed}"
        tasks = job.seed + 1 if job.label == "planner" else 0
        self._log = pd.DataFrame(
            {
                "time": [1.0] * (tasks + 1),
                "reward": [1.0] * tasks + [0.0],
                "failed": False,
                "expert": "planner" if job.label == "planner" else "habit",
                "weight_amplitude": 0.0,
            }
        )

    def log(self) -> pd.DataFrame:
        return self._log


class _Recorder:
    """Stands in for the store, the runs, the figures and the adaptation; keeps every call."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch) -> None:
        self.calls: dict[str, Any] = {}
        self.stages: list[tuple[str, int]] = []
        self.ticks: dict[str, list[Any]] = {}
        monkeypatch.setattr(reproduce_module, "store_of", self.store_of)
        monkeypatch.setattr(reproduce_module, "run_jobs", self.run_jobs)
        for name, stem in (
            ("cumulative_reward", "fig3_cumulative_reward"),
            ("actions_per_run", "fig4_actions_per_run"),
            ("weight_amplitude", "fig5_weight_amplitude"),
        ):
            monkeypatch.setattr(plots, name, self._figure(name, stem))
        monkeypatch.setattr(adaptation, "adaptation_jobs", lambda config: [None] * 5)
        monkeypatch.setattr(adaptation, "run_adaptation", self.run_adaptation)

    def store_of(self, out: Path) -> str:
        self.calls["store_of"] = out
        return "the store"

    def run_jobs(self, jobs: list[Any], store: Any, backend: Any, on_done: Any) -> tuple[list[_Run], None]:
        self.calls["run_jobs"] = (list(jobs), store, backend)
        runs = [_Run(job) for job in jobs]
        for job, run in zip(jobs, runs, strict=True):
            if on_done:
                on_done(job, run)
        return runs, None

    def _figure(self, name: str, stem: str) -> Any:
        def draw(*args: Any) -> Path:
            self.calls[name] = args
            return Path(args[-1]).with_name(stem + ".png")

        return draw

    def run_adaptation(self, out: Path, config: Any, workers: int, on_done: Any, on_figure: Any) -> Any:
        self.calls["adaptation"] = (out, config, workers, on_done, on_figure)
        return {"measured": 1}, {"adaptation_short": out / "short.png"}

    def progress(self, stage: str, total: int) -> Any:
        self.stages.append((stage, total))
        ticks = self.ticks.setdefault(stage, [])
        return lambda item, value: ticks.append((item, value))


def test_the_documented_defaults() -> None:
    config = ReproduceConfig()
    assert config.out == Path("results/paper2015")
    assert (config.seeds, config.duration, config.scenario) == (10, 1100.0, "paper2015")
    assert (config.paper_only, config.adaptation, config.adaptation_seeds, config.workers) == (False, True, 3, 1)


def test_the_paper_only_experiment_groups_runs_by_condition_and_writes_what_it_returns(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Three conditions x two seeds: six runs in the store of ``out``, run on one local worker;
    the planner solves 1 and 2 tasks (mean 1.5), the others none; keys listed per condition in
    seed order; three figures under ``out``; no adaptation."""
    rec = _Recorder(monkeypatch)
    out = tmp_path / "paper"
    config = ReproduceConfig(out=out, seeds=2, duration=60.0, scenario="roboergosum", paper_only=True, adaptation=False)
    summary = reproduce(config, progress=rec.progress)

    jobs, store, backend = rec.calls["run_jobs"]
    assert rec.calls["store_of"] == out and store == "the store"
    assert isinstance(backend, LocalBackend) and backend.capacity == 1
    assert [(j.label, j.seed, j.scenario, j.duration) for j in jobs] == [
        (label, seed, "roboergosum", 60.0) for label in PAPER_LABELS for seed in (0, 1)
    ]
    assert (summary["scenario"], summary["duration"], summary["seeds"]) == ("roboergosum", 60.0, 2)
    assert list(summary["conditions"]) == PAPER_LABELS
    assert summary["conditions"]["planner"]["tasks_solved"] == [1.0, 2.0]
    assert summary["conditions"]["habit"]["seeds"] == 2
    assert summary["paper"] == {"planner": 34.0, "random": 25.0, "habit": 3.0}
    assert summary["targets"]["planner > random mix >> habit"]["planner"] == 1.5
    assert summary["runs"] == {label: [f"{label}-0", f"{label}-1"] for label in PAPER_LABELS}
    assert "adaptation" not in summary and "adaptation" not in rec.calls

    figures = {
        "fig3": out / "fig3_cumulative_reward.png",
        "fig4": out / "fig4_actions_per_run.png",
        "fig5": out / "fig5_weight_amplitude.png",
    }
    assert summary["figures"] == {k: str(v) for k, v in figures.items()}
    logs, duration, path = rec.calls["cumulative_reward"]
    assert duration == 60.0 and path == figures["fig3"]
    assert list(logs) == PAPER_LABELS and len(logs["planner"]) == 2
    assert rec.calls["actions_per_run"][1] == figures["fig4"]
    assert rec.calls["weight_amplitude"][1] == figures["fig5"]

    assert rec.stages == [("paper experiment", 6), ("paper figures", 3)]
    assert [job.label for job, _ in rec.ticks["paper experiment"]] == [label for label in PAPER_LABELS for _ in (0, 1)]
    assert rec.ticks["paper figures"] == [(None, figures[k]) for k in ("fig3", "fig4", "fig5")]
    assert json.loads((out / "summary.json").read_text()) == json.loads(json.dumps(summary))


def test_the_full_experiment_adds_every_criterion_and_the_adaptation_with_its_own_seeds(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Seven conditions x one seed; the adaptation runs on the config's scenario with
    ``adaptation_seeds`` seeds and the config's workers; its stage counts its jobs (5, the
    stand-in's) and its figures one per switch plus the regret figure; its summary and figures
    join the paper's. The backend handed in is the one used."""
    rec = _Recorder(monkeypatch)
    out = tmp_path / "full"
    backend = object()
    config = ReproduceConfig(out=out, seeds=1, duration=30.0, scenario="paper2015", adaptation_seeds=4, workers=2)
    summary = reproduce(config, backend=backend, progress=rec.progress)

    jobs, _, used = rec.calls["run_jobs"]
    assert used is backend
    assert [j.label for j in jobs] == [*PAPER_LABELS, "entropy", "entropy_and_cost", "vpi", "learning_state"]
    where, adapt, workers, on_done, on_figure = rec.calls["adaptation"]
    assert where == out and workers == 2
    assert (adapt.scenario, adapt.seeds) == ("paper2015", 4)
    switches = len(adapt.switches)
    assert rec.stages == [
        ("paper experiment", 7),
        ("paper figures", 3),
        ("adaptation", 5),
        ("adaptation figures", switches + 1),
    ]
    on_done("job", "result")
    on_figure(None, "figure")
    assert rec.ticks["adaptation"] == [("job", "result")] and rec.ticks["adaptation figures"] == [(None, "figure")]
    assert summary["adaptation"] == {"measured": 1}
    assert summary["figures"]["adaptation_short"] == str(out / "short.png")
    assert set(summary["figures"]) == {"fig3", "fig4", "fig5", "adaptation_short"}
    assert json.loads((out / "summary.json").read_text())["adaptation"] == {"measured": 1}


def test_the_adaptation_figures_stage_counts_one_figure_per_switch_and_the_regret_figure(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """With one switch and with three (the experiment's own defaults replaced): 1 + 1 and 3 + 1 figures."""
    real = adaptation.AdaptationConfig
    first = next(iter(adaptation.SWITCHES))
    for switches in ((first,), (first, first, first)):
        rec = _Recorder(monkeypatch)
        monkeypatch.setattr(adaptation, "AdaptationConfig", functools.partial(real, switches=switches))
        reproduce(ReproduceConfig(out=tmp_path, seeds=1, paper_only=True), progress=rec.progress)
        assert rec.stages[-1] == ("adaptation figures", len(switches) + 1)


def test_without_a_progress_factory_nothing_is_reported_and_the_run_completes(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """``progress=None``: the runs and the adaptation get no callbacks (library code prints nothing)."""
    rec = _Recorder(monkeypatch)
    config = ReproduceConfig(out=tmp_path, seeds=1, paper_only=True)
    summary = reproduce(config)
    _, _, _, on_done, on_figure = rec.calls["adaptation"]
    assert on_done is None and on_figure is None
    assert list(summary["conditions"]) == PAPER_LABELS and rec.stages == []
