"""The comparison's configuration and summary: fractions of the oracle with intervals over seeds.

Kept apart from :mod:`hg_marl.training.baselines.compare` (which trains, so imports
torch and SB3) so that the command line reads its defaults without importing them.

Per (algorithm, human) row: the final rate's fraction of the oracle (mean over training
seeds) with its 95% percentile-bootstrap interval over those seeds, the best fraction,
and the steps to reach 50% and 90% (median; None when a seed never did). Across humans,
:func:`aggregates` gives each algorithm's IQM and mean with rliable's stratified
bootstrap, and the probability that one algorithm improves on another.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from hg_marl.core.errors import ConfigError, check_bool, check_finite, check_int
from hg_marl.training.aggregate import aggregate
from hg_marl.training.baselines.envs import DEFAULT_MAX_CYCLES
from hg_marl.training.baselines.evaluation import steps_to_reach
from hg_marl.training.regret import bootstrap_ci

BASELINE_ROBOTS: dict[str, dict[str, Any]] = {"planner": {}, "hybrid": {"criterion": "entropy_and_cost"}}
"""Robots scored next to the SB3 algorithms: registry name -> parameters."""


@dataclass(frozen=True)
class CompareConfig:
    """A comparison: algorithms x humans x seeds at a fixed budget."""

    algos: tuple[str, ...] = ("ppo", "maskable_ppo", "dqn", "a2c")
    """Algorithms to train."""
    humans: tuple[str, ...] = ("cooperative", "lazy", "no_handover")
    """Humans, one training per human (not a population)."""
    scenario: str = "paper2015"
    """Scenario spec."""
    steps: int = 20_000
    """Training budget per cell, in environment steps."""
    seeds: int = 3
    """Training seeds per (algorithm, human): 0 .. seeds-1 (the intervals need at least 2)."""
    eval_every: int = 2_000
    """Steps between runner evaluations."""
    eval_seeds: tuple[int, ...] = (100, 101)
    """Runner seeds of every evaluation (robots and SB3 models alike)."""
    duration: float = 1200.0
    """Simulated seconds per evaluation run (the paper's 20 minutes)."""
    deterministic: bool = False
    """Evaluate SB3 policies greedily (True) or by sampling their distribution with the robot's
    own generator (False, default: a greedy policy trained on facts that do not show
    everything can loop forever, e.g. both agents waiting, and score 0 until late in
    training; sampling is what the policy-gradient algorithms optimise). DQN is greedy either way."""
    max_cycles: int = DEFAULT_MAX_CYCLES
    """Training episode length."""
    out: Path = Path("runs/compare")
    """Output directory."""

    def __post_init__(self) -> None:
        if not self.algos or not self.humans:
            raise ConfigError("algos (--algos) and humans (--humans): expected at least one name each")
        check_int(self.steps, "steps (--steps)", minimum=1)
        check_int(self.seeds, "seeds (--seeds)", minimum=1)
        check_int(self.eval_every, "eval_every (--eval-every)", minimum=1)
        if not self.eval_seeds:
            raise ConfigError("eval_seeds (--eval-seeds): expected at least one evaluation seed")
        for seed in self.eval_seeds:
            check_int(seed, "eval_seeds (--eval-seeds)", minimum=0)
        check_finite(self.duration, "duration (--duration)", positive=True)
        check_bool(self.deterministic, "deterministic (--deterministic)")
        check_int(self.max_cycles, "max_cycles", minimum=1)


def _fraction(rate: float | None, oracle: float | None) -> float | None:
    return None if rate is None or not oracle else rate / oracle


def summarise(
    config: CompareConfig, cells: Sequence[dict[str, Any]], references: dict[str, dict[str, float | None]]
) -> list[dict[str, Any]]:
    """One row per (algorithm or baseline robot, human)."""
    rows: list[dict[str, Any]] = []
    for human in config.humans:
        ref = references[human]
        oracle = ref.get("oracle")
        for name in BASELINE_ROBOTS:
            rows.append(
                {
                    "agent": name,
                    "human": human,
                    "rate": ref.get(name),
                    "oracle": oracle,
                    "fraction": _fraction(ref.get(name), oracle),
                    "best_fraction": None,
                    "fraction_ci": None,
                    "steps_to_50": None,
                    "steps_to_90": None,
                    "seeds": len(config.eval_seeds),
                }
            )
        for algo in config.algos:
            mine = [c for c in cells if c["algo"] == algo and c["human"] == human]
            if not mine:
                continue
            finals = [c["curve"][-1][1] for c in mine]
            bests = [max(r for _, r in c["curve"]) for c in mine]
            row: dict[str, Any] = {
                "agent": algo,
                "human": human,
                "rate": float(np.mean(finals)),
                "oracle": oracle,
                "fraction": _fraction(float(np.mean(finals)), oracle),
                "fraction_ci": _seed_interval([r / oracle for r in finals]) if oracle else None,
                "best_fraction": _fraction(float(np.mean(bests)), oracle),
                "seeds": len(mine),
            }
            for level in (50, 90):
                reached = [steps_to_reach(c["curve"], level / 100 * oracle) for c in mine] if oracle else [None]
                row[f"steps_to_{level}"] = (
                    None if any(s is None for s in reached) else float(np.median([s for s in reached if s is not None]))
                )
            rows.append(row)
    return rows


def _seed_interval(fractions: Sequence[float]) -> list[float] | None:
    """Percentile-bootstrap 95% CI of the mean over training seeds (None with one seed)."""
    if len(fractions) < 2:
        return None
    _, low, high = bootstrap_ci(fractions)
    return [low, high]


def _fmt_ci(ci: Sequence[float] | None) -> str:
    return "-" if ci is None else f"[{ci[0]:.2f}, {ci[1]:.2f}]"


def aggregates(
    config: CompareConfig, cells: Sequence[dict[str, Any]], oracles: dict[str, float | None]
) -> dict[str, Any]:
    """rliable over every algorithm's final fractions: IQM and mean with stratified-bootstrap CIs.

    A task is a human (with an oracle rate), a run a training seed; the probability of
    improvement is given for each pair of algorithms (see :mod:`hg_marl.training.aggregate`).
    Empty with fewer than two training seeds (no interval to draw) or no oracle rate.
    """
    rows = [
        {
            "robot": c["algo"],
            "human": c["human"],
            "scenario": config.scenario,
            "seed": c["seed"],
            "score": c["curve"][-1][1] / oracle,
        }
        for c in cells
        if (oracle := oracles.get(c["human"]))
    ]
    if config.seeds < 2 or not rows:
        return {}
    return aggregate(pd.DataFrame(rows))


def format_table(rows: Sequence[dict[str, Any]]) -> str:
    """A fixed-width text table of the summary rows."""

    def fmt(value: Any, spec: str) -> str:
        if value is None or (isinstance(value, float) and math.isnan(value)):
            return "-"
        return format(value, spec)

    header = (
        f"{'agent':<13}{'human':<16}{'tasks/h':>9}{'oracle':>9}{'frac':>7}{'95% CI':>14}{'best':>7}"
        f"{'to 50%':>9}{'to 90%':>9}"
    )
    lines = [header, "-" * len(header)]
    for r in rows:
        lines.append(
            f"{r['agent']:<13}{r['human']:<16}{fmt(r['rate'], '.1f'):>9}{fmt(r['oracle'], '.1f'):>9}"
            f"{fmt(r['fraction'], '.2f'):>7}{_fmt_ci(r.get('fraction_ci')):>14}{fmt(r['best_fraction'], '.2f'):>7}"
            f"{fmt(r['steps_to_50'], '.0f'):>9}{fmt(r['steps_to_90'], '.0f'):>9}"
        )
    return "\n".join(lines)


def format_aggregate(result: dict[str, Any]) -> str:
    """The rliable aggregate as text lines (empty without one)."""
    lines = [
        f"{name:<13} IQM {r['iqm']:.2f} {_fmt_ci(r['iqm_ci'])}  mean {r['mean']:.2f} {_fmt_ci(r['mean_ci'])}"
        for name, r in result.get("robots", {}).items()
        if r["iqm"] is not None
    ]
    lines += [f"P({pair}) = {v['p']:.2f} {_fmt_ci(v['ci'])}" for pair, v in result.get("improvement", {}).items()]
    return "\n".join(lines)
