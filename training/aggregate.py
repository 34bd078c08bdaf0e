"""Study aggregates with rliable (Agarwal et al. 2021): IQM, mean, probability of improvement.

rliable's unit is a *task*; here a task is one (human, scenario) pair and a *run* is one
seed, so each robot's scores form a (seeds x tasks) matrix and rliable's stratified
bootstrap resamples seeds within every (human, scenario) (95% percentile intervals,
``reps`` replications from a fixed ``RandomState``, so ``aggregate.json`` is
reproducible). Computed per robot: IQM and mean with intervals; per pair of robots, the
probability that one improves on the other (on the tasks both played); and, for
held-out studies, the generalisation gap (IQM on train partners minus IQM on test
partners) with its interval.

The point estimates are rliable's metrics. The intervals follow rliable's method
(stratified bootstrap over runs, percentile intervals) with the resampling vectorised
(:func:`stratified_bootstrap`): rliable's ``get_interval_estimates`` calls the statistic
once per replication, and its probability of improvement runs scipy's Mann-Whitney U per
task per replication, which made most of a one-seed cross-play study's wall time;
vectorised, the aggregate is a small share of it (``benchmarks/study_aggregation.py``
measures both; the figures are in docs/benchmarks.md).
tests/training/test_aggregate.py checks the intervals against rliable's.

Intervals need seeds: with one seed every resample is the data itself (a zero-width
interval that says nothing), so none is computed; with fewer than
:data:`MIN_CI_SEEDS` seeds per task they are computed and flagged
(``aggregate.json``'s ``bootstrap.flag``, which report.md and the CLI print).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from itertools import combinations
from typing import Any

import numpy as np
import pandas as pd

REPS = 2000
"""Bootstrap replications of every interval."""
POI_REPS = 2000
"""Replications of each probability-of-improvement interval (vectorised: as cheap as the others)."""
SEED = 0
"""Seed of the bootstrap's generators."""
MIN_CI_SEEDS = 5
"""Seeds per task below which an interval is flagged: with n seeds a task's resample takes
at most C(2n-1, n) distinct values (n = 2: 3, n = 4: 35), too few for a 95% percentile
interval to mean what it says (with n = 1 there is one, and no interval is computed)."""


def score_matrix(
    frame: pd.DataFrame, robot: str, tasks: Sequence[tuple[str, str]] | None = None, column: str = "score"
) -> np.ndarray:
    """A robot's scores as a (seeds x tasks) matrix; tasks are (human, scenario) pairs in table order.

    Rows with no score (no reference rate) are left out; a task must have every seed.
    """
    mine = frame[(frame["robot"] == robot) & frame[column].notna()]
    if tasks is None:
        tasks = list(dict.fromkeys(zip(mine["human"], mine["scenario"], strict=True)))
    columns = []
    for human, scenario in tasks:
        cell = mine[(mine["human"] == human) & (mine["scenario"] == scenario)].sort_values("seed")
        columns.append(cell[column].to_numpy(dtype=float))
    if not columns:
        return np.zeros((0, 0))
    return np.stack(columns, axis=1)


def _tasks(frame: pd.DataFrame, robot: str) -> list[tuple[str, str]]:
    mine = frame[(frame["robot"] == robot) & frame["score"].notna()]
    return list(dict.fromkeys(zip(mine["human"], mine["scenario"], strict=True)))


def seeds_per_task(frame: pd.DataFrame) -> int:
    """The fewest seeds any (robot, human, scenario) with a score has (0: no score at all)."""
    scored = frame[frame["score"].notna()]
    if scored.empty:
        return 0
    return int(scored.groupby(["robot", "human", "scenario"], sort=False)["score"].count().min())


def ci_flag(seeds: int) -> str:
    """What a reader must know about intervals from ``seeds`` seeds per task ("" when nothing)."""
    if seeds <= 1:
        return "1 seed per task: no confidence interval can be computed (every resample is the data itself)"
    if seeds < MIN_CI_SEEDS:
        return (
            f"only {seeds} seeds per task (fewer than {MIN_CI_SEEDS}): the 95% intervals are too coarse "
            "to trust (a task's resample takes few distinct values)"
        )
    return ""


def iqm(x: np.ndarray) -> np.ndarray:
    """Interquartile mean of the last two axes (runs x tasks), as rliable's ``aggregate_iqm``.

    scipy's ``trim_mean(x, 0.25, axis=None)``: drop the ``int(0.25 N)`` lowest and highest
    of the N scores, average the rest; leading axes are bootstrap replications.
    """
    flat = np.sort(x.reshape(*x.shape[:-2], -1), axis=-1)
    cut = int(0.25 * flat.shape[-1])
    return np.asarray(flat[..., cut : flat.shape[-1] - cut].mean(axis=-1))


def mean(x: np.ndarray) -> np.ndarray:
    """Mean over tasks of the mean over runs (rliable's ``aggregate_mean``), over the last two axes."""
    return np.asarray(x.mean(axis=-2).mean(axis=-1))


def improvement(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """P(X > Y) per task averaged over tasks (rliable's ``probability_of_improvement``).

    Per task, the Mann-Whitney U of x over y divided by ``n_x n_y``: the share of (x, y)
    run pairs where x wins, ties counting one half. ``x`` is (..., runs_x, tasks), ``y``
    (..., runs_y, tasks).
    """
    diff = x[..., :, None, :] - y[..., None, :, :]
    wins = (diff > 0) + 0.5 * (diff == 0)
    return np.asarray(wins.mean(axis=(-3, -2)).mean(axis=-1))


Statistic = Callable[..., np.ndarray]
"""Maps matrices (..., runs, tasks) to (..., k) values; the leading axes are replications."""


def stratified_bootstrap(matrices: Sequence[np.ndarray], statistic: Statistic, reps: int) -> np.ndarray:
    """95% percentile interval (2 x k) of ``statistic`` under rliable's stratified bootstrap.

    Each matrix's runs are resampled with replacement within every task (column),
    independently per matrix (rliable's ``StratifiedIndependentBootstrap``), all ``reps``
    replications at once. A fresh generator seeded with :data:`SEED` per call, so an
    interval depends only on its own data (not on which other robots are in the study).
    """
    rng = np.random.default_rng(SEED)
    samples = []
    for m in matrices:
        index = rng.integers(0, m.shape[0], size=(reps, *m.shape))
        samples.append(np.take_along_axis(m[None], index, axis=1))
    values = np.asarray(statistic(*samples)).reshape(reps, -1)
    return np.asarray(np.percentile(values, [2.5, 97.5], axis=0))


def _iqm_and_mean(x: np.ndarray) -> np.ndarray:
    return np.stack([iqm(x), mean(x)], axis=-1)


def iqm_and_mean(scores: np.ndarray) -> np.ndarray:
    """``[IQM, mean]`` of a score matrix (rliable's metrics, vectorised: :func:`iqm`, :func:`mean`)."""
    return _iqm_and_mean(scores)


def _pair(values: np.ndarray | None, k: int) -> list[float] | None:
    return None if values is None else [float(values[0, k]), float(values[1, k])]


def aggregate(
    frame: pd.DataFrame, groups: dict[str, str] | None = None, reps: int = REPS, poi_reps: int = POI_REPS
) -> dict[str, Any]:
    """``aggregate.json``: per robot IQM/mean with CIs, pairwise improvement, generalisation gap.

    Intervals are None with one seed per task (see :func:`ci_flag`).

    Args:
        frame: the score table (``scores.csv``'s columns).
        groups: partner label -> ``train``/``test`` (held-out studies), else None.
        reps: bootstrap replications of the IQM, mean and gap intervals.
        poi_reps: bootstrap replications of the probability-of-improvement intervals.
    """
    seeds = seeds_per_task(frame)
    with_ci = seeds > 1
    robots = list(dict.fromkeys(frame["robot"]))
    matrices = {r: score_matrix(frame, r) for r in robots}
    matrices = {r: m for r, m in matrices.items() if m.size}
    out: dict[str, Any] = {
        "robots": {},
        "improvement": {},
        "bootstrap": {
            "reps": reps if with_ci else 0,
            "poi_reps": poi_reps if with_ci else 0,
            "seed": SEED,
            "ci": 0.95,
            "seeds_per_task": seeds,
            "flag": ci_flag(seeds),
        },
    }
    for r in robots:
        if r not in matrices:
            out["robots"][r] = {"iqm": None, "iqm_ci": None, "mean": None, "mean_ci": None, "runs": 0}
            continue
        p = iqm_and_mean(matrices[r])
        c = stratified_bootstrap([matrices[r]], _iqm_and_mean, reps) if with_ci else None
        out["robots"][r] = {
            "iqm": float(p[0]),
            "iqm_ci": _pair(c, 0),
            "mean": float(p[1]),
            "mean_ci": _pair(c, 1),
            "runs": int(matrices[r].size),
        }
    tasks = {r: _tasks(frame, r) for r in matrices}
    for a, b in combinations(list(matrices), 2):
        theirs = set(tasks[b])
        common = [t for t in tasks[a] if t in theirs]
        if not common:
            continue
        # the columns of the robots' matrices for the common tasks (no new pass over the frame)
        x = matrices[a][:, [tasks[a].index(t) for t in common]]
        y = matrices[b][:, [tasks[b].index(t) for t in common]]
        c = stratified_bootstrap([x, y], improvement, poi_reps) if with_ci else None
        out["improvement"][f"{a}>{b}"] = {"p": float(improvement(x, y)), "ci": _pair(c, 0)}
    if groups and {"train", "test"} <= set(groups.values()):
        out["generalisation"] = generalisation_gap(frame, groups, reps if with_ci else 0)
    out["br_prox"] = br_prox(frame, groups, reps if with_ci else 0)
    return out


def _gap(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    a, b = iqm(x), iqm(y)
    return np.stack([a, b, a - b], axis=-1)


def generalisation_gap(frame: pd.DataFrame, groups: dict[str, str], reps: int = REPS) -> dict[str, Any]:
    """Per robot: IQM on train partners, on test partners, and their difference with a CI (None: reps 0)."""
    train = frame[frame["human"].map(groups) == "train"]
    test = frame[frame["human"].map(groups) == "test"]
    out = {}
    for r in dict.fromkeys(frame["robot"]):
        a, b = score_matrix(train, r), score_matrix(test, r)
        if not (a.size and b.size):
            continue
        point = _gap(a, b)
        ci = stratified_bootstrap([a, b], _gap, reps) if reps else None
        out[r] = {
            "train_iqm": float(point[0]),
            "test_iqm": float(point[1]),
            "gap": float(point[2]),
            "gap_ci": _pair(ci, 2),
        }
    return out


def br_prox(frame: pd.DataFrame, groups: dict[str, str] | None = None, reps: int = REPS) -> list[dict[str, Any]]:
    """BR-Prox per robot, scenario and partner split: IQM with its 95% stratified-bootstrap CI (rliable).

    BR-Prox is ``min(1, rate / exact best-response rate)`` (``scores.csv``'s ``br_prox``);
    a split is a partner group (``train``, ``validation``, ``test``; ``all`` when the study
    has none). Only runs against partners with an exact best response count.
    """
    if "br_prox" not in frame or not frame["br_prox"].notna().any():
        return []
    split = frame["human"].map(groups or {}).fillna("all") if groups else pd.Series("all", index=frame.index)
    data: dict[str, np.ndarray] = {}
    keys: dict[str, tuple[str, str, str]] = {}
    for scenario in dict.fromkeys(frame["scenario"]):
        for group in dict.fromkeys(split):
            part = frame[(frame["scenario"] == scenario) & (split == group)]
            for robot in dict.fromkeys(part["robot"]):
                m = score_matrix(part, robot, column="br_prox")
                if m.size:
                    name = f"{robot}|{scenario}|{group}"
                    data[name], keys[name] = m, (robot, str(scenario), str(group))
    out = []
    for n, m in data.items():
        c = stratified_bootstrap([m], iqm, reps) if reps else None
        robot, scenario, group = keys[n]
        point = float(np.asarray(iqm(m)).reshape(-1)[0])
        out.append(
            {"robot": robot, "scenario": scenario, "split": group, "iqm": point, "ci": _pair(c, 0), "runs": int(m.size)}
        )
    return out


Curves = dict[str, np.ndarray]


def profile(x: np.ndarray, taus: np.ndarray) -> np.ndarray:
    """Fraction of runs with score > tau, for each tau (rliable's score distribution), over the last two axes."""
    return np.asarray((x[..., None] > taus).mean(axis=(-3, -2)))


def profiles(frame: pd.DataFrame, taus: np.ndarray, reps: int = 200) -> tuple[Curves, Curves]:
    """Performance profiles (fraction of runs with score > tau) and their 95% bands, per robot.

    rliable's ``create_performance_profile`` (score distributions over all runs and
    tasks, stratified-bootstrap bands), vectorised like every interval here; with one
    seed per task the band is the curve itself (there is nothing to resample).
    """
    taus = np.asarray(taus, dtype=float)
    curves: Curves = {}
    bands: Curves = {}
    for r in dict.fromkeys(frame["robot"]):
        m = score_matrix(frame, r)
        if not m.size:
            continue
        curves[r] = profile(m, taus)
        if len(m) > 1:
            bands[r] = stratified_bootstrap([m], lambda x: profile(x, taus), reps)
        else:
            bands[r] = np.stack([curves[r], curves[r]])
    return curves, bands
