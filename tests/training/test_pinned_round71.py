"""The values round 71's missed planted bugs changed (``mutation/planted.py``, FRESH71), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents import views
from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal
from hg_marl.agents.meta.fixed import HabitOnly, PlannerOnly
from hg_marl.agents.model_format import read_header
from hg_marl.core import World
from hg_marl.core.errors import ModelFileError
from hg_marl.training.backends import LocalBackend
from hg_marl.training.baselines import recipes
from hg_marl.training.store import Job
from hg_marl.training.sweep import run_sweep


def test_the_habit_alone_criterion_chooses_the_habit_even_when_asked_with_a_plan() -> None:
    # fixed.py: HabitOnly is "Always the habit" and its choose says "The habit, always";
    # PlannerOnly's says "The planner, always". The controller never asks HabitOnly to choose
    # (it wants no plan), but the criterion's own answer is public: asked directly with a
    # successful plan that proposes another action, each names its own expert.
    habit = HabitView(
        key=b"s",
        probs=np.full(3, 1 / 3),
        action=0,
        q=np.zeros(3),
        sd=np.ones(3),
        weight_amplitude=0.0,
        cost=0.01,
    )
    plan = PlanProposal.make(2, 3, cost=1.0)
    assert HabitOnly().choose(habit, plan) is Expert.HABIT
    assert PlannerOnly().choose(habit, plan) is Expert.PLANNER
    assert HabitOnly().wants_plan(habit) is False


def _header(tmp_path: Path, **fields: Any) -> Path:
    header = {
        "format": "hg_marl.model",
        "kind": "sb3",
        "seat": "robot",
        "fact_names": ["a"],
        "action_names": ["wait"],
        "file": "model.npz",
        **fields,
    }
    path = tmp_path / "model.json"
    path.write_text(json.dumps(header))
    return path


def test_an_sb3_header_needs_both_its_algorithm_and_its_observation_kind(tmp_path: Path) -> None:
    # read_header's rule for kind "sb3": "fields 'algo' and 'observation' (facts, flat, dict)
    # are required", each on its own: a header with the algorithm and no observation kind is
    # refused, as is one with the observation kind and no algorithm; with both it is read.
    with pytest.raises(ModelFileError, match="fields 'algo' and 'observation'"):
        read_header(_header(tmp_path, algo="PPO"))
    with pytest.raises(ModelFileError, match="fields 'algo' and 'observation'"):
        read_header(_header(tmp_path, algo="PPO", observation="pixels"))
    with pytest.raises(ModelFileError, match="fields 'algo' and 'observation'"):
        read_header(_header(tmp_path, observation="facts"))
    assert read_header(_header(tmp_path, algo="PPO", observation="facts"))["algo"] == "PPO"


def test_the_hsp_pool_is_the_members_and_the_drawn_partners(monkeypatch: pytest.MonkeyPatch) -> None:
    # recipes' docstring: hsp's pool is "the members plus HSP_PARTNERS preference humans",
    # "each table drawing one of the union". With the drawn partners replaced by two known
    # specs and the compiler replaced by a recorder, the humans compiled are the member first,
    # then the two drawn ones: three in all.
    asked: list[Any] = []

    def record(world: World, humans: Any, cache: Any, progress: bool = False) -> str:
        asked.append(humans)
        return "members"

    monkeypatch.setattr(views, "compiled_humans", record)
    monkeypatch.setattr(recipes, "hsp_partners", lambda world: ("lazy", "noisy"))
    out = recipes.recipe_partner(World("paper2015"), ("cooperative",), "hsp", None)
    assert out == "members"
    assert asked == [["cooperative", "lazy", "noisy"]]


class _Recording(LocalBackend):
    """The in-process backend, noting the keys it is given and whether it was closed."""

    def __init__(self) -> None:
        super().__init__(1)
        self.keys: list[str] = []
        self.closed = False

    def submit(self, key: str, job: Job) -> None:
        self.keys.append(key)
        super().submit(key, job)

    def close(self) -> None:
        self.closed = True
        super().close()


def test_run_sweep_runs_its_jobs_on_the_backend_it_is_given(tmp_path: Path) -> None:
    # run_sweep's docstring: "backend: executor (default: LocalBackend with workers)", and
    # run_jobs closes the executor on return. A given backend gets the one new job (its key)
    # and is closed; a second sweep on the same folder reuses the run and submits nothing.
    job = Job(robot="random", seed=0, duration=10.0, human="random")
    backend = _Recording()
    (summary,) = run_sweep([job], tmp_path, backend=backend)
    assert backend.keys == [job.key()]
    assert backend.closed
    assert summary["key"] == job.key()
    again = _Recording()
    run_sweep([job], tmp_path, backend=again)
    assert again.keys == [] and again.closed
