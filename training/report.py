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


def crossplay_png(frame: pd.DataFrame, path: Path, title: str) -> Path:
    """Annotated heatmap of mean score, robots x humans."""
    plt = _pyplot()
    table = mean_table(frame)
    fig, ax = plt.subplots(figsize=(1.2 * len(table.columns) + 2.5, 0.55 * len(table.index) + 1.8))
    values = table.to_numpy(dtype=float)
    image = ax.imshow(np.nan_to_num(values, nan=0.0), cmap="viridis", vmin=0.0, vmax=max(1.0, np.nanmax(values)))
    ax.set_xticks(range(len(table.columns)), table.columns, rotation=35, ha="right")
    ax.set_yticks(range(len(table.index)), table.index)
    for i in range(values.shape[0]):
        for j in range(values.shape[1]):
            text = "n/a" if np.isnan(values[i, j]) else f"{values[i, j]:.2f}"
            ax.text(j, i, text, ha="center", va="center", color="white" if values[i, j] < 0.6 else "black")
    fig.colorbar(image, ax=ax, label="score (tasks/h / reference rate)")
    ax.set_title(title)
    fig.tight_layout()
    atomic_write(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))
    plt.close(fig)
    return path


def profiles_png(frame: pd.DataFrame, path: Path) -> Path:
    """rliable performance profiles: fraction of runs above each score threshold."""
    from rliable import plot_utils

    plt = _pyplot()
    top = float(np.nanmax(frame["score"].to_numpy(dtype=float))) if frame["score"].notna().any() else 1.0
    taus = np.linspace(0.0, max(1.0, top) * 1.05, 61)
    curves, bands = profiles(frame, taus)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    plot_utils.plot_performance_profiles(
        curves, taus, performance_profile_cis=bands, ax=ax, xlabel=r"score $\tau$", ylabel=r"fraction of runs > $\tau$"
    )
    ax.legend(loc="upper right", fontsize="small")
    fig.tight_layout()
    atomic_write(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))
    plt.close(fig)
    return path


def intervals_png(agg: dict[str, Any], path: Path) -> Path:
    """IQM and mean per robot with their 95% stratified-bootstrap intervals (rliable's plot)."""
    from rliable import plot_utils

    plt = _pyplot()
    rows = {r: v for r, v in agg["robots"].items() if v["iqm"] is not None}
    point = {r: np.array([v["iqm"], v["mean"]]) for r, v in rows.items()}
    ci = {r: np.array([[v["iqm_ci"][0], v["mean_ci"][0]], [v["iqm_ci"][1], v["mean_ci"][1]]]) for r, v in rows.items()}
    fig, _ = plot_utils.plot_interval_estimates(
        point, ci, metric_names=["IQM", "Mean"], algorithms=list(rows), xlabel="score", row_height=0.6
    )
    atomic_write(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png", bbox_inches="tight"))
    plt.close(fig)
    return path


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
    parts = [
        f"# Study {study.name}",
        "",
        f"{len(frame)} runs: {frame['robot'].nunique()} robots x {frame['human'].nunique()} humans x "
        f"{len(study.scenarios)} scenario(s) x {len(study.seeds)} seeds, {study.duration:g} simulated s each "
        f"({stats['ran']} run now, {stats['reused']} reused from the store). Score = tasks per hour / the "
        "reference rate of that human and scenario (the oracle's optimum, or where it cannot be computed the "
        "best robot's mean rate: see the reference table). Intervals: 95% stratified bootstrap over seeds "
        f"within each (human, scenario), {agg['bootstrap']['reps']} replications "
        f"({agg['bootstrap']['poi_reps']} for the probability of improvement; rliable).",
        "",
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
    clear = {k: v for k, v in agg["improvement"].items() if v["ci"][0] > 0.5 or v["ci"][1] < 0.5}
    parts += [
        "## Probability of improvement",
        "",
        f"{len(clear)} of {len(agg['improvement'])} pairs have a 95% CI that excludes 0.5 "
        "(all pairs in aggregate.json):",
        "",
        "| pair | P(A > B) | 95% CI |",
        "|---|---:|---|",
        *[f"| {k} | {v['p']:.2f} | {_ci(v['ci'])} |" for k, v in clear.items()],
        "",
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
    """Write every output of a study into ``out``; return the aggregates (with the scenarios' headroom)."""
    atomic_write(out / "scores.csv", lambda tmp: frame.to_csv(tmp, index=False, float_format="%.10g"))
    groups = {h: study.group(h) for h in frame["human"].unique() if study.group(h)}
    agg = aggregate(frame, groups or None)
    agg["headroom"] = dict(headrooms or {})
    write_json(out / "aggregate.json", agg)
    crossplay_png(frame, out / "crossplay.png", f"{study.name}: mean score")
    if frame["score"].notna().any():
        profiles_png(frame, out / "profiles.png")
        intervals_png(agg, out / "intervals.png")
    write_text(out / "report.md", markdown(study, frame, agg, stats, headrooms))
    return agg
