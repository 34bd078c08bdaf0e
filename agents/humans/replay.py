"""``replay``: acts from a recorded trace (see :mod:`.trace` for the format).

Each :meth:`ReplayHuman.reset` moves to the trace's next episode, so a replay in the
same environment with the same seeds reproduces the recorded run action for action.
Before acting it compares the live observation with the recorded one: if they differ
the run has diverged from the recording (``on_mismatch`` decides what then).
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.trace import Episode, read_trace
from hg_marl.core import Agent, World
from hg_marl.policy import Turn

logger = logging.getLogger(__name__)

_MISMATCH = ("error", "warn", "ignore")
_END = ("wait", "error")


class ReplayHuman:
    """Plays back recorded actions.

    Args:
        path: the trace file (JSON lines).
        on_mismatch: when the live facts differ from the recorded ones: ``"error"``
            (raise), ``"warn"`` (log once per episode and go on) or ``"ignore"``.
        on_end: when the episode's recorded steps run out: ``"wait"`` or ``"error"``.
        loop: after the last episode start again at the first (else an extra reset raises).
    """

    name = "replay"

    def __init__(
        self, path: str | Path | None = None, on_mismatch: str = "error", on_end: str = "wait", loop: bool = False
    ) -> None:
        if path is None:
            raise ValueError("replay needs path=<trace file>")
        if on_mismatch not in _MISMATCH:
            raise ValueError(f"on_mismatch must be one of {_MISMATCH}, got {on_mismatch!r}")
        if on_end not in _END:
            raise ValueError(f"on_end must be one of {_END}, got {on_end!r}")
        self.path = Path(path)
        self.episodes: list[Episode] = read_trace(self.path)
        self.on_mismatch = on_mismatch
        self.on_end = on_end
        self.loop = loop
        self.episode = -1
        self.step = 0
        self.world: World | None = None
        self._warned = False
        self.last_decision: dict[str, object] = {}

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Move to the next recorded episode (``rng`` is unused: replay draws nothing)."""
        self.episode += 1
        if self.episode >= len(self.episodes):
            if not self.loop:
                raise ValueError(
                    f"{self.path}: only {len(self.episodes)} episode(s) recorded; pass loop=True to repeat"
                )
            self.episode = 0
        header = self.episodes[self.episode].header
        if list(header["action_names"]) != list(world.action_names[agent]):
            raise ValueError(
                f"{self.path}: episode {self.episode} was recorded in scenario {header['scenario']!r} as "
                f"{header['seat']!r}; its actions do not match {world.scenario.name!r} as {agent.label!r}"
            )
        self.world = world
        self.step = 0
        self._warned = False

    def act(self, turn: Turn) -> int:
        """The next recorded action."""
        steps = self.episodes[self.episode].steps
        if self.step >= len(steps):
            if self.on_end == "error":
                raise ValueError(f"{self.path}: episode {self.episode} has only {len(steps)} steps")
            return wait_index(turn.world)
        record = steps[self.step]
        self.step += 1
        if self.on_mismatch != "ignore":
            live = np.asarray(turn.observation["observation"]).astype(int).tolist()
            if live != record["facts"]:
                message = (
                    f"{self.path}: episode {self.episode} step {record['step']}: the live facts differ "
                    "from the recorded ones (the run diverged from the recording)"
                )
                if self.on_mismatch == "error":
                    raise ValueError(message)
                if not self._warned:
                    logger.warning(message)
                    self._warned = True
        self.last_decision = {"human": self.name, "action": record["action_name"], "step": record["step"]}
        return int(record["action"])
