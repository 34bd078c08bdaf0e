"""Evaluating SB3 models on the paper's protocol: the runner, continuing play, tasks per hour.

SB3's own ``evaluate_policy`` (used by the training's ``EvalCallback``) scores episodes
of the training view; the comparison with the planner, the hybrid robot and the oracle
needs the same protocol as theirs: :func:`hg_marl.training.runner.run`, continuing play
for a fixed simulated duration, decision time charged. :func:`runner_rate` wraps a model
(in memory or saved) as an :class:`~hg_marl.agents.robots.sb3.SB3Robot` and does that.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.policy import Actor
from hg_marl.training.runner import RunConfig, run

HOUR = 3600.0


def actor_rate(
    make_robot: Callable[[], Actor], human: str, scenario: str, duration: float, seeds: Sequence[int]
) -> float:
    """Mean tasks per simulated hour of fresh robots from ``make_robot`` with ``human`` over ``seeds``.

    Each seed gets a new robot and a new human, so learning robots (habit, hybrid) start
    from scratch every run, as in the paper.
    """
    rates = []
    for seed in seeds:
        result = run(make_robot(), make_human(human), RunConfig(scenario=scenario, duration=duration, seed=seed))
        rates.append(result.summary["tasks_solved"] * HOUR / duration)
    return float(np.mean(rates)) if rates else math.nan


def runner_rate(
    model: Any,
    observation: str,
    human: str,
    scenario: str,
    duration: float = 1200.0,
    seeds: Sequence[int] = (0,),
    deterministic: bool = True,
) -> float:
    """Tasks per simulated hour of an in-memory SB3 ``model`` in the robot seat (runner protocol)."""
    from hg_marl.agents.robots.sb3 import SB3Robot

    def build() -> Actor:
        return SB3Robot(model=model, observation=observation, deterministic=deterministic)

    return actor_rate(build, human, scenario, duration, seeds)


def steps_to_reach(curve: Sequence[tuple[int, float]], target: float) -> int | None:
    """First evaluated step count whose rate reaches ``target`` (None if never)."""
    for steps, rate in curve:
        if rate >= target:
            return int(steps)
    return None
