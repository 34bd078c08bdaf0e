"""Run a study: every robot with every human on every scenario and seed, scored against the oracle.

:func:`evaluate` is what ``hg-marl evaluate STUDY.toml --out DIR`` calls. Each cell is a
:class:`~hg_marl.training.store.Job` of the store in ``DIR/store`` (so an interrupted
study resumes without repeating finished cells, and a changed setting never reuses an
old one), run on the chosen backend. A cell's **score** is its tasks per simulated hour
divided by the *reference rate* of its (human, scenario): the oracle's optimal rate
(value iteration on the exact model, cached in the store) when the human is stationary
and the model fits ``oracle_max_states``; otherwise the best robot's mean rate in this
study, and every table says which. Outputs in DIR (see :func:`write_outputs`):
``scores.csv``, ``aggregate.json``, ``crossplay.png``, ``profiles.png``,
``intervals.png`` and ``report.md``.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from hg_marl.agents.content import scenario_content
from hg_marl.training.backends import Backend, LocalBackend
from hg_marl.training.store import Job, Store, StoredRun
from hg_marl.training.study import ORACLE, Actor, Study

log = logging.getLogger(__name__)

SCORE_COLUMNS = (
    "robot",
    "human",
    "scenario",
    "seed",
    "tasks",
    "rate",
    "oracle_rate",
    "score",
    "br_prox",
    "key",
    "reference",
)
"""Columns of ``scores.csv``: one row per run; ``reference`` says what ``oracle_rate`` is.
``br_prox`` is ``min(1, rate / oracle rate)`` when the reference is the exact best
response (the oracle against that very partner), empty otherwise."""


@dataclass(frozen=True)
class Cell:
    """One run of a study, with the labels it is reported under."""

    robot: Actor
    human: Actor
    scenario: str
    seed: int
    job: Job


@dataclass(frozen=True)
class Reference:
    """The rate a (human, scenario)'s scores are divided by."""

    rate: float | None
    """Tasks per simulated hour (None: no reference, scores are missing)."""
    source: str
    """``oracle`` or ``best robot (<label>)``, or why there is none."""


def stationary(human: Actor) -> bool:
    """Whether the oracle can model this human (a fixed action distribution per state)."""
    from hg_marl.agents.humans import available_humans

    return bool(available_humans().get(human.name, {}).get("stationary", False))


def cells(study: Study) -> list[Cell]:
    """Every run of the study, robots outermost (the oracle robot only meets stationary humans)."""
    out = []
    for robot in study.robots:
        for human in study.humans:
            if robot.name == ORACLE and not stationary(human):
                continue
            for scenario in study.scenarios:
                for seed in study.seeds:
                    job = Job(
                        robot=robot.name,
                        robot_params=dict(robot.params),
                        human=human.name,
                        human_params=dict(human.params),
                        scenario=scenario,
                        duration=study.duration,
                        seed=seed,
                        label=f"{robot.label} with {human.label}",
                    )
                    out.append(Cell(robot, human, scenario, seed, job))
    return out


def oracle_rate(store: Store, human: Actor, scenario: str, max_states: int, progress: bool = False) -> float | None:
    """The oracle's tasks per hour for (human, scenario), cached in the store (None: not computable).

    ``progress`` shows the solve's bar on stderr (a first solve can take tens of seconds).
    """
    if not stationary(human):
        return None
    from hg_marl.agents.oracle import DEFAULT_MEMORY, DEFAULT_SECONDS

    fields = {
        "human": {"name": human.name, "params": dict(human.params)},
        "scenario": scenario_content(scenario),
        "max_states": max_states,
        # the budget decides whether a refusal (None) is stored: a changed budget recomputes
        "budget": {"seconds": DEFAULT_SECONDS, "memory": DEFAULT_MEMORY},
    }

    def compute() -> float | None:
        from hg_marl.agents.oracle import OracleTooLarge
        from hg_marl.agents.oracle import oracle_rate as solve

        try:
            return float(solve(scenario, human.spec(), max_states=max_states, progress=progress).rate_per_hour)
        except OracleTooLarge as exc:
            log.warning("oracle for %s on %s is over its budget (%s); using the best robot", human.label, scenario, exc)
            return None

    value = store.cached("oracle", fields, compute)
    return None if value is None else float(value)


def _rate(run: StoredRun) -> float:
    return run.rate


def score_table(
    study: Study, plan: list[Cell], runs: list[StoredRun], store: Store, progress: bool = False
) -> pd.DataFrame:
    """``scores.csv``'s rows, in the study's order, and the references used."""
    rows = [
        {
            "robot": c.robot.label,
            "human": c.human.label,
            "scenario": c.scenario,
            "seed": c.seed,
            "tasks": r.tasks,
            "rate": _rate(r),
            "key": r.key,
        }
        for c, r in zip(plan, runs, strict=True)
    ]
    frame = pd.DataFrame(rows)
    refs: dict[tuple[str, str], Reference] = {}
    for human in study.humans:
        for scenario in study.scenarios:
            rate = oracle_rate(store, human, scenario, study.oracle_max_states, progress)
            if rate is not None and rate > 0:
                refs[(human.label, scenario)] = Reference(rate, "oracle")
                continue
            if rate == 0:  # the oracle proves that no robot can solve a task with this human
                refs[(human.label, scenario)] = Reference(None, "oracle: 0 tasks/h, no score")
                continue
            mine = frame[(frame["human"] == human.label) & (frame["scenario"] == scenario)]
            means = mine[mine["robot"] != ORACLE].groupby("robot", sort=False)["rate"].mean()
            if len(means) and means.max() > 0:
                refs[(human.label, scenario)] = Reference(float(means.max()), f"best robot ({means.idxmax()})")
            else:
                refs[(human.label, scenario)] = Reference(None, "none (no robot solved a task)")
    frame["oracle_rate"] = [refs[(h, s)].rate for h, s in zip(frame["human"], frame["scenario"], strict=True)]
    frame["reference"] = [refs[(h, s)].source for h, s in zip(frame["human"], frame["scenario"], strict=True)]
    frame["score"] = frame["rate"] / frame["oracle_rate"]
    exact = frame["reference"] == "oracle"
    frame["br_prox"] = frame["score"].clip(upper=1.0).where(exact)
    return frame[list(SCORE_COLUMNS)]


def headroom_of(store: Store, study: Study, scenario: str, progress: bool = False) -> float | None:
    """The scenario's adaptation headroom over the study's held-out partners (cached; None: not computable).

    The partners are the study's stationary test partners (every stationary partner when
    the study has no test group); see :mod:`hg_marl.agents.headroom`. ``progress`` shows
    the model's bars on stderr (on a large table the joint model takes minutes).
    """
    from hg_marl.agents import content
    from hg_marl.agents import headroom as module
    from hg_marl.agents.humans.registry import HUMANS

    pool = [h for h in study.humans if stationary(h)]
    test = [h for h in pool if study.group(h.label) == "test"] or pool
    if not test:
        return None
    # the code of the headroom, the models it builds and every partner's module (the store's
    # own roots, the runner's, do not reach the headroom)
    code = content.code_digest((module.__name__, *content.registry_targets(HUMANS)))
    fields = {
        "humans": [{"label": h.label, "name": h.name, "params": dict(h.params)} for h in test],
        "scenario": scenario_content(scenario),
        "max_states": study.oracle_max_states,
        "code": code,
    }

    def compute() -> float | None:
        from hg_marl.agents.oracle import OracleTooLarge

        try:
            value = module.headroom(
                scenario, [(h.label, h.spec()) for h in test], max_states=study.oracle_max_states, progress=progress
            ).headroom
        except OracleTooLarge as exc:
            log.warning("headroom of %s is over its budget (%s)", scenario, exc)
            return None
        return None if value != value else float(value)

    value = store.cached("headroom", fields, compute)
    return None if value is None else float(value)


def evaluate(
    study: Study,
    out: str | Path,
    backend: Backend | None = None,
    on_done: Callable[[Job, StoredRun], None] | None = None,
    progress: bool = False,
) -> dict[str, Any]:
    """Run (or resume) ``study`` into ``out``; write every output; return the aggregates.

    Args:
        study: a validated (possibly narrowed) study.
        out: output folder; its ``store`` keeps the runs.
        backend: executor (default: in this process).
        on_done: called per cell as it is found or finished (progress bars).
        progress: show the bar of each oracle solve and of the headroom's model not yet in the store (stderr).
    """
    from hg_marl.training.report import write_outputs
    from hg_marl.training.sweep import run_jobs, store_of

    out = Path(out)
    store = store_of(out)
    plan = cells(study)
    runs, stats = run_jobs([c.job for c in plan], store, backend or LocalBackend(1), on_done)
    frame = score_table(study, plan, runs, store, progress)
    headrooms = {scenario: headroom_of(store, study, scenario, progress) for scenario in study.scenarios}
    return write_outputs(study, frame, out, {"ran": stats.ran, "reused": stats.reused}, headrooms)
