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
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

import hg_marl
from hg_marl.core import Agent
from hg_marl.core.errors import check_bool, check_finite, check_int
from hg_marl.policy import Actor, info_of
from hg_marl.training.io import atomic_write

log = logging.getLogger(__name__)

COLUMNS = (
    "decision",
    "time",
    "cycle",
    "expert",
    "action",
    "action_name",
    "failed",
    "planner_action",
    "habit_action",
    "planning_time",
    "planner_nodes",
    "planner_success",
    "decision_time",
    "expected_human_action",
    "human_action",
    "human_action_name",
    "human_as_expected",
    "reward",
    "tasks_solved",
    "weight_amplitude",
)
"""Columns of the per-decision log."""


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
            record = info_of(robot)
            decision_time = float(record.get("decision_time", 0.0))
            if config.charge_decision_time and decision_time > 0:
                raw.charge_time(decision_time)
            env.step(action)
            expected = int(record.get("expected_human_action", -1))
            row = {
                "decision": len(rows),
                "time": raw.clock,
                "cycle": raw.cycles,
                "expert": record.get("expert", getattr(robot, "name", type(robot).__name__)),
                "action": action,
                "action_name": names[Agent.ROBOT][action],
                "failed": bool(raw.infos["robot"]["failed"]),
                "planner_action": int(record.get("planner_action", -1)),
                "habit_action": int(record.get("habit_action", -1)),
                "planning_time": float(record.get("planning_time", 0.0)),
                "planner_nodes": int(record.get("planner_nodes", 0)),
                "planner_success": record.get("planner_success"),
                "decision_time": decision_time,
                "expected_human_action": expected,
                "human_action": -1,
                "human_action_name": "",
                "human_as_expected": None,
                "reward": float(raw.rewards["robot"]),
                "tasks_solved": raw.tasks_solved,
                "weight_amplitude": float(record.get("weight_amplitude", 0.0)),
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
