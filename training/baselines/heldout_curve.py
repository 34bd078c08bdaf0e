"""The generalisation curve of a ``ppo_recurrent`` run: train vs held-out partners at each checkpoint.

Why. ``curve.csv`` shows the rate against the training partners only (and with the
recipe's noise). Whether the robot generalises shows in the gap between that and its
score against partners it never met, drawn against steps. At each checkpoint
(``checkpoint_freq``), :class:`HeldOutCurve` plays the current policy greedily against
each partner, train and held-out alike, on ``eval_envs`` fresh tables for
``eval_seconds`` simulated seconds (the protocol of ``greedy_rate``), and divides by the
exact best response's rate when the oracle can solve that partner (BR-Prox,
``min(1, rate / oracle rate)``); otherwise (or when the oracle itself solves nothing) the
BR-Prox cell is empty and that partner is left out of the split's mean BR-Prox.

File ``curve_heldout.csv``, one row per (checkpoint, partner)::

    steps,split,partner,tasks_per_hour,oracle_per_hour,br_prox

:func:`plot_generalisation` draws the mean over each split's partners against steps
(``generalisation.png``).
"""

from __future__ import annotations

import csv
import io
import logging
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.model_file import atomic_write_bytes
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig, greedy_rate, make_env

log = logging.getLogger(__name__)

COLUMNS = ("steps", "split", "partner", "tasks_per_hour", "oracle_per_hour", "br_prox")
SPLITS = ("train", "held_out")
EVAL_SEED = 20_000
"""Evaluation tables are seeded apart from training (``seed + 10_000``) and the final score."""


def oracle_per_hour(scenario: str, partner: str) -> float | None:
    """The exact best response's tasks per hour against ``partner`` (None: the oracle cannot solve it)."""
    from hg_marl.agents.oracle import oracle_rate

    try:
        return float(oracle_rate(scenario, partner).rate_per_hour)
    except Exception as exc:  # a partner the oracle refuses (non-stationary, over budget): no BR-Prox
        log.warning("no oracle rate for %s on %s (%s): tasks per hour only", partner, scenario, exc)
        return None


def held_out_members(path: Path) -> tuple[str, ...]:
    """The ``held_out`` members' specs of a population file (none: no held-out curve)."""
    from hg_marl.agents.humans.population import load_population

    return tuple(str(m.spec) for m in load_population(path).held_out)


class HeldOutCurve:
    """An ``on_update`` hook for ``train_recurrent``: scores every partner at each checkpoint, writes the CSV."""

    def __init__(self, config: RecurrentConfig, held_out: tuple[str, ...], every: int, *, oracle: bool = True) -> None:
        self.config = config
        self.every = every
        self.partners = [("train", p) for p in config.humans] + [("held_out", p) for p in held_out]
        self.oracle = {p: (oracle_per_hour(config.scenario, p) if oracle else None) for _, p in self.partners}
        self.envs = {
            p: make_env(replace(config, humans=(p,), recipe="members"), config.eval_envs) for _, p in self.partners
        }
        self.rows: list[tuple[Any, ...]] = []
        self.next = every
        self.path = config.out / "curve_heldout.csv"

    def __call__(self, steps: int, net: Any) -> None:
        if steps < self.next:
            return
        self.next = (steps // self.every + 1) * self.every
        for split, partner in self.partners:
            rate = greedy_rate(net, self.envs[partner], self.config.eval_seconds, self.config.seed + EVAL_SEED)
            best = self.oracle[partner]
            prox = min(1.0, rate / best) if best else None
            self.rows.append(
                (
                    steps,
                    split,
                    partner,
                    round(rate, 3),
                    None if best is None else round(best, 3),
                    None if prox is None else round(prox, 4),
                )
            )
        self.write()

    def write(self) -> Path:
        text = io.StringIO()
        writer = csv.writer(text, lineterminator="\n")
        writer.writerow(COLUMNS)
        writer.writerows(["" if v is None else v for v in row] for row in self.rows)
        atomic_write_bytes(self.path, text.getvalue().encode())
        return self.path


def _mean_scored(cells: list[str]) -> float:
    """Mean over the partners that have a BR-Prox (an oracle that solves nothing gives none); NaN if none has."""
    scored = [float(c) for c in cells if c]
    return float(np.mean(scored)) if scored else float("nan")


def read_curve(path: Path) -> dict[str, dict[str, np.ndarray]]:
    """Per split: ``steps``, the mean ``tasks_per_hour`` and the mean ``br_prox`` of the partners that have one."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    out: dict[str, dict[str, np.ndarray]] = {}
    for split in SPLITS:
        mine = [r for r in rows if r["split"] == split]
        steps = sorted({int(r["steps"]) for r in mine})
        rate = [np.mean([float(r["tasks_per_hour"]) for r in mine if int(r["steps"]) == s]) for s in steps]
        prox = [_mean_scored([r["br_prox"] for r in mine if int(r["steps"]) == s]) for s in steps]
        out[split] = {"steps": np.asarray(steps), "tasks_per_hour": np.asarray(rate), "br_prox": np.asarray(prox)}
    return out


def plot_generalisation(csv_path: Path, png: Path, title: str = "") -> Path:
    """Train vs held-out partners against steps (BR-Prox when every checkpoint has one, else tasks per hour)."""
    from hg_marl.training.plots import _pyplot, _save

    curves = read_curve(csv_path)
    use_prox = all(len(c["br_prox"]) and not np.isnan(c["br_prox"]).any() for c in curves.values() if len(c["steps"]))
    key, label = ("br_prox", "BR-Prox (mean over partners)") if use_prox else ("tasks_per_hour", "tasks per hour")
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 3.6))
    styles = {"train": ("tab:blue", "train partners"), "held_out": ("tab:orange", "held-out partners")}
    for split, curve in curves.items():
        if len(curve["steps"]):
            colour, name = styles[split]
            ax.plot(curve["steps"], curve[key], marker="o", color=colour, label=name)
    if len(curves["train"]["steps"]) and len(curves["held_out"]["steps"]):
        ax.fill_between(
            curves["train"]["steps"],
            curves["train"][key],
            curves["held_out"][key],
            color="grey",
            alpha=0.2,
            label="generalisation gap",
        )
    if use_prox:
        ax.set_ylim(0.0, 1.05)
    ax.set_xlabel("environment steps")
    ax.set_ylabel(label)
    ax.set_title(title or "greedy policy at each checkpoint")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8, frameon=False)
    return _save(fig, png)
