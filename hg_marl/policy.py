"""The one protocol for anything that acts in the table-cleaning task.

Robots and humans alike implement :class:`Actor`: ``reset`` hands them the world and
their own seeded generator, ``act`` gets a :class:`Turn` and returns a Discrete action
index. A turn carries both the full symbolic state (scripted humans, the planner and
the oracle reason on it, as HATP does with its world model) and the agent's
observation (learned policies see only the facts and the mask).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

import numpy as np

from hg_marl.core import Agent, Event, State, World


@dataclass(frozen=True)
class Turn:
    """Everything an actor may look at when it is its turn."""

    world: World
    """The task's rules (shared, read-only)."""
    state: State
    """The full symbolic state."""
    agent: Agent
    """Who is acting."""
    observation: dict[str, np.ndarray]
    """``{"observation": facts, "action_mask": mask}``, as the environment returns it."""
    clock: float = 0.0
    """Simulated seconds since the run started."""
    reward: float = 0.0
    """Reward this agent received since its previous turn."""
    tasks_solved: int = 0
    """Tasks completed so far in this run."""
    events: tuple[Event, ...] = field(default=())
    """What happened since this agent's previous turn: its own last action, then the partner's."""
    last_actions: tuple[int, int] = (-1, -1)
    """Last action index taken by the robot and by the human (-1 before any)."""

    @property
    def mask(self) -> np.ndarray:
        """The action mask of the acting agent."""
        return self.observation["action_mask"]


@runtime_checkable
class Actor(Protocol):
    """A decision maker in either seat."""

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Start a run: remember the world and seat, take ownership of ``rng``."""

    def act(self, turn: Turn) -> int:
        """Return the index of the action to execute this turn."""


def info_of(actor: Any) -> dict[str, Any]:
    """The actor's record of its last decision (``last_decision``), or an empty dict."""
    record = getattr(actor, "last_decision", None)
    return dict(record) if record else {}
