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
    """Fig. 3: mean (± sd over seeds) cumulative reward over simulated time."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    grid = np.linspace(0, duration, 241)
    for label, runs in logs.items():
        curves = np.array(
            [np.searchsorted(log.loc[log["reward"] > 0, "time"].to_numpy(), grid, side="right") for log in runs],
            dtype=float,
        )
        mean, sd = curves.mean(axis=0), curves.std(axis=0)
        ax.plot(grid / 60, mean, label=label)
        ax.fill_between(grid / 60, mean - sd, mean + sd, alpha=0.15)
    ax.set(
        xlabel="simulated time (min)",
        ylabel="cumulative reward (tasks solved)",
        title="Fig. 3: cumulative reward, mean ± sd",
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


def weight_amplitude(logs: dict[str, list[pd.DataFrame]], path: Path) -> Path:
    """Fig. 5: mean habit weight amplitude (sum |w|) over decisions."""
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
        ax.plot(np.arange(length), np.nanmean(table, axis=0), label=label)
    ax.set(xlabel="decision", ylabel="weight amplitude (sum |w|)", title="Fig. 5: habit weight amplitude")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return _save(fig, path)


def adaptation(
    curves: dict[str, tuple[np.ndarray, np.ndarray]],
    switch_time: float,
    oracle_rates: tuple[float, float],
    title: str,
    path: Path,
) -> Path:
    """Reward rate over time around a switch of the human, against the oracle's rates."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, (t, rate) in curves.items():
        ax.plot(t / 60, rate, label=label)
    before, after = oracle_rates
    ax.axvline(switch_time / 60, color="k", linestyle=":", label="human switches")
    ax.hlines(
        [before, after],
        [0, switch_time / 60],
        [switch_time / 60, ax.get_xlim()[1]],
        colors="grey",
        linestyles="dashed",
        label="oracle rate",
    )
    ax.set(xlabel="simulated time (min)", ylabel="tasks per hour (sliding window)", title=title)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return _save(fig, path)
