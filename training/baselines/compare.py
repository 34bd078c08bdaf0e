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
from collections.abc import Callable
from pathlib import Path
from typing import Any

from hg_marl.agents.content import scenario_content
from hg_marl.training.baselines.callbacks import RateCurve
from hg_marl.training.baselines.comparison import BASELINE_ROBOTS, CompareConfig, aggregates, summarise
from hg_marl.training.baselines.envs import EnvSpec
from hg_marl.training.baselines.evaluation import actor_rate, runner_rate
from hg_marl.training.baselines.train import TrainConfig, train
from hg_marl.training.io import write_json
from hg_marl.training.store import content_key
from hg_marl.training.sweep import store_of

log = logging.getLogger(__name__)


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

    if algo == "ppo_batched":
        return _run_batched_cell(config, human, seed, directory, evaluate)
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
    if result.interrupted:
        # A cell stopped by a signal is not a result: nothing is stored for it and the
        # comparison stops (the cells before it are in the store, so the same command
        # goes on from this cell). Otherwise one Ctrl-C stopped one cell and the next began.
        raise KeyboardInterrupt(f"{algo} vs {human} seed {seed}: stopped at {result.num_timesteps} steps")
    if not curve.curve or curve.curve[-1][0] != result.num_timesteps:
        curve.curve.append((result.num_timesteps, evaluate(result.model)))
    return _record(config, algo, human, seed, result, curve.curve)


def _record(
    config: CompareConfig, algo: str, human: str, seed: int, result: Any, curve: list[tuple[int, float]]
) -> dict[str, Any]:
    """One cell's record (every algorithm's the same fields, so the table and plots read them alike)."""
    return {
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
        "curve": [[s, r] for s, r in curve],
        "model": str(result.path),
    }


def _run_batched_cell(config: CompareConfig, human: str, seed: int, directory: Path, evaluate: Any) -> dict[str, Any]:
    """A ``ppo_batched`` cell: the batched learner, evaluated on the same runner protocol."""
    from hg_marl.training.baselines.ppo_batched import PPOBatchedConfig, train_ppo_batched

    curve: list[tuple[int, float]] = []
    due = [0]

    def on_update(steps: int, model: Any) -> None:
        if steps >= due[0]:
            curve.append((steps, float(evaluate(model))))
            due[0] = (steps // config.eval_every + 1) * config.eval_every

    batched = PPOBatchedConfig(
        humans=(human,), scenario=config.scenario, steps=config.steps, seed=seed, out=directory, tensorboard=False
    )
    result = train_ppo_batched(batched, on_update)
    if curve[-1][0] != result.num_timesteps:
        curve.append((result.num_timesteps, float(evaluate(result_model(result.path)))))
    return _record(config, "ppo_batched", human, seed, result, curve)


def result_model(path: Path) -> Any:
    """The SB3 model of a saved model file (for a last evaluation)."""
    from hg_marl.agents.model_file import build_sb3, load_model_file

    return build_sb3(load_model_file(path), optimizer=False)


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


def compare(config: CompareConfig, on_cell: Callable[[str], None] | None = None) -> dict[str, Any]:
    """Run (or resume) every cell, score the references, write ``OUT/summary.json``.

    Args:
        config: the comparison.
        on_cell: called with a label before each cell (progress reporting in the CLI).

    Returns:
        ``{"config": ..., "rows": [...], "aggregate": {...}, "references": {...}, "cells": [...]}``
        (also written to ``summary.json``); ``aggregate`` has the shape of a study's
        ``aggregate.json`` (per algorithm IQM and mean with 95% CIs, pairwise improvement).
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
        "aggregate": aggregates(config, cells, {h: r.get("oracle") for h, r in references.items()}),
        "references": references,
        "cells": cells,
    }
    write_json(config.out / "summary.json", summary)
    return summary
