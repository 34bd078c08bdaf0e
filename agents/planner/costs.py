"""The planner's cost model: what a joint cycle costs, term by term, and its weights.

A plan is a sequence of joint *cycles* (the robot's action, then the human's, the way
the AEC environment runs them). A cycle lasts ``dt = max(d_robot, d_human)`` because the
agents act in parallel (``hg_marl.core.cycle.cycle_length``, the environment's clock
rule). Every term below is a sum over cycles, so the total cost is
additive and the cost-to-go of a state does not depend on how it was reached: that is
what lets the search share one transposition table entry per state and what makes the
suffix of an optimal plan optimal (Bellman), which the planner's cache relies on.

Per cycle, with ``e_r`` and ``e_h`` the robot's and human's *active* time (the duration
of a non-wait action, 0 for ``wait``):

- ``time``: ``dt``. Summed, the predicted completion time.
- ``human_effort``: ``e_h``, the seconds the human spends working.
- ``effort_balance``: ``max(0, e_h - e_r)``, seconds the human works while the robot
  does not (or works less); an unanswered robot ``give`` is not robot work. A per-cycle
  form of "the human should not carry the team": a global ``|E_h - E_r|`` would not be
  additive and would break the table.
- ``human_idle``: ``dt - e_h``, seconds the human waits (for the robot, for a handover,
  or for the end of the robot's longer action).
- ``human_holding``: ``dt`` when the human holds an object at the end of the cycle: the
  undesirable state "human left holding an object".
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from typing import NamedTuple

from hg_marl.core import Agent, Kind, World
from hg_marl.core.cycle import cycle_length

TERMS: tuple[str, ...] = ("time", "human_effort", "effort_balance", "human_idle", "human_holding")
"""Names of the cost terms, in the order of :class:`Terms`."""


class Terms(NamedTuple):
    """Raw (unweighted) quantities of one cycle or a whole plan, in seconds."""

    time: float = 0.0
    human_effort: float = 0.0
    effort_balance: float = 0.0
    human_idle: float = 0.0
    human_holding: float = 0.0

    def __add__(self, other: tuple[float, ...]) -> Terms:  # type: ignore[override]
        return Terms(*(a + b for a, b in zip(self, other, strict=True)))


MAX_WEIGHT = 1e6
"""The largest weight of a cost term, per second: only the weights' ratios matter to a plan, and
past this a plan's cost (weights times up to millions of simulated seconds) could overflow to
infinity, the bound's mark for a dead end, so every plan would fail as unreachable."""


@dataclass(frozen=True)
class CostWeights:
    """Weights of the cost terms (cost per second of each quantity).

    The defaults make time dominant (a plan that finishes 1 s later must save the
    human at least ~4 s of work to be preferred) while still separating plans of equal
    duration in the human's favour, as HATP's social rules do.
    """

    time: float = 1.0
    """Per second until the task completes (the robot's completing ``wait`` included)."""
    human_effort: float = 0.2
    """Per second of human activity (any successful action other than ``wait``)."""
    effort_balance: float = 0.1
    """Per second the human works more than the robot within a cycle."""
    human_idle: float = 0.05
    """Per second the human waits (idle, or done before the robot's action ends)."""
    human_holding: float = 0.1
    """Per second the human holds an object at the end of a cycle (undesirable state)."""

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if not math.isfinite(value):  # NaN passes every comparison below; plans would cost NaN
                raise ValueError(f"CostWeights.{f.name} must be a finite number, got {value}")
            if value < 0:
                raise ValueError(f"CostWeights.{f.name} must be >= 0, got {value}")
            if value > MAX_WEIGHT:
                raise ValueError(f"CostWeights.{f.name} must be at most {MAX_WEIGHT:g} per second, got {value}")
        if self.time <= 0:
            raise ValueError("CostWeights.time must be > 0 (plans must not be free to lengthen)")

    @property
    def vector(self) -> tuple[float, ...]:
        """Weights in :data:`TERMS` order."""
        return tuple(getattr(self, name) for name in TERMS)

    def total(self, terms: tuple[float, ...]) -> float:
        """Weighted sum of raw terms."""
        return sum(w * t for w, t in zip(self.vector, terms, strict=True))

    def breakdown(self, terms: tuple[float, ...]) -> dict[str, float]:
        """Weighted contribution of each term; the values sum to :meth:`total`."""
        return {name: w * t for name, w, t in zip(TERMS, self.vector, terms, strict=True)}

    @classmethod
    def time_only(cls) -> CostWeights:
        """Weights that minimise completion time alone (social weights 0)."""
        return cls(time=1.0, human_effort=0.0, effort_balance=0.0, human_idle=0.0, human_holding=0.0)


@dataclass(frozen=True)
class PlannerConfig:
    """Search settings. Frozen: a planner's behaviour is fixed at construction."""

    weights: CostWeights = field(default_factory=CostWeights)
    """The cost model's weights."""
    node_budget: int = 200_000
    """Maximum nodes expanded per call; beyond it the call fails with reason 'budget'."""
    cache_size: int = 4096
    """Plans memoised per planner instance (by state and mover); 0 disables the cache."""
    cache_suffixes: bool = True
    """Also cache the suffix of each plan for the states it passes through (Bellman: they are
    optimal there). A cached suffix is *an* optimal plan, but a cold search from that state may
    break ties differently; set False when every answer must be a function of the query alone
    (exact repeats are still cached)."""
    value_tolerance: float = 1e-9
    """Stochastic human models: value iteration stops when no value moves more than this."""
    max_sweeps: int = 10_000
    """Stochastic human models: value-iteration sweeps before giving up (reason 'budget')."""

    def __post_init__(self) -> None:
        if self.node_budget < 1:
            raise ValueError(f"PlannerConfig.node_budget must be >= 1, got {self.node_budget}")
        if self.cache_size < 0:
            raise ValueError(f"PlannerConfig.cache_size must be >= 0, got {self.cache_size}")
        if not (0 <= self.value_tolerance < math.inf):  # a negative one is never met: every search would fail
            raise ValueError(f"PlannerConfig.value_tolerance must be finite and >= 0, got {self.value_tolerance}")
        if self.max_sweeps < 1:
            raise ValueError(f"PlannerConfig.max_sweeps must be >= 1, got {self.max_sweeps}")


def robot_active(world: World, robot_action: int, human_action: int) -> bool:
    """Whether the robot's action counts as activity in the cycle's terms.

    ``wait`` does not, nor does an unknown action (-1), nor a ``give`` the human does not
    answer with a ``take``: an offer that lapses is the robot waiting with its arm out.
    Without that last rule an unanswered give would be free busy-work that lowers
    ``effort_balance`` (found by the exhaustive reference in the tests).
    """
    if robot_action < 0:
        return False
    kind = world.actions(Agent.ROBOT)[robot_action].kind
    if kind is Kind.WAIT:
        return False
    return kind is not Kind.GIVE or world.actions(Agent.HUMAN)[human_action].kind is Kind.TAKE


def cycle_terms(d_robot: float, active_robot: bool, d_human: float, active_human: bool, holding: bool) -> Terms:
    """Raw terms of one cycle.

    Args:
        d_robot: duration of the robot's action (0 when the cycle has no robot part, i.e.
            the plan starts at the human's turn and the robot's action is unknown).
        active_robot: whether the robot's action counts as activity (:func:`robot_active`).
        d_human: duration of the human's action.
        active_human: whether the human's action is not a ``wait``.
        holding: whether the human holds an object after the cycle.
    """
    dt = cycle_length(d_robot, d_human)
    e_r = d_robot if active_robot else 0.0
    e_h = d_human if active_human else 0.0
    return Terms(dt, e_h, max(0.0, e_h - e_r), dt - e_h, dt if holding else 0.0)


def cycle_cost(
    weights: tuple[float, ...], d_robot: float, active_robot: bool, d_human: float, active_human: bool, holding: bool
) -> float:
    """Weighted cost of one cycle: ``CostWeights.total(cycle_terms(...))`` in one pass.

    The search's inner loop calls this for every edge, so it takes the weights as a plain
    tuple (:attr:`CostWeights.vector`) and builds no :class:`Terms`; a test checks it
    against ``total(cycle_terms(...))``.
    """
    w_time, w_effort, w_balance, w_idle, w_holding = weights
    dt = d_robot if d_robot > d_human else d_human  # cycle_length, inlined in the search's inner loop
    e_h = d_human if active_human else 0.0
    e_r = d_robot if active_robot else 0.0
    cost = w_time * dt + w_effort * e_h + w_idle * (dt - e_h)
    if e_h > e_r:
        cost += w_balance * (e_h - e_r)
    if holding:
        cost += w_holding * dt
    return cost
