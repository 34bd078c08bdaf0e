"""Plans and planning results: two timed streams with cross-stream links.

A :class:`Plan` is first a sequence of joint cycles ``(robot action, human action)``, the
unit the environment executes; the per-agent streams, their times and the links are
derived from it with the scenario's durations, so the two views cannot disagree.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property, reduce
from operator import add
from typing import NamedTuple

import numpy as np

from hg_marl.agents.planner.costs import CostWeights, Terms, cycle_terms, robot_active
from hg_marl.core import Agent, Kind, State, World

NO_ACTION = -1
"""Robot action of a plan's first cycle when planning started at the human's turn."""


class Step(NamedTuple):
    """One action in an agent's stream."""

    agent: Agent
    action: int
    name: str
    cycle: int
    start: float
    end: float
    obj: int
    method: str


class Link(NamedTuple):
    """A cross-stream dependency between two steps, each given as (agent, index in its stream).

    ``kind`` is ``"handover"`` (a give and the take that answers it: same cycle when the
    robot gives, next cycle when the human gives) or ``"waits_for"`` (a wait whose agent's
    next step needs the source step to have happened).
    """

    kind: str
    source: tuple[Agent, int]
    target: tuple[Agent, int]


@dataclass(frozen=True)
class Plan:
    """A joint plan, from the state it was made for to the robot's completing ``wait``."""

    cycles: tuple[tuple[int, int], ...]
    """Per cycle, (robot action index, human action index); the robot's is -1 in the first
    cycle when the plan starts at the human's turn."""
    states: tuple[State, ...]
    """The state before each cycle's robot action (the root itself for a human-turn start),
    then the state after the last cycle: ``len(cycles) + 1`` entries."""
    first_to_move: Agent
    """Who acts first."""
    terms: tuple[Terms, ...]
    """Raw cost terms of each cycle."""
    world: World = field(compare=False, repr=False)
    """The rules the streams are read with."""
    durations: tuple[tuple[float, float], ...] = field(compare=False, repr=False)
    """Per cycle, the robot's and the human's action durations as replayed."""
    mids: tuple[State, ...] = field(default=(), compare=False, repr=False)
    """Per cycle, the state after its robot action (the cycle's start where it has none), as replayed."""

    @cached_property
    def streams(self) -> tuple[tuple[Step, ...], tuple[Step, ...]]:
        """The robot's and the human's steps with start and end times (seconds from now).

        Derived on first use: the search's callers (the robot's next action, the humans'
        intents) read the cycles and terms only, and naming the steps costs more than the
        search on small tables.
        """
        return _streams(self.world, self.cycles, self.durations, self.terms)

    @cached_property
    def links(self) -> tuple[Link, ...]:
        """Handover and waiting dependencies between the streams."""
        return _links(self.world, *self.streams)

    @property
    def duration(self) -> float:
        """Predicted seconds until the task completes."""
        return sum(t.time for t in self.terms)

    @property
    def totals(self) -> Terms:
        """Raw cost terms summed over the plan: each term added cycle after cycle from 0.0
        (``Terms() + t1 + t2 + ...``, the same additions in the same order)."""
        return Terms(*[reduce(add, column, 0.0) for column in zip(*self.terms, strict=True)])

    def cost(self, weights: CostWeights) -> float:
        """Weighted cost of the plan."""
        return weights.total(self.totals)

    def __len__(self) -> int:
        return len(self.cycles)


@dataclass(frozen=True)
class PlanResult:
    """What a planning call returns; failure is a value with a reason, never an empty list."""

    success: bool
    """Whether a plan was found."""
    plan: Plan | None
    """The plan, or None on failure."""
    cost: float
    """Its cost (expected cost under a stochastic human model); inf on failure."""
    breakdown: dict[str, float]
    """Weighted contribution of each cost term (sums to ``cost``); empty on failure."""
    nodes: int
    """Nodes expanded by the search (0 when served from the cache)."""
    wall_time: float
    """Seconds spent in this call."""
    reason: str = ""
    """Why planning failed: starts with 'unreachable', 'budget' or 'no plan'; '' on success."""
    optimal: bool = False
    """Whether the cost is proven minimal."""
    robot_action: int = -1
    """The robot's next action index (its ``wait`` on failure or when it waits for the human)."""
    human_action: int = -1
    """The human action the plan expects next, -1 if none or on failure."""
    cached: bool = False
    """Whether the result came from the planner's cache."""
    extras: dict[str, float] = field(default_factory=dict)
    """Model-specific figures (e.g. the nominal plan's own cost under a stochastic model)."""

    def action_distribution(self, n_actions: int, agent: Agent = Agent.ROBOT) -> np.ndarray:
        """The planner's action distribution for the MetaController (docs/task.md, section 4).

        ``1 - (N - 1) * 0.01`` on the planned action and ``0.01`` on each other one; uniform
        (maximum entropy) when there is no planned action for ``agent``.
        """
        action = self.robot_action if agent is Agent.ROBOT else self.human_action
        if not self.success or not 0 <= action < n_actions:
            return np.full(n_actions, 1.0 / n_actions)
        out = np.full(n_actions, 0.01)
        out[action] = 1.0 - (n_actions - 1) * 0.01
        return out


def failure(reason: str, nodes: int, wall_time: float, robot_wait: int) -> PlanResult:
    """A failed result with its reason."""
    return PlanResult(False, None, float("inf"), {}, nodes, wall_time, reason, False, robot_wait, -1)


def build_plan(
    world: World,
    root: State,
    first_to_move: Agent,
    cycles: list[tuple[int, int]],
    robot_part: tuple[float, int] = (0.0, NO_ACTION),
    replayed: list[tuple[State, State]] | None = None,
) -> Plan:
    """Replay ``cycles`` from ``root`` with the rule table: states, durations and terms (streams and links on use).

    Args:
        world: the rules.
        root: the state the plan starts from.
        first_to_move: ``HUMAN`` when the first cycle has no robot action.
        cycles: (robot, human) action indices per cycle.
        robot_part: for a human-turn start, the duration and index of the robot's action
            already under way in the first cycle; ``(0, -1)`` if unknown.
        replayed: per cycle, the states after its robot action and after the cycle, where
            the caller has them (a search's path: it applied the same rules); the actions'
            durations are then read from the rule table's specs, as a replay returns them.
    """
    hand_h = world.hand[Agent.HUMAN]
    wait_h = world.n_actions(Agent.HUMAN) - 1
    table = world.table
    successor, specs = table.successor, table.specs  # what ``World.step`` returns, without its events
    states, terms, durations, mids = [root], [], [], []
    state = root
    for k, (ar, ah) in enumerate(cycles):
        if replayed is not None:
            mid, state = replayed[k]
            d_r, r_act = robot_part if ar == NO_ACTION else (specs[0][ar].duration, ar)
            d_h = specs[1][ah].duration
            mids.append(mid)
        else:
            if ar == NO_ACTION:
                d_r, r_act = robot_part
            else:
                state, _, d_r = successor(state, Agent.ROBOT, ar)
                r_act = ar
            mids.append(state)
            state, _, d_h = successor(state, Agent.HUMAN, ah)
        terms.append(cycle_terms(d_r, robot_active(world, r_act, ah), d_h, ah != wait_h, hand_h in state.where))
        states.append(state)
        durations.append((d_r, d_h))
    return Plan(tuple(cycles), tuple(states), first_to_move, tuple(terms), world, tuple(durations), tuple(mids))


def _streams(
    world: World,
    cycles: tuple[tuple[int, int], ...],
    durations: tuple[tuple[float, float], ...],
    terms: tuple[Terms, ...],
) -> tuple[tuple[Step, ...], tuple[Step, ...]]:
    """Each agent's steps of a replayed plan, timed by its cycles' terms, with their methods named."""
    robot_acts, human_acts = world.actions(Agent.ROBOT), world.actions(Agent.HUMAN)
    names = world.action_names
    streams: tuple[list[Step], list[Step]] = ([], [])
    clock = 0.0
    for k, (ar, ah) in enumerate(cycles):
        d_r, d_h = durations[k]
        if ar != NO_ACTION:
            streams[0].append(Step(Agent.ROBOT, ar, names[0][ar], k, clock, clock + d_r, robot_acts[ar].obj, ""))
        streams[1].append(Step(Agent.HUMAN, ah, names[1][ah], k, clock, clock + d_h, human_acts[ah].obj, ""))
        clock += terms[k].time
    return _label_methods(world, streams)


def _label_methods(world: World, streams: tuple[list[Step], list[Step]]) -> tuple[tuple[Step, ...], tuple[Step, ...]]:
    """Name the ``dispose(o)`` method each object's steps belong to."""
    kinds: dict[int, set[tuple[Agent, Kind]]] = {}
    for stream in streams:
        for s in stream:
            if s.obj >= 0:
                kinds.setdefault(s.obj, set()).add((s.agent, world.actions(s.agent)[s.action].kind))
    method = {}
    for o, ks in kinds.items():
        if (Agent.HUMAN, Kind.GIVE) in ks:
            method[o] = "handover_h2r"
        elif (Agent.ROBOT, Kind.GIVE) in ks:
            method[o] = "handover_r2h"
        elif (Agent.HUMAN, Kind.PLACE) in ks:
            method[o] = "human_places"
        elif all(agent is Agent.HUMAN for agent, _ in ks):
            method[o] = "human_alone"
        else:
            method[o] = "robot_alone"
    return tuple(  # type: ignore[return-value]
        tuple(s._replace(method=method.get(s.obj, "")) for s in stream) for stream in streams
    )


def _links(world: World, robot: tuple[Step, ...], human: tuple[Step, ...]) -> tuple[Link, ...]:
    links: list[Link] = []
    streams = (robot, human)
    kind_of = [[world.actions(ag)[s.action].kind for s in streams[ag]] for ag in Agent]
    # handovers: a give, and the partner's take of the same object right after it
    for giver in Agent:
        taker = giver.other
        for i, s in enumerate(streams[giver]):
            if kind_of[giver][i] is not Kind.GIVE:
                continue
            cycle = s.cycle if giver is Agent.ROBOT else s.cycle + 1
            for j, t in enumerate(streams[taker]):
                if t.cycle == cycle and kind_of[taker][j] is Kind.TAKE and t.obj == s.obj:
                    links.append(Link("handover", (giver, i), (taker, j)))
    # waits: an agent waiting because its next step on an object needs the partner's step
    for agent in Agent:
        own, other = streams[agent], streams[agent.other]
        for i, s in enumerate(own):
            if kind_of[agent][i] is not Kind.WAIT:
                continue
            nxt = next((n for j, n in enumerate(own) if j > i and kind_of[agent][j] is not Kind.WAIT), None)
            if nxt is None or nxt.obj < 0:
                continue
            # partner steps on the same object strictly before nxt in execution order
            before = [
                (j, t)
                for j, t in enumerate(other)
                if t.obj == nxt.obj
                and (t.cycle < nxt.cycle or (t.cycle == nxt.cycle and agent is Agent.HUMAN))
                and t.cycle >= s.cycle
            ]
            if before:
                links.append(Link("waits_for", (agent.other, before[-1][0]), (agent, i)))
    return tuple(links)
