"""What every MetaController criterion sees and the one signature they all implement.

A decision runs in two phases, so that a criterion can spare the planner's cost (the
point of Keramati et al. 2011 and Dromnelle et al. 2022):

1. :meth:`Criterion.wants_plan` sees only the habit (cheap: its Boltzmann distribution,
   Q-values, uncertainty, weight amplitude) and says whether the planner must be
   consulted. A criterion that needs no plan for this decision returns False and the
   habit's proposal is executed.
2. :meth:`Criterion.choose` sees both proposals (called only when the planner was
   consulted *and* found a plan; on failure the controller falls back to the habit) and
   returns the expert whose action is executed.

:meth:`Criterion.observe` receives the reward since the previous decision (VPI's reward
rate). :attr:`Criterion.stats` holds the numbers behind the last choice, for the log.
"""

from __future__ import annotations

import inspect
import math
from abc import ABC, abstractmethod
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, ClassVar

import numpy as np

DEFAULT_MIN_VISITS = 5
"""Default ``min_visits`` of the learned criteria (entropy, entropy_and_cost, vpi,
learning_state): the best measured setting (docs/results.md)."""

PLANNER_EPSILON = 0.01
"""Probability the planner's distribution puts on each non-planned action (docs/task.md, section 4)."""


class Expert(StrEnum):
    """Who proposed the executed action."""

    PLANNER = "planner"
    HABIT = "habit"


@dataclass(frozen=True, eq=False)
class HabitView:
    """The habitual expert's view of the current state (all cheap to compute)."""

    key: bytes
    """Identity of the state for per-state filters (the fact vector's bytes)."""
    probs: np.ndarray
    """Boltzmann distribution over all actions."""
    action: int
    """The habit's proposal (a draw from ``probs``)."""
    q: np.ndarray
    """Q-values of all actions."""
    sd: np.ndarray
    """Uncertainty (sd) of each Q-value (see ``QLearner.uncertainty``)."""
    weight_amplitude: float
    """``sum |w|`` of the habit's weights now."""
    cost: float
    """The habit's decision cost (seconds; see :class:`~hg_marl.agents.meta.cost.CostModel`)."""
    visits: int = 0
    """TD updates the habit has made from this state (``QLearner.visits``)."""


@dataclass(frozen=True, eq=False)
class PlanProposal:
    """The goal-directed expert's proposal, decoupled from the planner's own result type."""

    success: bool
    """Whether the planner found a plan."""
    action: int
    """The robot's next action in the plan (wait when it must wait for the human)."""
    distribution: np.ndarray
    """``1 - (N - 1) * eps`` on ``action``, ``eps`` elsewhere."""
    cost: float
    """Decision cost of this planning call (seconds)."""
    nodes: int = 0
    """Search nodes expanded."""
    human_action: int = -1
    """The human action the plan expects next, or -1."""

    @classmethod
    def make(cls, action: int, n_actions: int, cost: float, success: bool = True, **extra: Any) -> PlanProposal:
        """Build a proposal with the canonical planner distribution around ``action``."""
        return cls(success, action, planner_distribution(action, n_actions), cost, **extra)


def planner_distribution(action: int, n_actions: int, eps: float = PLANNER_EPSILON) -> np.ndarray:
    """The planner's action distribution: it commits to ``action`` with all but ``eps`` per other."""
    p = np.full(n_actions, eps)
    p[action] = 1.0 - (n_actions - 1) * eps
    return p


def entropy_bits(p: np.ndarray) -> float:
    """Shannon entropy in bits (zero-probability terms contribute nothing)."""
    nz = p[p > 0]
    return float(-(nz * np.log2(nz)).sum())


def normalised_entropy(p: np.ndarray) -> float:
    """Entropy over its maximum, ``H / log2 |A|``, in [0, 1]."""
    return entropy_bits(p) / math.log2(len(p))


class Criterion(ABC):
    """A MetaController strategy. Subclasses set ``name`` and implement :meth:`choose`."""

    name: ClassVar[str]
    """Registry name."""
    min_visits: int = 0
    """The habit is trusted only in states it has learnt from this many times; elsewhere the
    controller consults the planner whatever the criterion says (0: trust it everywhere, as
    the paper's fixed and random criteria do)."""

    def __init__(self) -> None:
        self.rng = np.random.default_rng(0)
        self.stats: dict[str, float] = {}

    def reset(self, rng: np.random.Generator) -> None:
        """Start a run: forget filters and take the robot's generator for any random choice."""
        self.rng = rng
        self.stats = {}
        self._reset()

    def _reset(self) -> None:  # noqa: B027 (optional hook)
        """Hook: clear per-run state."""

    def wants_plan(self, habit: HabitView) -> bool:
        """Whether the planner must be consulted this decision (default: always)."""
        return True

    @abstractmethod
    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        """Pick the expert to execute, given both proposals (the plan succeeded)."""

    def observe(self, reward: float) -> None:  # noqa: B027 (optional hook)
        """Reward received since the previous decision (default: ignored)."""

    def params(self) -> dict[str, Any]:
        """The criterion's parameters, for logs."""
        names = inspect.signature(type(self)).parameters
        return {k: getattr(self, k) for k in names if hasattr(self, k)}


def check_probability(name: str, value: float) -> float:
    """Validate a parameter in [0, 1]."""
    if not 0.0 <= float(value) <= 1.0:
        raise ValueError(f"{name}: expected a value in [0, 1], got {value!r}")
    return float(value)


def check_count(name: str, value: int) -> int:
    """Validate a non-negative integer parameter."""
    if isinstance(value, bool) or not isinstance(value, int | float) or value < 0 or int(value) != value:
        raise ValueError(f"{name}: expected a non-negative integer, got {value!r}")
    return int(value)


def check_positive(name: str, value: float, allow_zero: bool = True) -> float:
    """Validate a non-negative (or positive) parameter."""
    v = float(value)
    if not math.isfinite(v):  # NaN passes the comparisons below
        raise ValueError(f"{name}: expected a finite number, got {value!r}")
    if v < 0 or (v == 0 and not allow_zero):
        kind = "non-negative" if allow_zero else "positive"
        raise ValueError(f"{name}: expected a {kind} number, got {value!r}")
    return v
