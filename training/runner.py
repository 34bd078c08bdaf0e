"""One robot, one human, one scenario, one seed, for a fixed simulated duration.

This is the paper's protocol: the table is re-set after every success (continuing
mode) and the run lasts a fixed simulated time, with the robot's decision time charged
to the clock, so a cheap decider and an expensive one are compared fairly. Every robot
decision becomes one row of a tidy table (see :data:`COLUMNS`).

Seeding: one ``SeedSequence(seed)`` is split into the environment's seed and the two
actors' generators, so a run is a pure function of (robot, human, scenario, seed).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

import hg_marl
from hg_marl.core import Agent
from hg_marl.core.durations import MIN_DURATION
from hg_marl.core.errors import ConfigError, check_bool, check_finite, check_int
from hg_marl.policy import Actor, decision_of, log_fields
from hg_marl.training.io import atomic_write

log = logging.getLogger(__name__)

COLUMNS = (
    "decision",
    "time",
    "cycle",
    *log_fields(),
    "action_name",
    "failed",
    "human_action",
    "human_action_name",
    "human_as_expected",
    "reward",
    "tasks_solved",
)
"""Columns of the per-decision log: the run's own, then every field of the robot's
:class:`~hg_marl.policy.Decision` (see :func:`~hg_marl.policy.log_fields`), then the outcome."""


MAX_CYCLES = 50_000_000
"""Most cycles a run may need: ``duration / shortest action duration`` is checked against it
before the run starts: the longest `--duration` at the default durations (1e7 s at 0.2 s)
fits; durations near the 0.01 s floor shorten the longest run accordingly."""


def check_cycles(duration: float, shortest: float, what: str = "--duration") -> None:
    """Refuse a run whose duration, at the scenario's shortest action, needs over :data:`MAX_CYCLES` cycles."""
    if duration / shortest > MAX_CYCLES:
        raise ConfigError(
            f"{what} {duration:g}: up to {duration / shortest:.3g} cycles at the shortest action duration "
            f"({shortest:g} s), over the limit {MAX_CYCLES:,}"
        )


def check_seconds(value: Any, option: str) -> float:
    """A span of simulated seconds a trainer plays (an episode, an evaluation): positive, and at
    most :data:`MAX_CYCLES` cycles of the shortest action any scenario may have
    (:data:`~hg_marl.core.durations.MIN_DURATION`), since the scenario is not known yet: so it ends."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0 or value == float("inf"):
        raise ConfigError(f"{option}: expected a positive number of seconds, got {value!r}")
    check_cycles(float(value), MIN_DURATION, option)
    return float(value)


@dataclass(frozen=True)
class RunConfig:
    """What to run."""

    scenario: str = "paper2015"
    """Scenario name or TOML path."""
    duration: float = 1200.0
    """Simulated seconds the run lasts."""
    seed: int = 0
    """Seeds the table layouts and both actors' generators."""
    charge_decision_time: bool = True
    """Add each robot decision's ``decision_time`` to the simulated clock."""
    max_decisions: int | None = None
    """Optional safety cap on robot decisions (None: the duration alone ends the run)."""

    def __post_init__(self) -> None:
        check_finite(self.duration, "duration (--duration)", positive=True)
        check_int(self.seed, "seed (--seed)", minimum=0)
        check_bool(self.charge_decision_time, "charge_decision_time")
        if self.max_decisions is not None:
            check_int(self.max_decisions, "max_decisions", minimum=1)


@dataclass
class RunResult:
    """A finished run: its per-decision log and a summary."""

    config: RunConfig
    log: pd.DataFrame
    summary: dict[str, Any] = field(default_factory=dict)

    def save(self, path: str | Path) -> Path:
        """Write the log as CSV, atomically."""
        return atomic_write(path, lambda tmp: self.log.to_csv(tmp, index=False))


def _mean_or_none(column: pd.Series) -> float | None:
    """Mean of the non-missing values (None when there are none: JSON has no NaN)."""
    values = column.dropna()
    return float(values.astype(float).mean()) if len(values) else None


def summarise(log: pd.DataFrame, duration: float) -> dict[str, Any]:
    """Tasks solved, actions, failed actions, simulated time and the planner's share."""
    n = len(log)
    return {
        "tasks_solved": int(log["reward"].sum()) if n else 0,
        "actions": n,
        "failed_actions": int(log["failed"].sum()) if n else 0,
        "simulated_time": float(log["time"].iloc[-1]) if n else 0.0,
        "duration": duration,
        "planner_share": float((log["expert"] == "planner").mean()) if n else 0.0,
        "final_weight_amplitude": float(log["weight_amplitude"].iloc[-1]) if n else 0.0,
        "human_as_expected": _mean_or_none(log["human_as_expected"]) if n else None,
    }


def run(
    robot: Actor,
    human: Actor,
    config: RunConfig,
    on_decision: Callable[[float], None] | None = None,
) -> RunResult:
    """Play ``robot`` with ``human`` for ``config.duration`` simulated seconds.

    Args:
        robot: the robot seat's actor.
        human: the human seat's actor.
        config: scenario, duration, seed.
        on_decision: called with the simulated clock after each robot decision
            (progress bars hook in here; library code prints nothing).
    """
    env = hg_marl.env(scenario=config.scenario, continuing=True, max_cycles=None, time_budget=config.duration)
    raw = env.unwrapped
    check_cycles(config.duration, raw.world.durations.shortest)
    env_seed, robot_seq, human_seq = np.random.SeedSequence(config.seed).spawn(3)
    env.reset(seed=int(env_seed.generate_state(1)[0]))
    robot.reset(raw.world, Agent.ROBOT, np.random.default_rng(robot_seq))
    human.reset(raw.world, Agent.HUMAN, np.random.default_rng(human_seq))
    names = raw.world.action_names
    rows: list[dict[str, Any]] = []
    row: dict[str, Any] = {}
    for agent in env.agent_iter():
        _, _, term, trunc, _ = env.last()
        if term or trunc:
            env.step(None)
            continue
        if agent == "robot":
            if config.max_decisions is not None and len(rows) >= config.max_decisions:
                break
            action = int(robot.act(raw.turn("robot")))
            record = decision_of(robot)
            if config.charge_decision_time and record.decision_time > 0:
                raw.charge_time(record.decision_time)
            env.step(action)
            fields = asdict(record)
            del fields["stats"]
            fields["action"] = action
            row = {
                "decision": len(rows),
                "time": raw.clock,
                "cycle": raw.cycles,
                **fields,
                "action_name": names[Agent.ROBOT][action],
                "failed": bool(raw.infos["robot"]["failed"]),
                "human_action": -1,
                "human_action_name": "",
                "human_as_expected": None,
                "reward": float(raw.rewards["robot"]),
                "tasks_solved": raw.tasks_solved,
            }
            rows.append(row)
        else:
            action = int(human.act(raw.turn("human")))
            env.step(action)
            row["human_action"] = action
            row["human_action_name"] = names[Agent.HUMAN][action]
            row["human_as_expected"] = (
                None if row["expected_human_action"] < 0 else action == row["expected_human_action"]
            )
            row["time"] = raw.clock
            if on_decision is not None:
                on_decision(raw.clock)
    frame = pd.DataFrame(rows, columns=list(COLUMNS))
    return RunResult(config, frame, summarise(frame, config.duration))
