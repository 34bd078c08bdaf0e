"""A study's outputs: ``scores.csv``, ``aggregate.json``, three figures and ``report.md``.

``report.md`` is what a person reads first: the per-robot table (IQM and mean with 95%
CIs), the robots x humans table of mean scores, what each human's scores were divided
by (the oracle, or the best robot where the oracle could not be computed), the
generalisation gap of held-out studies, and the pairs whose probability of improvement
is clearly away from one half. Figures: ``crossplay.png`` (annotated heatmap of mean
score), ``profiles.png`` (rliable performance profiles), ``intervals.png`` (IQM and
mean with their intervals).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from hg_marl.training.aggregate import aggregate, profiles
from hg_marl.training.io import atomic_write, write_json, write_text
from hg_marl.training.study import Study


def _pyplot() -> Any:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def mean_table(frame: pd.DataFrame) -> pd.DataFrame:
    """Robots x humans mean score (study order)."""
    table = frame.pivot_table(index="robot", columns="human", values="score", aggfunc="mean", sort=False)
    return table.reindex(index=list(dict.fromkeys(frame["robot"])), columns=list(dict.fromkeys(frame["human"])))


def _save(fig: Any, path: Path) -> Path:
    atomic_write(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png", bbox_inches="tight"))
    _pyplot().close(fig)
    return path


NA_COLOUR = "#d9d9d9"
"""Cells with no score (no reference rate): light grey, hatched, never a colour of the scale."""


def crossplay_figure(frame: pd.DataFrame, title: str) -> Any:
    """Annotated heatmap of mean score, robots x humans; a cell without a score reads "n/a" on grey."""
    import matplotlib as mpl

    plt = _pyplot()
    table = mean_table(frame)
    fig, ax = plt.subplots(figsize=(1.2 * len(table.columns) + 2.5, 0.55 * len(table.index) + 1.8))
    values = table.to_numpy(dtype=float)
    cmap = mpl.colormaps["viridis"].with_extremes(bad=NA_COLOUR)
    top = max(1.0, float(np.nanmax(values))) if np.isfinite(values).any() else 1.0
    image = ax.imshow(np.ma.masked_invalid(values), cmap=cmap, vmin=0.0, vmax=top)
    ax.set_xticks(range(len(table.columns)), table.columns, rotation=35, ha="right")
    ax.set_yticks(range(len(table.index)), table.index)
    for i in range(values.shape[0]):
        for j in range(values.shape[1]):
            if np.isnan(values[i, j]):
                cell = mpl.patches.Rectangle((j - 0.5, i - 0.5), 1, 1, fill=False, hatch="//", ec="#a0a0a0", lw=0)
                ax.add_patch(cell)
                ax.text(j, i, "n/a", ha="center", va="center", color="black", fontstyle="italic")
            else:
                dark = values[i, j] < 0.6 * top
                ax.text(j, i, f"{values[i, j]:.2f}", ha="center", va="center", color="white" if dark else "black")
    fig.colorbar(image, ax=ax, label="score (tasks/h / reference rate); grey n/a: no reference")
    ax.set_title(title)
    return fig


def crossplay_png(frame: pd.DataFrame, path: Path, title: str) -> Path:
    """``crossplay.png``: :func:`crossplay_figure`."""
    return _save(crossplay_figure(frame, title), path)


def profiles_figure(frame: pd.DataFrame) -> Any:
    """rliable performance profiles: fraction of runs above each score threshold, in two panels.

    The left panel spans every score; the right one zooms on the thresholds where the
    best robots' profiles fall (most robots of a study score close to one another
    there, so on the full axis their curves would lie on each other). Each robot has
    its own colour and line style (:mod:`hg_marl.training.colours`); the legend sits
    outside the axes.
    """
    from hg_marl.training.colours import styles

    plt = _pyplot()
    scores = frame["score"].to_numpy(dtype=float)
    top = float(np.nanmax(scores)) if frame["score"].notna().any() else 1.0
    taus = np.linspace(0.0, max(1.0, top) * 1.05, 61)
    curves, bands = profiles(frame, taus)
    look = styles(dict.fromkeys(frame["robot"]))
    colours = {r: look[r]["color"] for r in curves}
    dashes = {r: look[r]["linestyle"] for r in curves}
    # The zoom: from the 25th percentile of the robots' median scores to the top score.
    medians = frame.groupby("robot")["score"].median().dropna().to_numpy(dtype=float)
    low = float(np.percentile(medians, 25)) if len(medians) else 0.0
    fine = np.linspace(max(0.0, low - 0.05 * max(top - low, 0.05)), max(top, low + 0.05) * 1.01, 61)
    fine_curves, fine_bands = profiles(frame, fine)
    # Robots whose profiles are identical on both grids are drawn once, the legend naming all.
    groups: dict[str, list[str]] = {}
    for r in curves:
        same = (g for g in groups if np.array_equal(curves[g], curves[r]))
        twin = next((g for g in same if np.array_equal(fine_curves[g], fine_curves[r])), None)
        groups.setdefault(twin or r, []).append(r)
    names = {g: "\n= ".join(members) + (" (identical)" if len(members) > 1 else "") for g, members in groups.items()}

    def drawn(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        return {names[g]: c[g] for g in groups}

    colours, dashes = {names[g]: colours[g] for g in groups}, {names[g]: dashes[g] for g in groups}
    curves, bands, fine_curves, fine_bands = drawn(curves), drawn(bands), drawn(fine_curves), drawn(fine_bands)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={"width_ratios": [1, 1]})
    panels = ((axes[0], taus, curves, bands, "all scores"), (axes[1], fine, fine_curves, fine_bands, "zoom"))
    for ax, grid, c, b, name in panels:
        for label, curve in c.items():
            ax.plot(grid, curve, color=colours[label], linestyle=dashes[label], linewidth=2.0, label=label)
            ax.fill_between(grid, b[label][0], b[label][1], color=colours[label], alpha=0.15, linewidth=0)
        ax.set(xlabel=r"score $\tau$", ylabel=r"fraction of runs > $\tau$", ylim=(-0.03, 1.03), title=name)
        ax.grid(alpha=0.3)
    axes[1].set_ylabel("")
    axes[1].legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", frameon=False)
    fig.tight_layout()
    return fig


def profiles_png(frame: pd.DataFrame, path: Path) -> Path:
    """``profiles.png``: :func:`profiles_figure`."""
    return _save(profiles_figure(frame), path)


def intervals_figure(agg: dict[str, Any]) -> Any:
    """IQM and mean per robot with their 95% stratified-bootstrap intervals (rliable's figure, in matplotlib).

    One panel per metric; a bar spans the interval, a black tick marks the point
    estimate. Without intervals (one seed) only the ticks are drawn and the title says so.
    """
    from hg_marl.training.colours import colours

    plt = _pyplot()
    rows = {r: v for r, v in agg["robots"].items() if v["iqm"] is not None}
    colour = colours(agg["robots"])
    fig, axes = plt.subplots(1, 2, figsize=(8, 0.45 * len(rows) + 1.4), sharey=True, squeeze=False)
    for ax, (metric, key) in zip(axes[0], (("IQM", "iqm"), ("Mean", "mean")), strict=True):
        for i, (robot, v) in enumerate(rows.items()):
            ci = v[f"{key}_ci"]
            if ci is not None:
                ax.barh(i, ci[1] - ci[0], left=ci[0], height=0.6, color=colour[robot], alpha=0.8)
            ax.vlines(v[key], i - 0.35, i + 0.35, colors="black", linewidth=1.5)
        ax.set_yticks(range(len(rows)), list(rows))
        ax.invert_yaxis()
        ax.set(xlabel="score", title=metric)
        ax.grid(alpha=0.3, axis="x")
    if agg["bootstrap"]["flag"]:
        fig.suptitle(agg["bootstrap"]["flag"], fontsize=8)
    fig.tight_layout()
    return fig


def intervals_png(agg: dict[str, Any], path: Path) -> Path:
    """``intervals.png``: :func:`intervals_figure`."""
    return _save(intervals_figure(agg), path)


def _ci(values: list[float] | None) -> str:
    return "-" if values is None else f"[{values[0]:.2f}, {values[1]:.2f}]"


def _num(value: float | None) -> str:
    return "-" if value is None or (isinstance(value, float) and np.isnan(value)) else f"{value:.2f}"


def robot_table(agg: dict[str, Any]) -> str:
    """Markdown table of IQM and mean with CIs per robot."""
    lines = ["| robot | IQM | 95% CI | mean | 95% CI | runs |", "|---|---:|---|---:|---|---:|"]
    for name, v in agg["robots"].items():
        cells = [name, _num(v["iqm"]), _ci(v["iqm_ci"]), _num(v["mean"]), _ci(v["mean_ci"]), str(v["runs"])]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def crossplay_table(frame: pd.DataFrame) -> str:
    """Markdown robots x humans table of mean score, and a reference line per human."""
    table = mean_table(frame)
    lines = ["| robot | " + " | ".join(table.columns) + " |", "|---|" + "---:|" * len(table.columns)]
    for robot, row in table.iterrows():
        lines.append(f"| {robot} | " + " | ".join("n/a" if np.isnan(v) else f"{v:.2f}" for v in row) + " |")
    refs = frame.drop_duplicates(["human", "scenario"])[["human", "scenario", "oracle_rate", "reference"]]
    lines += ["", "| human | scenario | reference rate (tasks/h) | reference |", "|---|---|---:|---|"]
    for _, r in refs.iterrows():
        scenario = Path(str(r["scenario"])).name
        lines.append(f"| {r['human']} | {scenario} | {_num(r['oracle_rate'])} | {r['reference']} |")
    return "\n".join(lines)


def br_prox_section(agg: dict[str, Any], headrooms: dict[str, float | None]) -> list[str]:
    """BR-Prox IQM per robot, scenario and split, with each scenario's adaptation headroom beside it."""
    rows = agg.get("br_prox") or []
    if not rows:
        return []
    lines = [
        "## BR-Prox (score against each partner's exact best response)",
        "",
        "BR-Prox = min(1, tasks per hour / the oracle's rate against that very partner); IQM with its 95% "
        "stratified-bootstrap CI over seeds within each partner. Headroom: 1 - IQM over the held-out partners "
        "of the cooperative model's optimal policy played with them (exact, `hg-marl headroom`): what knowing "
        "one's partner is worth on that scenario.",
        "",
        "| scenario | headroom | split | robot | BR-Prox IQM | 95% CI | runs |",
        "|---|---:|---|---|---:|---|---:|",
    ]
    for r in rows:
        name = Path(r["scenario"]).name
        lines.append(
            f"| {name} | {_num(headrooms.get(r['scenario']))} | {r['split']} | {r['robot']} | {r['iqm']:.2f} | "
            f"{_ci(r['ci'])} | {r['runs']} |"
        )
    return [*lines, ""]


def markdown(
    study: Study,
    frame: pd.DataFrame,
    agg: dict[str, Any],
    stats: dict[str, int],
    headrooms: dict[str, float | None] | None = None,
) -> str:
    """``report.md``."""
    flag = agg["bootstrap"]["flag"]
    parts = [
        f"# Study {study.name}",
        "",
        f"{len(frame)} runs: {frame['robot'].nunique()} robots x {frame['human'].nunique()} humans x "
        f"{len(study.scenarios)} scenario(s) x {len(study.seeds)} seeds, {study.duration:g} simulated s each "
        f"({stats['ran']} run now, {stats['reused']} reused from the store). Score = tasks per hour / the "
        "reference rate of that human and scenario (the oracle's optimum, or where it cannot be computed the "
        "best robot's mean rate: see the reference table). Intervals: 95% stratified bootstrap over seeds "
        f"within each (human, scenario), {agg['bootstrap']['reps']} replications "
        f"({agg['bootstrap']['poi_reps']} for the probability of improvement; rliable's method).",
        "",
        *([f"**Caution: {flag}.**", ""] if flag else []),
        "## Per robot",
        "",
        robot_table(agg),
        "",
        "## Mean score, robots x humans",
        "",
        crossplay_table(frame),
        "",
    ]
    parts += br_prox_section(agg, headrooms or {})
    if "generalisation" in agg:
        parts += [
            "## Generalisation to held-out partners",
            "",
            f"Train partners: {', '.join(study.train)}. Test partners: {', '.join(study.test)}.",
            "",
            "| robot | IQM train | IQM test | gap (train - test) | 95% CI |",
            "|---|---:|---:|---:|---|",
        ]
        for r, g in agg["generalisation"].items():
            parts.append(f"| {r} | {g['train_iqm']:.2f} | {g['test_iqm']:.2f} | {g['gap']:.2f} | {_ci(g['gap_ci'])} |")
        parts.append("")
    pairs = agg["improvement"]
    clear = {k: v for k, v in pairs.items() if v["ci"] is not None and (v["ci"][0] > 0.5 or v["ci"][1] < 0.5)}
    parts += ["## Probability of improvement", ""]
    if pairs and all(v["ci"] is None for v in pairs.values()):
        parts += [
            f"No interval with {agg['bootstrap']['seeds_per_task']} seed per task, so no pair can be called "
            f"clearly better; the {len(pairs)} point estimates are in aggregate.json.",
            "",
        ]
    else:
        parts += [
            f"{len(clear)} of {len(pairs)} pairs have a 95% CI that excludes 0.5 (all pairs in aggregate.json)"
            + (f" ({flag})" if flag else "")
            + ":",
            "",
            "| pair | P(A > B) | 95% CI |",
            "|---|---:|---|",
            *[f"| {k} | {v['p']:.2f} | {_ci(v['ci'])} |" for k, v in clear.items()],
            "",
        ]
    parts += [
        "Figures: crossplay.png, profiles.png, intervals.png. Every run: scores.csv (its key names its "
        "entry in store/).",
        "",
    ]
    return "\n".join(parts)


def write_outputs(
    study: Study,
    frame: pd.DataFrame,
    out: Path,
    stats: dict[str, int],
    headrooms: dict[str, float | None] | None = None,
) -> dict[str, Any]:
    """Write every output of a study into ``out``; return the aggregates (with the scenarios' headroom).

    The returned dict also holds ``seconds`` (the aggregation's wall time, which the CLI
    prints; not written to ``aggregate.json``, which stays a function of the scores).
    """
    import time

    atomic_write(out / "scores.csv", lambda tmp: frame.to_csv(tmp, index=False, float_format="%.10g"))
    groups = {h: study.group(h) for h in frame["human"].unique() if study.group(h)}
    start = time.perf_counter()
    agg = aggregate(frame, groups or None)
    agg["headroom"] = dict(headrooms or {})
    seconds = time.perf_counter() - start
    write_json(out / "aggregate.json", agg)
    crossplay_png(frame, out / "crossplay.png", f"{study.name}: mean score")
    if frame["score"].notna().any():
        profiles_png(frame, out / "profiles.png")
        intervals_png(agg, out / "intervals.png")
    write_text(out / "report.md", markdown(study, frame, agg, stats, headrooms))
    return {**agg, "seconds": seconds}
