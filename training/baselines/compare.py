"""Compare SB3 algorithms with the paper's robots on the same protocol, as a fraction of the oracle.

For each (algorithm, human, seed) *cell*: train for a fixed step budget against that
human and, every ``eval_every`` steps (and at step 0), score the model on the runner's
protocol (continuing play, ``duration`` simulated seconds, decision time charged, the
same evaluation seeds for everyone). Each cell is a training job of the content-addressed
store in ``OUT/store`` (:mod:`hg_marl.training.store`), keyed by everything that makes it
(:func:`cell_fields`: algorithm, human, seed, scenario content, budget, evaluation
protocol, the trainer's sources and hyperparameter files, the SB3 and torch versions),
written as soon as it finishes; an interrupted comparison resumes where it stopped, and
a changed setting never reuses an old cell.

The summary puts, per (algorithm, human): the final and best rate as a fraction of the
oracle's (mean over seeds), and the environment steps to first reach 50% and 90% of the
oracle rate (median over seeds; None when a seed never reached it, so "never" is not
averaged away), next to the planner's and the hybrid robot's (``entropy_and_cost``)
fractions on the same humans and evaluation seeds. The oracle is computed once per
human (None for a non-stationary human).
"""

from __future__ import annotations

import hashlib
import logging
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.training.baselines.callbacks import RateCurve
from hg_marl.training.baselines.envs import DEFAULT_MAX_CYCLES, EnvSpec
from hg_marl.training.baselines.evaluation import actor_rate, runner_rate, steps_to_reach
from hg_marl.training.baselines.train import TrainConfig, train
from hg_marl.training.io import write_json
from hg_marl.training.store import content_key, scenario_content
from hg_marl.training.sweep import store_of

log = logging.getLogger(__name__)

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
    seeds: int = 1
    """Training seeds per (algorithm, human): 0 .. seeds-1."""
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


def _trainer_fingerprint() -> dict[str, str]:
    """What the trainer is: its sources, its hyperparameter files, the learning libraries' versions."""
    import stable_baselines3
    import torch

    here = Path(__file__).parent
    digest = hashlib.sha256()
    for f in sorted([*here.glob("*.py"), *(here.parent / "hyperparams").glob("*.yml")]):
        digest.update(f.name.encode())
        digest.update(f.read_bytes())
    return {"sources": digest.hexdigest(), "sb3": stable_baselines3.__version__, "torch": str(torch.__version__)}


def cell_fields(config: CompareConfig, algo: str, human: str, seed: int) -> dict[str, Any]:
    """Everything that determines a cell's result (its key in the store)."""
    return {
        "algo": algo,
        "human": human,
        "seed": seed,
        "scenario": scenario_content(config.scenario),
        "steps": config.steps,
        "eval_every": config.eval_every,
        "eval_seeds": list(config.eval_seeds),
        "duration": config.duration,
        "deterministic": config.deterministic,
        "max_cycles": config.max_cycles,
        "trainer": _trainer_fingerprint(),
    }


def run_cell(config: CompareConfig, algo: str, human: str, seed: int, directory: Path) -> dict[str, Any]:
    """Train one cell with runner evaluations (the model goes to ``directory``); return its record."""
    spec = EnvSpec(seat="robot", partners=(human,), scenario=config.scenario, max_cycles=config.max_cycles)

    def evaluate(model: Any) -> float:
        return runner_rate(
            model,
            spec.observation,
            human,
            config.scenario,
            config.duration,
            config.eval_seeds,
            deterministic=config.deterministic,
        )

    curve = RateCurve(config.eval_every, evaluate)
    result = train(
        TrainConfig(
            algo=algo,
            env=spec,
            steps=config.steps,
            seed=seed,
            out=directory,
            eval_freq=0,
            checkpoint_freq=0,
            tensorboard=False,
        ),
        callbacks=[curve],
    )
    if not curve.curve or curve.curve[-1][0] != result.num_timesteps:
        curve.curve.append((result.num_timesteps, evaluate(result.model)))
    record = {
        "algo": algo,
        "human": human,
        "seed": seed,
        "scenario": config.scenario,
        "budget": config.steps,
        "deterministic": config.deterministic,
        "steps": result.num_timesteps,
        "eval_seeds": list(config.eval_seeds),
        "duration": config.duration,
        "train_seconds": result.seconds,
        "steps_per_second": result.steps_per_second,
        "curve": [[s, r] for s, r in curve.curve],
        "model": str(result.path),
    }
    return record


def reference_rates(config: CompareConfig, human: str) -> dict[str, float | None]:
    """The oracle's and the baseline robots' tasks per hour against ``human`` (cached in the store)."""
    fields = {
        "human": human,
        "scenario": scenario_content(config.scenario),
        "duration": config.duration,
        "eval_seeds": list(config.eval_seeds),
        "robots": BASELINE_ROBOTS,
    }
    rates: dict[str, float | None] = store_of(config.out).cached(
        "compare_reference", fields, lambda: _reference_rates(config, human)
    )
    return rates


def _reference_rates(config: CompareConfig, human: str) -> dict[str, float | None]:
    from hg_marl.agents.humans import HumanError
    from hg_marl.agents.oracle import OracleTooLarge, oracle_rate
    from hg_marl.agents.robots import make_robot

    rates: dict[str, float | None] = {}
    try:
        rates["oracle"] = oracle_rate(config.scenario, human).rate_per_hour
    except (HumanError, OracleTooLarge) as exc:
        log.warning("no oracle for %s: %s", human, exc)
        rates["oracle"] = None
    for name, params in BASELINE_ROBOTS.items():

        def build(name: str = name, params: dict[str, Any] = params) -> Any:
            return make_robot(name, **params)

        rates[name] = actor_rate(build, human, config.scenario, config.duration, config.eval_seeds)
    return rates


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


def format_table(rows: Sequence[dict[str, Any]]) -> str:
    """A fixed-width text table of the summary rows."""

    def fmt(value: Any, spec: str) -> str:
        if value is None or (isinstance(value, float) and math.isnan(value)):
            return "-"
        return format(value, spec)

    header = f"{'agent':<13}{'human':<16}{'tasks/h':>9}{'oracle':>9}{'frac':>7}{'best':>7}{'to 50%':>9}{'to 90%':>9}"
    lines = [header, "-" * len(header)]
    for r in rows:
        lines.append(
            f"{r['agent']:<13}{r['human']:<16}{fmt(r['rate'], '.1f'):>9}{fmt(r['oracle'], '.1f'):>9}"
            f"{fmt(r['fraction'], '.2f'):>7}{fmt(r['best_fraction'], '.2f'):>7}"
            f"{fmt(r['steps_to_50'], '.0f'):>9}{fmt(r['steps_to_90'], '.0f'):>9}"
        )
    return "\n".join(lines)


def compare(config: CompareConfig, on_cell: Callable[[str], None] | None = None) -> dict[str, Any]:
    """Run (or resume) every cell, score the references, write ``OUT/summary.json``.

    Args:
        config: the comparison.
        on_cell: called with a label before each cell (progress reporting in the CLI).

    Returns:
        ``{"config": ..., "rows": [...], "cells": [...]}`` (also written to ``summary.json``).
    """
    cells: list[dict[str, Any]] = []
    store = store_of(config.out)
    references = {human: reference_rates(config, human) for human in config.humans}
    for algo in config.algos:
        for human in config.humans:
            for seed in range(config.seeds):
                fields = cell_fields(config, algo, human, seed)
                directory = config.out / "models" / content_key("compare_cell", fields)[:16]

                def cell(algo: str = algo, human: str = human, seed: int = seed, directory: Path = directory) -> Any:
                    if on_cell is not None:
                        on_cell(f"{algo} vs {human} seed {seed}")
                    return run_cell(config, algo, human, seed, directory)

                cells.append(store.cached("compare_cell", fields, cell))
    rows = summarise(config, cells, references)
    summary = {
        "config": {k: (str(v) if isinstance(v, Path) else v) for k, v in vars(config).items()},
        "rows": rows,
        "references": references,
        "cells": cells,
    }
    write_json(config.out / "summary.json", summary)
    return summary
