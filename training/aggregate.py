"""Study aggregates with rliable (Agarwal et al. 2021): IQM, mean, probability of improvement.

rliable's unit is a *task*; here a task is one (human, scenario) pair and a *run* is one
seed, so each robot's scores form a (seeds x tasks) matrix and rliable's stratified
bootstrap resamples seeds within every (human, scenario) (95% percentile intervals,
``reps`` replications from a fixed ``RandomState``, so ``aggregate.json`` is
reproducible). Computed per robot: IQM and mean with intervals; per pair of robots, the
probability that one improves on the other (on the tasks both played); and, for
held-out studies, the generalisation gap (IQM on train partners minus IQM on test
partners) with its interval. Nothing here re-implements rliable; this module only
shapes the score table into its matrices.
"""

from __future__ import annotations

import contextlib
import warnings
from collections.abc import Callable, Iterator, Sequence
from itertools import combinations
from typing import Any

import numpy as np
import pandas as pd

REPS = 2000
"""Bootstrap replications of every interval."""
POI_REPS = 200
"""Replications of each probability-of-improvement interval (a Mann-Whitney U per task per
replication: the costly one, ~20 pairs x 7 humans in the cross-play study)."""
SEED = 0
"""Seed of the bootstrap's RandomState."""


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


def _interval(
    data: dict[str, Any], func: Callable[..., np.ndarray], reps: int
) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
    from rliable import library as rly

    with warnings.catch_warnings(), _seeded_global_rng():
        # arch announces that RandomState is deprecated; rliable 1.2 still passes one, which is what we want
        warnings.filterwarnings("ignore", category=FutureWarning, module="arch")
        return rly.get_interval_estimates(data, func, reps=reps, random_state=np.random.RandomState(SEED))


@contextlib.contextmanager
def _seeded_global_rng() -> Iterator[None]:
    """Seed numpy's global generator for the block, then put its state back.

    rliable 1.2's stratified bootstrap draws its indices with ``np.random.choice`` (the
    global generator) whatever ``random_state`` it is given, so without this the
    intervals would change from call to call.
    """
    state = np.random.get_state()
    np.random.seed(SEED)
    try:
        yield
    finally:
        np.random.set_state(state)


def iqm_and_mean(scores: np.ndarray) -> np.ndarray:
    """``[IQM, mean]`` of a score matrix (rliable's metrics)."""
    from rliable import metrics

    return np.array([metrics.aggregate_iqm(scores), metrics.aggregate_mean(scores)])


def aggregate(
    frame: pd.DataFrame, groups: dict[str, str] | None = None, reps: int = REPS, poi_reps: int = POI_REPS
) -> dict[str, Any]:
    """``aggregate.json``: per robot IQM/mean with CIs, pairwise improvement, generalisation gap.

    Args:
        frame: the score table (``scores.csv``'s columns).
        groups: partner label -> ``train``/``test`` (held-out studies), else None.
        reps: bootstrap replications of the IQM, mean and gap intervals.
        poi_reps: bootstrap replications of the probability-of-improvement intervals.
    """
    from rliable import metrics

    robots = list(dict.fromkeys(frame["robot"]))
    matrices = {r: score_matrix(frame, r) for r in robots}
    matrices = {r: m for r, m in matrices.items() if m.size}
    point, ci = _interval(matrices, iqm_and_mean, reps) if matrices else ({}, {})
    out: dict[str, Any] = {
        "robots": {},
        "improvement": {},
        "bootstrap": {"reps": reps, "poi_reps": poi_reps, "seed": SEED, "ci": 0.95},
    }
    for r in robots:
        if r not in matrices:
            out["robots"][r] = {"iqm": None, "iqm_ci": None, "mean": None, "mean_ci": None, "runs": 0}
            continue
        p, c = point[r], ci[r]
        out["robots"][r] = {
            "iqm": float(p[0]),
            "iqm_ci": [float(c[0, 0]), float(c[1, 0])],
            "mean": float(p[1]),
            "mean_ci": [float(c[0, 1]), float(c[1, 1])],
            "runs": int(matrices[r].size),
        }
    pairs: dict[str, list[np.ndarray]] = {}
    for a, b in combinations(list(matrices), 2):
        common = [t for t in _tasks(frame, a) if t in set(_tasks(frame, b))]
        if common:
            pairs[f"{a}>{b}"] = [score_matrix(frame, a, common), score_matrix(frame, b, common)]
    if pairs:
        p_point, p_ci = _interval(pairs, lambda x, y: np.array([metrics.probability_of_improvement(x, y)]), poi_reps)
        for name in pairs:
            low, high = p_ci[name][:, 0]
            out["improvement"][name] = {"p": float(p_point[name][0]), "ci": [float(low), float(high)]}
    if groups and {"train", "test"} <= set(groups.values()):
        out["generalisation"] = generalisation_gap(frame, groups, reps)
    out["br_prox"] = br_prox(frame, groups, reps)
    return out


def generalisation_gap(frame: pd.DataFrame, groups: dict[str, str], reps: int = REPS) -> dict[str, Any]:
    """Per robot: IQM on train partners, on test partners, and their difference with a CI."""
    from rliable import metrics

    train = frame[frame["human"].map(groups) == "train"]
    test = frame[frame["human"].map(groups) == "test"]
    data = {}
    for r in dict.fromkeys(frame["robot"]):
        a, b = score_matrix(train, r), score_matrix(test, r)
        if a.size and b.size:
            data[r] = [a, b]
    if not data:
        return {}

    def train_test_gap(x: np.ndarray, y: np.ndarray) -> np.ndarray:
        a, b = metrics.aggregate_iqm(x), metrics.aggregate_iqm(y)
        return np.array([a, b, a - b])

    point, ci = _interval(data, train_test_gap, reps)
    return {
        r: {
            "train_iqm": float(point[r][0]),
            "test_iqm": float(point[r][1]),
            "gap": float(point[r][2]),
            "gap_ci": [float(ci[r][0, 2]), float(ci[r][1, 2])],
        }
        for r in data
    }


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
    if not data:
        return []
    from rliable import metrics

    point, ci = _interval(data, lambda x: np.array([metrics.aggregate_iqm(x)]), reps)
    return [
        {
            "robot": keys[n][0],
            "scenario": keys[n][1],
            "split": keys[n][2],
            "iqm": float(point[n][0]),
            "ci": [float(ci[n][0, 0]), float(ci[n][1, 0])],
            "runs": int(data[n].size),
        }
        for n in data
    ]


Curves = dict[str, np.ndarray]


def profiles(frame: pd.DataFrame, taus: np.ndarray, reps: int = 200) -> tuple[Curves, Curves]:
    """Performance profiles (fraction of runs with score > tau) and their CIs, per robot (rliable).

    The bands come from a bootstrap seeded like every interval here.
    """
    from rliable import library as rly

    matrices = {r: score_matrix(frame, r) for r in dict.fromkeys(frame["robot"])}
    matrices = {r: m for r, m in matrices.items() if m.size}
    with _seeded_global_rng():
        return rly.create_performance_profile(matrices, taus, reps=reps)
