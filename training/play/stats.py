"""Statistics of recorded play, and which scripted human a person resembles most.

Per episode of a trace (one game), from the recorded facts, masks and actions only:

- ``moves``, ``tasks`` and ``moves_per_task`` (the human's moves per solved task);
- ``handover_acceptance``: of the turns where the robot was offering (a ``take`` was
  feasible), the share where the human took it (None when the robot never offered);
- ``share_<kind>``: the share of moves of each action kind (``pick``, ``place``,
  ``give``, ``take``, ``throw``, ``wait``); ``share_wait`` is the idle share by moves;
- ``response_time`` (mean and median wall seconds; recordings of people only).

The comparison replays each scripted human (with default parameters) against the same
robot, on the same seed and for the same simulated time as the recorded game, records
it in the same trace format and measures it the same way. Resemblance is the L1
distance between the vectors of action-kind shares plus handover acceptance (a side
that never saw an offer counts as accepting none); the scripted human at the smallest
distance is named.
"""

from __future__ import annotations

import statistics
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.trace import Episode, TraceRecorder, check_episode, read_trace, trace_paths
from hg_marl.core.errors import HumanError
from hg_marl.training.play.session import build_robot
from hg_marl.training.runner import RunConfig, run

KINDS = ("pick", "place", "give", "take", "throw", "wait")
SCRIPTED = ("cooperative", "lazy", "no_handover", "adversarial", "random", "noisy")
"""Scripted humans compared (those with a default for every parameter and one behaviour)."""


@dataclass(frozen=True)
class PlayStats:
    """The statistics of one game (see the module docstring)."""

    who: str
    robot: str
    moves: int
    tasks: int
    handover_acceptance: float | None
    shares: dict[str, float] = field(default_factory=dict)
    response_times: tuple[float, ...] = ()

    @property
    def moves_per_task(self) -> float | None:
        """Human moves per solved task (None without a solved task)."""
        return self.moves / self.tasks if self.tasks else None

    def profile(self) -> np.ndarray:
        """The vector compared between players: action-kind shares then acceptance."""
        return np.array([self.shares.get(k, 0.0) for k in KINDS] + [self.handover_acceptance or 0.0])


def episode_stats(episode: Episode, who: str | None = None) -> PlayStats:
    """The statistics of one recorded episode."""
    h = episode.header
    names = list(h["action_names"])
    kind = [n.split("(")[0] for n in names]
    offered = accepted = 0
    counts = dict.fromkeys(KINDS, 0)
    for step in episode.steps:
        a = int(step["action"])
        counts[kind[a]] = counts.get(kind[a], 0) + 1
        if any(m and kind[i] == "take" for i, m in enumerate(step["mask"])):
            offered += 1
            accepted += kind[a] == "take"
    moves = len(episode.steps)
    last = episode.steps[-1]["tasks_solved"] if episode.steps else 0
    tasks = int(episode.end.get("tasks_solved", last))
    meta = h.get("meta", {})
    return PlayStats(
        who=who or str(meta.get("player") or h.get("actor") or "?"),
        robot=str(meta.get("robot") or "?"),
        moves=moves,
        tasks=tasks,
        handover_acceptance=accepted / offered if offered else None,
        shares={k: c / moves for k, c in counts.items()} if moves else {},
        response_times=tuple(float(s["response_time"]) for s in episode.steps if "response_time" in s),
    )


def load_games(path: Path) -> list[Episode]:
    """Every episode of every trace under ``path``."""
    games: list[Episode] = []
    for file in trace_paths(path):
        try:
            episodes = read_trace(file)
            for episode in episodes:
                check_episode(episode, file, seat="human")
        except (ValueError, KeyError) as exc:
            raise HumanError(str(exc)) from None
        games += episodes
    return games


def scripted_stats(episode: Episode, human: str) -> PlayStats:
    """A scripted human's statistics on the recorded game's layouts, robot and time."""
    h = episode.header
    robot = str(h.get("meta", {}).get("robot") or "planner")
    clock = float(episode.end.get("clock") or (episode.steps[-1]["clock"] if episode.steps else 0.0))
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "scripted.jsonl"
        recorder = TraceRecorder(make_human(human), path, seed=h.get("seed"), meta={"robot": robot})
        config = RunConfig(scenario=str(h["scenario"]), duration=max(clock, 1.0), seed=int(h.get("seed") or 0))
        run(build_robot(robot), recorder, config)
        recorder.close()
        (recorded,) = read_trace(path)
    return episode_stats(recorded, who=human)


def resemblance(person: list[PlayStats], scripted: dict[str, list[PlayStats]]) -> dict[str, float]:
    """Mean L1 distance of the person's profile to each scripted human's, game by game."""
    return {
        name: float(np.mean([np.abs(p.profile() - s.profile()).sum() for p, s in zip(person, games, strict=True)]))
        for name, games in scripted.items()
    }


def summarise(stats: list[PlayStats]) -> dict[str, Any]:
    """Totals over games: sessions, moves per task, acceptance, shares, response times."""
    moves, tasks = sum(s.moves for s in stats), sum(s.tasks for s in stats)
    offered = [s.handover_acceptance for s in stats if s.handover_acceptance is not None]
    rt = [t for s in stats for t in s.response_times]
    return {
        "sessions": len(stats),
        "moves": moves,
        "tasks": tasks,
        "moves_per_task": moves / tasks if tasks else None,
        "handover_acceptance": float(np.mean(offered)) if offered else None,
        "idle_share": sum(s.shares.get("wait", 0.0) * s.moves for s in stats) / moves if moves else None,
        "shares": {k: sum(s.shares.get(k, 0.0) * s.moves for s in stats) / moves if moves else 0.0 for k in KINDS},
        "response_time_mean": float(np.mean(rt)) if rt else None,
        "response_time_median": float(statistics.median(rt)) if rt else None,
    }
