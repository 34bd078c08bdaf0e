"""The headroom instrument's outputs: the matrix as CSV, a heatmap and ``headroom.json``.

:func:`~hg_marl.agents.headroom.headroom` computes the matrix; this module writes it
(``hg-marl headroom`` calls :func:`write_headroom`). Which partners: a population
file's members (columns: every member; the headroom number over its ``held_out``
split), or a list of human specs (columns and headroom number: all of them). The rows
are the cooperative model, then every column's partner.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.headroom import HeadroomResult, headroom
from hg_marl.training.io import atomic_write, write_json


def partners(population: str | Path | None, humans: Sequence[str]) -> tuple[list[tuple[str, str]], list[str]]:
    """(label, spec) columns and the held-out labels, from a population file or a list of specs.

    Raises:
        PopulationError: a bad population file (``path:line``).
        ConfigError: neither or both given, or a human spec that is not a stationary human.
    """
    from hg_marl.agents.humans.population import _check_spec, load_population
    from hg_marl.core.errors import ConfigError

    if (population is None) == (not humans):
        raise ConfigError("give exactly one of --population and --humans")
    if population is not None:
        pop = load_population(population)
        return [(m.name, m.spec) for m in pop.members()], [m.name for m in pop.held_out]
    for spec in humans:
        problem = _check_spec(spec)
        if problem:
            raise ConfigError(f"--humans {spec}: {problem}")
    if len(set(humans)) != len(humans):
        raise ConfigError("--humans: a human is listed twice")
    return [(h, h) for h in humans], list(humans)


def matrix_csv(result: HeadroomResult, path: Path) -> Path:
    """Rows: assumed partner; columns: true partner; cells: ratio to the optimum (empty: n/a)."""
    import pandas as pd

    frame = pd.DataFrame(result.ratio, index=list(result.assumed), columns=list(result.true))
    frame.index.name = "assumed \\ true"
    atomic_write(path, lambda tmp: frame.to_csv(tmp, float_format="%.6f"))
    return path


def heatmap_png(result: HeadroomResult, path: Path) -> Path:
    """Annotated heatmap of the matrix; cells without an optimum are grey and read n/a."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    values = result.ratio
    fig, ax = plt.subplots(figsize=(1.0 * len(result.true) + 3.5, 0.5 * len(result.assumed) + 2.2))
    cmap = matplotlib.colormaps["viridis"].with_extremes(bad="lightgrey")
    image = ax.imshow(np.ma.masked_invalid(values), cmap=cmap, vmin=0.0, vmax=1.0, aspect="auto")
    ax.set_xticks(range(len(result.true)), result.true, rotation=35, ha="right")
    ax.set_yticks(range(len(result.assumed)), result.assumed)
    ax.set_xlabel("true partner (plays with the robot)")
    ax.set_ylabel("assumed partner (the policy is optimal against)")
    for i in range(values.shape[0]):
        for j in range(values.shape[1]):
            v = values[i, j]
            text, colour = ("n/a", "black") if np.isnan(v) else (f"{v:.2f}", "white" if v < 0.6 else "black")
            ax.text(j, i, text, ha="center", va="center", color=colour, fontsize="small")
    fig.colorbar(image, ax=ax, label="rate / optimal rate with the true partner")
    ax.set_title(f"{result.scenario}: adaptation headroom {result.headroom:.2f}")
    fig.tight_layout()
    atomic_write(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))
    plt.close(fig)
    return path


def summary(result: HeadroomResult) -> dict[str, Any]:
    """``headroom.json``: the number, the rates and the model's size."""
    return {
        "scenario": result.scenario,
        "headroom": None if np.isnan(result.headroom) else result.headroom,
        "held_out": list(result.held_out),
        "assumed": list(result.assumed),
        "true": list(result.true),
        "optimal_rate": result.optimum.tolist(),
        "rates": result.rates.tolist(),
        "n_states": result.n_states,
        "seconds": result.seconds,
    }


def write_headroom(
    scenario: str, columns: list[tuple[str, str]], held_out: list[str], out: Path, progress: bool = True, **budget: Any
) -> HeadroomResult:
    """Compute the matrix and write ``headroom.csv``, ``headroom.png`` and ``headroom.json`` into ``out``."""
    result = headroom(scenario, columns, held_out, progress=progress, **budget)
    out.mkdir(parents=True, exist_ok=True)
    matrix_csv(result, out / "headroom.csv")
    heatmap_png(result, out / "headroom.png")
    write_json(out / "headroom.json", summary(result))
    return result
