"""The paper's figures (Fig. 3-5) and the adaptation figure, as PNGs (matplotlib, Agg)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from hg_marl.training.io import atomic_write


def _pyplot() -> Any:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig: Any, path: Path) -> Path:
    out = atomic_write(path, lambda tmp: fig.savefig(tmp, dpi=110, bbox_inches="tight", format="png"))
    _pyplot().close(fig)
    return out


def cumulative_reward(logs: dict[str, list[pd.DataFrame]], duration: float, path: Path) -> Path:
    """Fig. 3: mean (± sd over seeds) cumulative reward over simulated time.

    Conditions whose mean curves coincide (e.g. criteria that always defer to the
    planner early on) are drawn once, the legend naming all of them.
    """
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    grid = np.linspace(0, duration, 241)
    groups: list[tuple[list[str], np.ndarray, np.ndarray]] = []
    for label, runs in logs.items():
        curves = np.array(
            [np.searchsorted(log.loc[log["reward"] > 0, "time"].to_numpy(), grid, side="right") for log in runs],
            dtype=float,
        )
        mean, sd = curves.mean(axis=0), curves.std(axis=0)
        same = next((g for g in groups if np.allclose(g[1], mean) and np.allclose(g[2], sd)), None)
        if same is not None:
            same[0].append(label)
        else:
            groups.append(([label], mean, sd))
    for labels, mean, sd in groups:
        name = labels[0] if len(labels) == 1 else " = ".join(labels) + " (coincide)"
        ax.plot(grid / 60, mean, label=name)
        ax.fill_between(grid / 60, mean - sd, mean + sd, alpha=0.15)
    seeds = max(len(runs) for runs in logs.values())
    ax.set(
        xlabel="simulated time (min)",
        ylabel="cumulative reward (tasks solved)",
        title=f"Fig. 3: cumulative reward, mean ± sd over {seeds} seeds",
    )
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    return _save(fig, path)


def actions_per_run(logs: dict[str, list[pd.DataFrame]], path: Path) -> Path:
    """Fig. 4: actions proposed per run, one dot per seed, dashed mean per condition."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i, runs in enumerate(logs.values()):
        counts = np.array([len(log) for log in runs])
        ax.scatter(np.full(len(counts), i) + np.linspace(-0.15, 0.15, len(counts)), counts, s=18)
        ax.hlines(counts.mean(), i - 0.3, i + 0.3, linestyles="dashed", colors="k")
    ax.set_xticks(range(len(logs)), list(logs), rotation=20)
    ax.set(ylabel="actions proposed per run", title="Fig. 4: actions per experiment (dashed: mean)")
    ax.grid(alpha=0.3, axis="y")
    return _save(fig, path)


def weight_amplitude(logs: dict[str, list[pd.DataFrame]], path: Path, threshold: float = 1.0) -> Path:
    """Fig. 5: habit weight amplitude (sum |w|) over decisions, averaged over seeds.

    A run shorter than the longest is held at its last value. ``threshold`` marks the
    amplitude at which the habit is said to have started learning (the README cites the
    decision at which each condition crosses it).
    """
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, runs in logs.items():
        if not any(log["weight_amplitude"].abs().sum() > 0 for log in runs):
            continue
        length = max(len(log) for log in runs)
        table = np.full((len(runs), length), np.nan)
        for k, log in enumerate(runs):
            values = log["weight_amplitude"].to_numpy()
            table[k, : len(values)] = values
            table[k, len(values) :] = values[-1] if len(values) else np.nan
        ax.plot(np.arange(length), np.nanmean(table, axis=0), label=f"{label} (mean of {len(runs)} seeds)")
    ax.axhline(threshold, color="k", linestyle=":", label=f"{threshold:g}: the habit has started learning")
    ax.set(
        xlabel="decision",
        ylabel="weight amplitude (sum |w|)",
        title="Fig. 5: habit weight amplitude, mean over seeds",
    )
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return _save(fig, path)


def _band(curves: np.ndarray, seed: int = 0, n_boot: int = 1000) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mean over seeds (rows) and its percentile-bootstrap 95% band at each column."""
    mean = curves.mean(axis=0)
    if len(curves) < 2:
        return mean, mean, mean
    rng = np.random.default_rng(seed)
    boot = curves[rng.integers(0, len(curves), size=(n_boot, len(curves)))].mean(axis=1)
    low, high = np.percentile(boot, [2.5, 97.5], axis=0)
    return mean, low, high


def adaptation(
    grid: np.ndarray,
    curves: dict[str, np.ndarray],
    phases: list[tuple[float, float]],
    title: str,
    path: Path,
) -> Path:
    """Reward rate around the human's changes: one panel per robot, so none hides another.

    Args:
        grid: times (s) of the rate estimates.
        curves: robot -> array (seeds x grid) of tasks per hour.
        phases: ``(start time, oracle rate)`` of each human, in order.
        title: the figure's title.
        path: PNG to write.
    """
    plt = _pyplot()
    n = len(curves)
    cols = min(3, n)
    rows = -(-n // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 2.8 * rows), sharex=True, sharey=True, squeeze=False)
    end = float(grid[-1]) if len(grid) else 0.0
    starts = [t for t, _ in phases] + [end]
    for ax, (label, table) in zip(axes.flat, curves.items(), strict=False):
        mean, low, high = _band(np.asarray(table, dtype=float))
        ax.plot(grid / 60, mean, color="C0", label="robot (mean)")
        ax.fill_between(grid / 60, low, high, color="C0", alpha=0.25, label="95% CI")
        for k, (start, rate) in enumerate(phases):
            ax.hlines(
                rate,
                start / 60,
                starts[k + 1] / 60,
                colors="k",
                linestyles="dashed",
                label="oracle" if k == 0 else None,
            )
            if k:
                ax.axvline(start / 60, color="grey", linestyle=":")
        ax.set_title(label, fontsize=9)
        ax.grid(alpha=0.3)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("simulated time (min)")
    for ax in axes[:, 0]:
        ax.set_ylabel("tasks per hour")
    axes.flat[0].legend(fontsize=7, loc="lower left")
    fig.suptitle(title, fontsize=10)
    return _save(fig, path)


def regret_bars(results: dict[str, Any], path: Path) -> Path:
    """Tasks lost to the oracle after the last change, mean and 95% CI, one panel per switch."""
    plt = _pyplot()
    n = len(results)
    fig, axes = plt.subplots(1, n, figsize=(4.0 * n, 3.6), squeeze=False, sharey=True)
    for ax, block in zip(axes[0], results.values(), strict=True):
        robots = list(block["robots"])
        cis = [block["robots"][r]["tasks_lost"] for r in robots]
        mean = np.array([c["mean"] for c in cis], dtype=float)
        err = np.array(
            [
                [m - c["low"] for m, c in zip(mean, cis, strict=True)],
                [c["high"] - m for m, c in zip(mean, cis, strict=True)],
            ]
        )
        ax.bar(range(len(robots)), mean, yerr=err, capsize=3, color="C1")
        ax.set_xticks(range(len(robots)), robots, rotation=60, ha="right", fontsize=7)
        ax.axhline(0.0, color="k", linewidth=0.8)
        ax.set_title(" -> ".join(block["humans"]), fontsize=9)
        ax.grid(alpha=0.3, axis="y")
    axes[0][0].set_ylabel("tasks lost to the oracle (mean, 95% CI)")
    return _save(fig, path)
