"""What every scripted human shares: the stationary-policy base class and the geometry helpers.

A *stationary* human is one whose choice depends on the symbolic state only (not on the
clock, the history or the tasks solved). It implements
``distribution(world, state) -> list[(action_index, probability)]`` and acts by sampling
that distribution with its own generator. The oracle (:mod:`hg_marl.agents.oracle`) folds
exactly this distribution into its model, so what the oracle optimises against and what
the human does in the environment can never drift apart.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Sequence

import numpy as np

from hg_marl.core import WAIT, Action, Agent, Kind, State, World
from hg_marl.core.cycle import seen
from hg_marl.core.errors import HumanError as HumanError  # re-exported: humans raise it
from hg_marl.policy import Turn

Distribution = list[tuple[int, float]]
"""A human's action distribution at one state: ``[(action_index, probability), ...]``."""


class StationaryHuman(ABC):
    """Base class of the humans whose policy is a function of the state.

    Subclasses implement :meth:`distribution`; :meth:`act` samples it with the generator
    handed over in :meth:`reset`. A single-action distribution consumes no random number,
    so deterministic humans leave their generator untouched.
    """

    name = "stationary"
    """Registry name (overridden by subclasses)."""
    uses_robot_action = False
    """Whether :meth:`distribution` depends on the robot's action under way this cycle."""
    equivariant = False
    """Whether relabelling interchangeable objects (same bins) in the state relabels the
    answer the same way and changes nothing else. The oracle then keeps one state per
    relabelling class (exact only in that case). A rule that picks "the first object"
    by index is not: it picks another object once the labels are swapped."""

    def __init__(self) -> None:
        self.world: World | None = None
        self.agent = Agent.HUMAN
        self.rng = np.random.default_rng(0)
        self.last_decision: dict[str, object] = {}

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Start a run in ``world`` in seat ``agent``; take ownership of ``rng``."""
        self.world = world
        self.agent = agent
        self.rng = rng

    @abstractmethod
    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """The probability of each action this human may take in ``state`` (sums to 1).

        ``robot_action`` is the robot's successful action of this cycle (-1: unknown or
        failed); only humans with ``uses_robot_action`` look at it (a planning human
        needs its duration: the cycle lasts the longer of the two actions).
        """

    def act(self, turn: Turn) -> int:
        """Sample :meth:`distribution` at the turn's state."""
        dist = self.distribution(turn.world, turn.state, robot_action_of(turn) if self.uses_robot_action else -1)
        index = sample(dist, self.rng)
        self.last_decision = {"human": self.name, "action": turn.world.action_names[turn.agent][index]}
        return index


def robot_action_of(turn: Turn) -> int:
    """The robot's action of this cycle if it succeeded, else -1 (``cycle.seen``, read from the turn's events)."""
    return seen(turn.last_actions[0], not any(e.kind == "failed" and e.agent == "robot" for e in turn.events))


def sample(dist: Distribution, rng: np.random.Generator) -> int:
    """Draw one action index from ``dist`` (no draw at all when there is one choice)."""
    if len(dist) == 1:
        return dist[0][0]
    probs = np.array([p for _, p in dist], dtype=float)
    k = int(rng.choice(len(dist), p=probs / probs.sum()))
    return dist[k][0]


def deterministic(index: int) -> Distribution:
    """The distribution that always picks ``index``."""
    return [(index, 1.0)]


def check_p_idle(p_idle: float) -> float:
    """Validate the idle probability every scripted human takes."""
    if not 0.0 <= p_idle <= 1.0:
        raise ValueError(f"p_idle must be a probability in [0, 1], got {p_idle}")
    return float(p_idle)


def with_idle(dist: Distribution, world: World, p_idle: float) -> Distribution:
    """Mix ``dist`` with ``wait`` taken with probability ``p_idle``."""
    if p_idle <= 0.0:
        return dist
    wait = world.index(Agent.HUMAN, WAIT)
    merged: dict[int, float] = {wait: p_idle}
    for index, p in dist:
        merged[index] = merged.get(index, 0.0) + (1.0 - p_idle) * p
    return sorted(merged.items())


def wait_index(world: World) -> int:
    """The human's ``wait`` index."""
    return world.index(Agent.HUMAN, WAIT)


def human_spots(world: World) -> tuple[int, ...]:
    """Spots the human reaches: its "area"."""
    return tuple(s for s, spot in enumerate(world.scenario.spots) if spot.reach.human)


def shared_spots(world: World) -> tuple[int, ...]:
    """Spots both the human and the robot (from some location) reach, e.g. ``mat_shared``."""
    return tuple(s for s, spot in enumerate(world.scenario.spots) if spot.reach.human and spot.reach.robot_from)


def human_only_spots(world: World) -> tuple[int, ...]:
    """Spots only the human reaches: whatever lies there the robot cannot get alone."""
    return tuple(s for s, spot in enumerate(world.scenario.spots) if spot.reach.human and not spot.reach.robot_from)


def first_feasible(world: World, state: State, candidates: Sequence[int]) -> int:
    """The first of ``candidates`` (human action indices) feasible in ``state``, or -1."""
    acts = world.actions(Agent.HUMAN)
    for index in candidates:
        if world.feasible(state, Agent.HUMAN, acts[index]):
            return index
    return -1


def index_of(world: World, kind: Kind, obj: int, target: int = -1) -> int:
    """The human's index of the ground action ``(kind, obj, target)``."""
    return world.index(Agent.HUMAN, Action(kind, obj, target))


def tidy_action(world: World, state: State, *, give: bool) -> int:
    """The helpful action of a human who only handles objects in its own area, or -1.

    Holding an object: throw it if its bin is within reach, else hand it over (when
    ``give`` and the robot stands at a handover location), else put it on a free
    shared spot. Empty-handed: pick an object from the human's area that it can do
    something with: one whose bin it reaches, or one the robot cannot reach from
    anywhere (it then moves it within the robot's reach). Objects the robot can already
    reach are left alone, so the human never undoes its own work.
    """
    held = world.holding(state, Agent.HUMAN)
    if held >= 0:
        options = [index_of(world, Kind.THROW, held)]
        if give:
            options.append(index_of(world, Kind.GIVE, held))
        options += [index_of(world, Kind.PLACE, held, s) for s in shared_spots(world)]
        return first_feasible(world, state, options)
    free_shared = any(s not in state.where for s in shared_spots(world))
    can_hand_over = give and state.robot_at in world.scenario.handover_locations
    only_human = human_only_spots(world)
    for o, place in enumerate(state.where):
        if place >= world.n_spots or not world.spot_reachable(state, Agent.HUMAN, place):
            continue
        bin_ok = world.table.throw_to[Agent.HUMAN][state.robot_at][o] >= 0  # some bin accepting o in reach
        if bin_ok or (place in only_human and (free_shared or can_hand_over)):
            return index_of(world, Kind.PICK, o)
    return -1
