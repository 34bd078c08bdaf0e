"""Watching a run: labelled frames of the table written as a GIF or an MP4 (imageio).

:class:`FrameRecorder` wraps an actor and draws the table each time that actor is
asked to act, so wrapping the robot gives one frame per cycle (the table after the
previous cycle, captioned with both agents' last actions, the clock and the tasks
solved) without touching the runner. GIFs are written with Pillow (comes with
matplotlib); MP4 needs ffmpeg from the ``video`` extra (``imageio-ffmpeg``).
"""

from __future__ import annotations

import importlib.util
import logging
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.render import caption_of, render_rgb
from hg_marl.policy import Actor, Turn
from hg_marl.training.io import atomic_write
from hg_marl.training.outputs import check_output

log = logging.getLogger(__name__)

FORMATS = (".gif", ".mp4")
MAX_FRAMES = 3000
"""Frames kept in memory at most (their memory: ``docs/inputs.md``); later ones are dropped."""


def check_video_path(path: Path) -> Path:
    """Refuse an unknown extension, MP4 without ffmpeg, or a place it cannot be written, before a run starts.

    Raises:
        ConfigError: one line naming ``--video`` and what to do.
    """
    if path.suffix.lower() not in FORMATS:
        raise ConfigError(f"--video {path}: expected a .gif or .mp4 file name")
    check_output(path, "--video")
    if path.suffix.lower() == ".mp4" and importlib.util.find_spec("imageio_ffmpeg") is None:
        raise ConfigError(f"--video {path}: MP4 needs ffmpeg: pip install 'hg-marl[video]' (or write a .gif)")
    return path


class FrameRecorder:
    """Wraps an actor; draws the table (labelled) before each of its decisions.

    Args:
        actor: the wrapped actor (its decisions are unchanged).
        max_frames: frames kept at most.
    """

    def __init__(self, actor: Actor, max_frames: int = MAX_FRAMES) -> None:
        self.actor = actor
        self.max_frames = max_frames
        self.frames: list[np.ndarray] = []
        self.dropped = 0
        self.name = getattr(actor, "name", type(actor).__name__)

    @property
    def last_decision(self) -> Any:
        """The wrapped actor's decision record (the runner reads it)."""
        return getattr(self.actor, "last_decision", None)

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Reset the wrapped actor."""
        self.actor.reset(world, agent, rng)

    def act(self, turn: Turn) -> int:
        """Draw the table, then act as the wrapped actor."""
        self.capture(turn)
        return self.actor.act(turn)

    def capture(self, turn: Turn) -> None:
        """Draw ``turn``'s table as one frame."""
        if len(self.frames) >= self.max_frames:
            self.dropped += 1
            return
        caption = caption_of(turn.world, turn.clock, turn.tasks_solved, turn.last_actions)
        self.frames.append(render_rgb(turn.world, turn.state, caption))

    def __getattr__(self, name: str) -> Any:
        # Anything else (end(), habit, ...) is the wrapped actor's.
        return getattr(self.actor, name)


def write_video(frames: list[np.ndarray], path: str | Path, fps: float = 2.0) -> Path:
    """Write ``frames`` as a GIF (looping) or MP4, atomically; returns the path."""
    import imageio.v3 as iio

    out = check_video_path(Path(path))
    if not frames:
        raise ConfigError(f"--video {out}: the run produced no frames")
    if len(frames) >= MAX_FRAMES:
        log.warning("video: kept the first %d frames only; shorten the run for the rest", MAX_FRAMES)
    stack = np.stack(frames)

    def write(tmp: Path) -> None:
        # ffmpeg picks its muxer from the file name, so the frames go to a sibling that keeps
        # the output's suffix, which then becomes the atomic write's temporary file
        named = tmp.with_name(tmp.name + out.suffix.lower())
        try:
            if out.suffix.lower() == ".gif":
                iio.imwrite(named, stack, extension=".gif", duration=1000.0 / fps, loop=0)
            else:
                iio.imwrite(named, stack, extension=".mp4", plugin="FFMPEG", fps=fps, macro_block_size=1)
            if not named.exists() or named.stat().st_size == 0:
                raise ConfigError(f"--video {out}: the encoder wrote nothing")
            named.replace(tmp)
        finally:
            named.unlink(missing_ok=True)

    return atomic_write(out, write)
