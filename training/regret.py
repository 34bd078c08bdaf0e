"""Adaptation metrics on per-decision logs: regret against the oracle and time to recover.

Pure functions of a run's log (columns ``time`` and ``reward``, one row per robot
decision, as :mod:`hg_marl.training.runner` writes them), independent of how the runs
were executed.

After the human switches at ``switch_at``, the oracle robot (optimal for the new human)
solves tasks at ``oracle_rate`` per hour. With ``N(t)`` the tasks the robot solved in
``(switch_at, t]``, the *regret* is the oracle's expected tasks minus the robot's::

    D(t) = oracle_rate / 3600 * (t - switch_at) - N(t)

It grows linearly between completions and drops by one at each, so its value at the end
of the run is the tasks lost to the oracle, and its shape says when the loss stopped.
The *time to recover* is the earliest ``tau >= switch_at`` from which the robot keeps the
oracle's pace, never falling more than ``slack`` tasks behind it again:
``max_{t >= tau} D(t) - D(tau) <= slack``, with at least ``min_tail`` seconds of run
left to show it (else ``None``). It is read on the decision times, so its resolution is
one decision, not a rate window.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd


def _completions(log: pd.DataFrame, switch_at: float) -> np.ndarray:
    """Times of the tasks solved after ``switch_at`` (sorted)."""
    times = log.loc[(log["reward"] > 0) & (log["time"] > switch_at), "time"].to_numpy(dtype=float)
    return np.sort(times)


def regret_at(log: pd.DataFrame, switch_at: float, oracle_rate: float, grid: np.ndarray) -> np.ndarray:
    """``D(t)`` at each time of ``grid`` (seconds; times before the switch give 0)."""
    done = _completions(log, switch_at)
    grid = np.asarray(grid, dtype=float)
    solved = np.searchsorted(done, grid, side="right")
    return np.where(grid > switch_at, oracle_rate / 3600.0 * (grid - switch_at) - solved, 0.0)


def tasks_lost(log: pd.DataFrame, switch_at: float, oracle_rate: float, end: float | None = None) -> float:
    """Cumulative regret at ``end`` (default: the log's last time): tasks lost to the oracle."""
    stop = float(log["time"].iloc[-1]) if end is None else float(end)
    return float(regret_at(log, switch_at, oracle_rate, np.array([stop]))[0])


def time_to_recover(
    log: pd.DataFrame,
    switch_at: float,
    oracle_rate: float,
    slack: float = 1.0,
    min_tail: float = 300.0,
    end: float | None = None,
) -> float | None:
    """Seconds from the switch until the robot keeps the oracle's pace (see the module docstring)."""
    stop = float(log["time"].iloc[-1]) if end is None else float(end)
    times = log["time"].to_numpy(dtype=float)
    candidates = np.concatenate([[switch_at], times[(times > switch_at) & (times <= stop - min_tail)]])
    if stop - switch_at < min_tail:
        return None
    done = _completions(log, switch_at)
    done = done[done <= stop]
    # D peaks just before each completion and at the end: those are the only maxima to check
    peaks_t = np.concatenate([done, [stop]])
    peaks = oracle_rate / 3600.0 * (peaks_t - switch_at) - (np.arange(len(peaks_t)))
    suffix_max = np.maximum.accumulate(peaks[::-1])[::-1]
    d_tau = regret_at(log, switch_at, oracle_rate, candidates)
    d_tau[0] = 0.0
    first_peak = np.searchsorted(peaks_t, candidates, side="right")  # peaks strictly after tau
    ok = suffix_max[np.minimum(first_peak, len(peaks) - 1)] - d_tau <= slack + 1e-9
    hits = np.flatnonzero(ok)
    return float(candidates[hits[0]] - switch_at) if len(hits) else None


def bootstrap_ci(
    values: Sequence[float], level: float = 0.95, n_boot: int = 2000, seed: int = 0
) -> tuple[float, float, float]:
    """Mean and percentile-bootstrap confidence interval of the mean (seeded, so reproducible).

    Returns:
        ``(mean, low, high)``; with one value the interval is that value.
    """
    x = np.asarray(values, dtype=float)
    if x.size == 0 or not np.isfinite(x).all():
        raise ValueError("bootstrap_ci: needs at least one finite value")
    if x.size == 1:
        return float(x[0]), float(x[0]), float(x[0])
    rng = np.random.default_rng(seed)
    means = x[rng.integers(0, x.size, size=(n_boot, x.size))].mean(axis=1)
    tail = (1.0 - level) / 2.0 * 100.0
    low, high = np.percentile(means, [tail, 100.0 - tail])
    return float(x.mean()), float(low), float(high)
