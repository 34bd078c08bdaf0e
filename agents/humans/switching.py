"""``switching``: a schedule of other humans, by simulated time or by tasks solved.

``make_human("switching", humans=["cooperative", "lazy:p_idle=0.5"], at=[600.0])`` plays
the cooperative human until the clock reaches 600 simulated seconds, then the lazy one.
With ``by="tasks"`` the thresholds count tasks solved instead. It is the adaptation
experiment's partner (docs/task.md, section 6). Not stationary: the oracle refuses it, and is
run once per phase instead.
"""

from __future__ import annotations

import itertools
from bisect import bisect_right
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from hg_marl.core import Agent, World
from hg_marl.policy import Actor, Turn

if TYPE_CHECKING:
    HumanSpec = str | Actor


class SwitchingHuman:
    """Delegates each turn to the phase's human.

    Args:
        humans: the phases' humans: registry names (``"lazy"``, ``"lazy:p_idle=0.5"``) or
            Actor instances, in order.
        at: the thresholds at which play moves to the next human, increasing, one fewer
            than ``humans``.
        by: ``"time"`` (simulated seconds on the clock) or ``"tasks"`` (tasks solved).

    Every phase's human is reset at :meth:`reset` with its own child generator spawned
    from the switching human's, so adding a phase does not change the others' draws.
    """

    name = "switching"

    def __init__(
        self, humans: Sequence[HumanSpec] = ("cooperative", "lazy"), at: Sequence[float] = (600.0,), by: str = "time"
    ) -> None:
        from hg_marl.agents.humans.registry import resolve_human

        if by not in ("time", "tasks"):
            raise ValueError(f"by must be 'time' or 'tasks', got {by!r}")
        if len(humans) < 1 or len(at) != len(humans) - 1:
            raise ValueError(f"need one threshold fewer than humans: got {len(humans)} humans and at={list(at)}")
        if any(b <= a for a, b in itertools.pairwise(at)):
            raise ValueError(f"thresholds must increase, got at={list(at)}")
        self.humans: list[Actor] = [resolve_human(h) for h in humans]
        self.specs: list[str | None] = [h if isinstance(h, str) else None for h in humans]
        """Each phase's registry spec (None for an instance): a batched env compiles and caches by it."""
        self.at = [float(x) for x in at]
        self.by = by
        self.phase = 0
        self.last_decision: dict[str, object] = {}

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Reset every phase's human with a child generator; start in phase 0."""
        for human, child in zip(self.humans, rng.spawn(len(self.humans)), strict=True):
            human.reset(world, agent, child)
        self.phase = 0

    def phase_at(self, clock: float, tasks_solved: int) -> int:
        """Index of the human in charge at this clock / number of tasks solved."""
        value = clock if self.by == "time" else float(tasks_solved)
        return bisect_right(self.at, value)

    def act(self, turn: Turn) -> int:
        """Act as the human of the current phase."""
        self.phase = self.phase_at(turn.clock, turn.tasks_solved)
        human = self.humans[self.phase]
        index = human.act(turn)
        inner = getattr(human, "last_decision", None) or {}
        self.last_decision = {**inner, "phase": self.phase, "human": getattr(human, "name", type(human).__name__)}
        return index
