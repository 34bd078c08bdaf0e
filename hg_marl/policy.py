"""The one protocol for anything that acts in the table-cleaning task.

Robots and humans alike implement :class:`Actor`: ``reset`` hands them the world and
their own seeded generator, ``act`` gets a :class:`Turn` and returns a Discrete action
index. A turn carries both the full symbolic state (scripted humans, the planner and
the oracle reason on it, as HATP does with its world model) and the agent's
observation (learned policies see only the facts and the mask).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
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


@dataclass(frozen=True)
class Decision:
    """A robot's record of one decision, read by the runner (one log row) and by viewers.

    One typed record instead of a dict whose keys were written by each robot and read
    back with defaults: a field added here becomes a log column (see :func:`log_fields`).
    """

    expert: str
    """Who chose the executed action: "planner", "habit", "random", "sb3", "oracle"..."""
    action: int
    """The executed action's index."""
    planner_action: int = -1
    """The planner's proposal (-1: the planner did not propose or failed)."""
    habit_action: int = -1
    """The habit's proposal (-1: no habit)."""
    planning_time: float = 0.0
    """Wall seconds spent planning (or deciding, for robots without a planner)."""
    planner_nodes: int = 0
    """Search nodes the planner expanded."""
    planner_success: bool = False
    """Whether the planner found a plan."""
    planner_consulted: bool = False
    """Whether the planner was asked at all (criteria may spare it)."""
    decision_time: float = 0.0
    """Simulated seconds to charge to the clock for this decision."""
    expected_human_action: int = -1
    """The human action the robot's plan expects next (-1: no expectation)."""
    weight_amplitude: float = 0.0
    """The habit's weight amplitude (the paper's Fig. 5; 0 without a habit)."""
    reason: str = ""
    """Why this expert was chosen, or why the planner failed."""
    partner: str = ""
    """The partner model's current estimate of the human (partner-aware robots)."""
    stats: tuple[tuple[str, float], ...] = ()
    """The criterion's numbers (entropy, VPI, ...), as (name, value) pairs."""


def log_fields() -> tuple[str, ...]:
    """The :class:`Decision` fields that are log columns (every scalar field)."""
    return tuple(f.name for f in fields(Decision) if f.name != "stats")


def decision_of(actor: Any) -> Decision:
    """The actor's record of its last decision (``last_decision``).

    Actors outside this package need not keep one: they get a record naming their class
    with no expectation, so the runner logs them like any other robot.
    """
    record = getattr(actor, "last_decision", None)
    if isinstance(record, Decision):
        return record
    name = str(getattr(actor, "name", type(actor).__name__))
    return Decision(expert=name, action=-1)
