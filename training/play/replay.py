"""Replaying a recorded game through the runner: same seed, same robot, the ``replay`` human.

This is the check that a recording means what it says: the runner plays the robot
(rebuilt from the spec in the trace) against :class:`~hg_marl.agents.humans.replay.ReplayHuman`
with the recorded seed, for just as long as the game lasted, and the replay human
refuses to go on if the live table ever differs from the recorded one.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hg_marl.agents.humans.replay import ReplayHuman
from hg_marl.agents.humans.trace import Episode, check_episode, read_trace
from hg_marl.core.errors import ConfigError, HumanError
from hg_marl.policy import Actor
from hg_marl.training.play.session import build_robot
from hg_marl.training.runner import RunConfig, RunResult, run

MARGIN = 1e-3
"""Seconds past the recorded end clock. A game ends just after the robot's turn that
follows the person's last move (the person saw its result, maybe a solved task), and
that turn's cycle never ended. The replay runs until the clock passes the end of the
last complete cycle: the robot takes that turn too, the replay human, out of moves,
waits, and the runner stops at the end of that cycle (every cycle lasts longer than
the margin). Without an end line the last turn's clock is used (no extra robot turn)."""


@dataclass(frozen=True)
class ReplayResult:
    """What a replay reproduced."""

    scenario: str
    seed: int
    robot: str
    player: str
    moves: int
    tasks_solved: int
    rewards: float
    clock: float
    """Simulated seconds at the end of the replay's last cycle (past the recording's end, see :data:`MARGIN`)."""
    recorded_clock: float
    """Simulated seconds at which the recorded game ended (what the CLI reports)."""
    recorded_rewards: float | None
    """The rewards written in the trace's end line (None when it has none)."""
    video: Path | None = None
    frames: int = 0


def load_episode(trace: Path, episode: int) -> Episode:
    """One episode of a trace file, with file errors as one-line messages."""
    try:
        episodes = read_trace(trace)
    except FileNotFoundError:
        raise ConfigError(f"{trace}: no such trace file") from None
    except (ValueError, KeyError) as exc:
        raise HumanError(str(exc)) from None
    if not 0 <= episode < len(episodes):
        raise ConfigError(f"--episode {episode}: {trace} holds episodes 0..{len(episodes) - 1}")
    check_episode(episodes[episode], trace, seat="human")
    return episodes[episode]


def end_clock(ep: Episode) -> float:
    """The recorded game's end: its end line's clock, else its last turn's (0 without turns)."""
    return float(ep.end["clock"]) if "clock" in ep.end else float(ep.steps[-1]["clock"]) if ep.steps else 0.0


def replay_run(
    trace: Path, episode: int = 0, robot: str | None = None, wrap: Callable[[Actor], Actor] | None = None
) -> RunResult:
    """Run the recorded episode again; ``wrap`` may wrap the robot (to film it)."""
    ep = load_episode(trace, episode)
    h = ep.header
    actor = build_robot(robot or h.get("meta", {}).get("robot") or "planner")
    if wrap is not None:
        actor = wrap(actor)
    human = ReplayHuman(trace, on_mismatch="error")
    human.episode = episode - 1  # reset() moves to the next episode
    config = RunConfig(scenario=str(h["scenario"]), duration=end_clock(ep) + MARGIN, seed=int(h.get("seed") or 0))
    try:
        return run(actor, human, config)
    except ValueError as exc:
        raise HumanError(f"replay of {trace}: {exc}") from None


def replay_trace(trace: Path, episode: int = 0, robot: str | None = None, video: Path | None = None) -> ReplayResult:
    """Replay and summarise; write the video when asked."""
    ep = load_episode(trace, episode)
    frames: list[np.ndarray] = []
    wrap = None
    if video is not None:
        from hg_marl.training.video import FrameRecorder, check_video_path

        check_video_path(video)

        def wrap(actor: Actor) -> Actor:
            recorder = FrameRecorder(actor)
            recorder.frames = frames
            return recorder

    result = replay_run(trace, episode, robot, wrap)
    written = None
    if video is not None:
        from hg_marl.training.video import write_video

        written = write_video(frames, video)
    h = ep.header
    meta = h.get("meta", {})
    log = result.log
    return ReplayResult(
        scenario=str(h["scenario"]),
        seed=int(h.get("seed") or 0),
        robot=robot or meta.get("robot") or "planner",
        player=str(meta.get("player", "")),
        moves=len(ep.steps),
        tasks_solved=int(result.summary["tasks_solved"]),
        rewards=float(log["reward"].sum()) if len(log) else 0.0,
        clock=float(log["time"].iloc[-1]) if len(log) else 0.0,
        recorded_clock=end_clock(ep),
        recorded_rewards=float(ep.end["rewards"]) if "rewards" in ep.end else None,
        video=written,
        frames=len(frames),
    )
