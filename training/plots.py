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


def _label_panels(axes: Any, n: int, xlabel: str, ylabel: str) -> None:
    """A grid of ``n`` used panels: the spare ones hidden, x labels on the bottom row, y on the left column."""
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel(xlabel)
    for ax in axes[:, 0]:
        ax.set_ylabel(ylabel)


def _legend_outside(ax: Any, source: Any = None) -> None:
    """The legend of ``source``'s lines (default: ``ax``'s), right of ``ax``, off the data."""
    handles, labels = (source or ax).get_legend_handles_labels()
    ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8, frameon=False)


def _merged(curves: dict[str, np.ndarray]) -> dict[str, tuple[list[str], np.ndarray]]:
    """Conditions whose curves are equal, drawn once: first label -> (every label, curve)."""
    groups: dict[str, tuple[list[str], np.ndarray]] = {}
    for label, curve in curves.items():
        twin = next((g for g, (_, c) in groups.items() if c.shape == curve.shape and np.allclose(c, curve)), None)
        if twin is None:
            groups[label] = ([label], curve)
        else:
            groups[twin][0].append(label)
    return groups


def _name(labels: list[str]) -> str:
    return labels[0] if len(labels) == 1 else " = ".join(labels) + " (coincide)"


def cumulative_reward(logs: dict[str, list[pd.DataFrame]], duration: float, path: Path) -> Path:
    """Fig. 3: :func:`cumulative_reward_figure` as a PNG."""
    return _save(cumulative_reward_figure(logs, duration), path)


def cumulative_reward_figure(logs: dict[str, list[pd.DataFrame]], duration: float) -> Any:
    """Fig. 3: mean (± sd over seeds) cumulative reward over simulated time, and each minus the planner.

    Most conditions solve within a task of the planner, so on the left panel their
    curves lie on one another; the right panel draws each mean minus the first
    condition's (the planner), on a symmetric-log scale (linear within one task of the
    planner, logarithmic beyond), so both the criteria's fractions of a task and the
    habit's tens show. Curves equal
    everywhere are drawn once, the legend naming all of them; each condition keeps its
    colour and line style (:mod:`hg_marl.training.colours`) in both panels.
    """
    from hg_marl.training.colours import styles

    plt = _pyplot()
    fig, (ax, diff) = plt.subplots(1, 2, figsize=(12, 4.5))
    grid = np.linspace(0, duration, 241)
    look = styles(logs)
    means, sds = {}, {}
    for label, runs in logs.items():
        curves = np.array(
            [np.searchsorted(log.loc[log["reward"] > 0, "time"].to_numpy(), grid, side="right") for log in runs],
            dtype=float,
        )
        means[label], sds[label] = curves.mean(axis=0), curves.std(axis=0)
    both = {k: np.concatenate([means[k], sds[k]]) for k in means}
    reference = next(iter(means))
    groups = _merged(both)
    for first, (labels, _) in groups.items():
        mean, sd = means[first], sds[first]
        ax.plot(grid / 60, mean, label=_name(labels), **look[first])
        ax.fill_between(grid / 60, mean - sd, mean + sd, alpha=0.12, color=look[first]["color"])
    # the reference is the zero line of the difference panel: drawn last, so the others show where they leave it
    for first in [*(g for g in groups if g != reference), reference]:
        diff.plot(grid / 60, means[first] - means[reference], **look[first])
    diff.set_yscale("symlog", linthresh=1.0, linscale=1.5)
    diff.yaxis.set_major_formatter(plt.FuncFormatter(lambda v, _: f"{v:g}"))
    seeds = max(len(runs) for runs in logs.values())
    ax.set(
        xlabel="simulated time (min)",
        ylabel="cumulative reward (tasks solved)",
        title=f"Fig. 3: cumulative reward, mean ± sd over {seeds} seeds",
    )
    diff.set(
        xlabel="simulated time (min)", ylabel=f"mean minus {reference}'s (tasks)", title=f"difference from {reference}"
    )
    for a in (ax, diff):
        a.grid(alpha=0.3)
    _legend_outside(diff, ax)
    fig.tight_layout()
    return fig


def actions_per_run(logs: dict[str, list[pd.DataFrame]], path: Path) -> Path:
    """Fig. 4: :func:`actions_per_run_figure` as a PNG."""
    return _save(actions_per_run_figure(logs), path)


def actions_per_run_figure(logs: dict[str, list[pd.DataFrame]]) -> Any:
    """Fig. 4: actions proposed per run, one dot per seed, dashed mean per condition.

    Conditions are rows (names read horizontally at any length, so long names such as
    ``entropy_and_cost`` never run into each other), the paper's first at the top.
    """
    from hg_marl.training.colours import colours

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 0.45 * len(logs) + 1.5))
    colour = colours(logs)
    for i, (label, runs) in enumerate(logs.items()):
        counts = np.array([len(log) for log in runs])
        ax.scatter(counts, np.full(len(counts), i) + np.linspace(-0.15, 0.15, len(counts)), s=18, color=colour[label])
        ax.vlines(counts.mean(), i - 0.3, i + 0.3, linestyles="dashed", colors="k")
    ax.set_yticks(range(len(logs)), list(logs))
    ax.invert_yaxis()
    ax.set(xlabel="actions proposed per run", title="Fig. 4: actions per experiment (dashed: mean)")
    ax.grid(alpha=0.3, axis="x")
    fig.tight_layout()
    return fig


def weight_amplitude(logs: dict[str, list[pd.DataFrame]], path: Path, threshold: float = 1.0) -> Path:
    """Fig. 5: :func:`weight_amplitude_figure` as a PNG."""
    return _save(weight_amplitude_figure(logs, threshold), path)


def weight_amplitude_figure(logs: dict[str, list[pd.DataFrame]], threshold: float = 1.0) -> Any:
    """Fig. 5: habit weight amplitude (sum |w|) over decisions, mean over seeds (:func:`paper.mean_amplitude`).

    Small multiples, one panel per condition (curves equal everywhere share one): the
    tabular criteria's curves lie within a line width of each other, so one axes would
    hide all but the last drawn. Each panel draws its condition in its colour over the
    others in grey, on a shared logarithmic axis (early amplitudes differ by orders of
    magnitude), and its title gives the decision at which the drawn curve crosses
    ``threshold`` (:func:`paper.crossing`, the number summary.json reports).
    """
    from hg_marl.training.colours import styles
    from hg_marl.training.paper import crossing, mean_amplitude

    plt = _pyplot()
    look = styles(logs)
    curves = {
        label: mean_amplitude(runs)
        for label, runs in logs.items()
        if any(log["weight_amplitude"].abs().sum() > 0 for log in runs)
    }
    groups = _merged(curves)
    n = max(1, len(groups))
    cols = min(3, n)
    rows = -(-n // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.0 * cols, 2.9 * rows), sharex=True, sharey=True, squeeze=False)
    positive = {k: np.where(c > 0, c, np.nan) for k, (_, c) in groups.items()}
    for ax, (first, (labels, curve)) in zip(axes.flat, groups.items(), strict=False):
        for other, shown in positive.items():
            if other != first:
                ax.plot(np.arange(len(shown)), shown, color="0.8", linewidth=1.0)
        at = crossing(curve, threshold)
        ax.plot(np.arange(len(curve)), positive[first], linewidth=2.0, label=_name(labels), **look[first])
        ax.axhline(threshold, color="k", linestyle=":", linewidth=1.0)
        where = f"crosses {threshold:g} at decision {at}" if at is not None else f"never reaches {threshold:g}"
        ax.set_title(f"{_name(labels)}\n{where} (mean of {len(logs[first])} seeds)", fontsize=8)
        ax.set_yscale("log")
        ax.grid(alpha=0.3)
    _label_panels(axes, n, "decision", "sum |w| (log)")
    title = f"Fig. 5: habit weight amplitude, mean over seeds (dotted: {threshold:g}, the habit has started learning)"
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


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
    """:func:`adaptation_figure` as a PNG."""
    return _save(adaptation_figure(grid, curves, phases, title), path)


def adaptation_figure(
    grid: np.ndarray,
    curves: dict[str, np.ndarray],
    phases: list[tuple[float, float]],
    title: str,
) -> Any:
    """Reward rate around the human's changes: one panel per robot, so none hides another.

    Args:
        grid: times (s) of the rate estimates.
        curves: robot -> array (seeds x grid) of tasks per hour.
        phases: ``(start time, oracle rate)`` of each human, in order.
        title: the figure's title.
    """
    from hg_marl.training.colours import colours

    plt = _pyplot()
    colour = colours(curves)
    n = len(curves)
    cols = min(3, n)
    rows = -(-n // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 2.8 * rows), sharex=True, sharey=True, squeeze=False)
    end = float(grid[-1]) if len(grid) else 0.0
    starts = [t for t, _ in phases] + [end]
    for ax, (label, table) in zip(axes.flat, curves.items(), strict=False):
        mean, low, high = _band(np.asarray(table, dtype=float))
        ax.plot(grid / 60, mean, color=colour[label], label="robot (mean)")
        ax.fill_between(grid / 60, low, high, color=colour[label], alpha=0.25, label="95% CI")
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
    _label_panels(axes, n, "simulated time (min)", "tasks per hour")
    axes.flat[0].legend(fontsize=7, loc="lower left")
    fig.suptitle(title, fontsize=10)
    # tight_layout makes room for the figure's title above the panels' own (without it they overlap)
    fig.tight_layout()
    return fig


CLIP = 4.0
"""A bar taller than this many times the panel's median bar top is clipped (see :func:`regret_bars_figure`)."""


def regret_bars(results: dict[str, Any], path: Path) -> Path:
    """:func:`regret_bars_figure` as a PNG."""
    return _save(regret_bars_figure(results), path)


def regret_bars_figure(results: dict[str, Any]) -> Any:
    """Tasks lost to the oracle after the last change, mean and 95% CI, one panel per switch.

    Each panel's scale fits the robots the text compares: a bar whose top exceeds
    :data:`CLIP` times the panel's median bar top (the habit alone loses many times what
    the others lose: ``docs/results.md``) is cut at the top of the axis, hatched, and its value written on it, so
    the others' differences are not slivers. Colours are the robots' own
    (:mod:`hg_marl.training.colours`).
    """
    from hg_marl.training.colours import colours

    plt = _pyplot()
    n = len(results)
    fig, axes = plt.subplots(1, n, figsize=(4.0 * n, 3.6), squeeze=False)
    order = [r for block in results.values() for r in block["robots"]]
    colour = colours(order)
    for ax, block in zip(axes[0], results.values(), strict=True):
        robots = list(block["robots"])
        cis = [block["robots"][r]["tasks_lost"] for r in robots]
        mean = np.array([c["mean"] for c in cis], dtype=float)
        low = np.array([c["low"] for c in cis], dtype=float)
        high = np.array([c["high"] for c in cis], dtype=float)
        tops = np.maximum(high, mean)
        reference = float(np.median(np.abs(tops))) if len(tops) else 0.0
        kept = tops <= CLIP * reference if reference > 0 else np.ones(len(tops), dtype=bool)
        limit = 1.15 * float(tops[kept].max()) if kept.any() and tops[kept].max() > 0 else float(tops.max(initial=1.0))
        bottom = min(0.0, 1.15 * float(low.min(initial=0.0)))
        for i, r in enumerate(robots):
            if kept[i]:
                ax.bar(i, mean[i], yerr=[[mean[i] - low[i]], [high[i] - mean[i]]], capsize=3, color=colour[r])
            else:
                ax.bar(i, limit, color=colour[r], hatch="//", edgecolor="white")
                ax.text(
                    i, limit * 0.5, f"{mean[i]:.1f}\n[{low[i]:.1f}, {high[i]:.1f}]\n(cut)", ha="center", va="center",
                    fontsize=7, rotation=90, color="black",
                )  # fmt: skip
        ax.set_ylim(bottom, limit)
        ax.set_xticks(range(len(robots)), robots, rotation=60, ha="right", fontsize=7, rotation_mode="anchor")
        ax.axhline(0.0, color="k", linewidth=0.8)
        ax.set_title(" -> ".join(block["humans"]), fontsize=9)
        ax.grid(alpha=0.3, axis="y")
    axes[0][0].set_ylabel("tasks lost to the oracle (mean, 95% CI)")
    fig.tight_layout()
    return fig


def switching(summary: dict[str, Any], path: Path) -> Path:
    """:func:`switching_figure` as a PNG."""
    return _save(switching_figure(summary), path)


def switching_figure(summary: dict[str, Any]) -> Any:
    """Tasks per run against the switching period, one panel per partner pair.

    Each robot is a line of means with 95% CI bars over seeds (its own colour,
    :mod:`hg_marl.training.colours`); the per-phase best response is the black dashed
    reference. The period axis is logarithmic (seconds to many minutes), with a tick at
    every period run. A robot that loses to the baseline on a cell (the CI of the paired
    difference below 0) gets a red ring there, so a reader sees where adaptation hurts.
    """
    from hg_marl.training.colours import styles

    plt = _pyplot()
    cells = summary["cells"]
    pairs = list(dict.fromkeys(c["pair"] for c in cells))
    robots = list(dict.fromkeys(c["robot"] for c in cells))
    style = styles(robots)
    fig, axes = plt.subplots(1, len(pairs), figsize=(4.6 * len(pairs), 3.6), squeeze=False, sharey=False)
    for ax, pair in zip(axes[0], pairs, strict=True):
        mine = [c for c in cells if c["pair"] == pair]
        periods = sorted({float(c["period"]) for c in mine})
        reference = [next(c["reference_tasks"] for c in mine if c["period"] == p) for p in periods]
        ax.plot(periods, reference, color="k", linestyle="--", marker="_", label="per-phase best response")
        for k, robot in enumerate(robots):
            rows = sorted((c for c in mine if c["robot"] == robot), key=lambda c: c["period"])
            x = np.array([float(c["period"]) for c in rows])
            # robots side by side at each period, so their bars never cover each other
            x = x * (1.0 + 0.04 * (k - (len(robots) - 1) / 2))
            mean = np.array([c["tasks"]["mean"] for c in rows], dtype=float)
            low = np.array([c["tasks"]["low"] for c in rows], dtype=float)
            high = np.array([c["tasks"]["high"] for c in rows], dtype=float)
            ax.errorbar(x, mean, yerr=[mean - low, high - mean], capsize=3, marker="o", markersize=4, label=robot,
                        **style[robot])  # fmt: skip
            lost = np.array([c["loses"] for c in rows], dtype=bool)
            if lost.any():
                ax.scatter(x[lost], mean[lost], s=140, facecolors="none", edgecolors="red", linewidths=1.5,
                           label=f"{robot}: loses to {summary['baseline']}", zorder=5)  # fmt: skip
        ax.set_xscale("log")
        ax.set_xticks(periods, [f"{p:g}" for p in periods])
        ax.minorticks_off()
        ax.set_xlabel("switching period (simulated s)")
        ax.set_title(f"partner switches {pair.replace('/', ' <-> ')}", fontsize=9)
        ax.grid(alpha=0.3)
        ax.margins(y=0.12)
    axes[0][0].set_ylabel(f"tasks per {summary['duration']:g} s run (mean, 95% CI)")
    # one legend for all panels, below them: it never covers a curve nor squeezes a panel
    handles: dict[str, Any] = {}
    for ax in axes[0]:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            handles.setdefault(label, handle)
    fig.suptitle(f"{summary['scenario']}: {summary['seeds']} seeds per point", fontsize=10)
    fig.tight_layout(rect=(0.0, 0.1 + 0.035 * len(handles) // 2, 1.0, 1.0))
    fig.legend(list(handles.values()), list(handles), loc="lower center", ncol=2, fontsize=8, frameon=False)
    return fig
