"""``preference``: a scripted human whose preferences are weights over the task's events.

In the spirit of HSP's event-weighted rewards (hidden-utility partners), each member
of this family scores every feasible action by the events it causes and acts on the
best score; a population is a set of weight vectors (:mod:`.population`).

Scores (one-step lookahead, all weights are parameters):

- holding ``o``: ``throw(o)`` scores ``self_work`` (the human does the work itself),
  ``give(o)`` scores ``handover``, ``place(o, s)`` scores ``shared`` on a spot the
  robot reaches from some location and ``keep`` on a spot only the human reaches.
- empty-handed: ``pick(o)`` scores the best of what the human could then do with
  ``o`` (the scores above, as feasible right after the pick; a ``place`` counts only
  when it moves ``o`` to the other side, since moving it within a side is no progress),
  plus ``robot_side`` when the robot can reach ``o`` itself, plus ``colour_bonus`` when
  ``o`` has the colour ``colour``. A pick with nothing to follow it is never taken.
- every action's score is lowered by ``haste`` x its duration (seconds), both steps'
  for a pick; ``wait`` scores 0.

The human takes the best action whose score is above 0 (``wait`` if none), ties broken
by the lowest action index, so the answer is a canonical function of the state; with
``temperature > 0`` it draws from the softmax of the scores (``wait`` included) instead.
A pending offer of the robot is taken with probability ``accept`` (else the offer
lapses and the human does what it would have done), and the whole answer is mixed with
``wait`` by ``p_idle``. The distribution depends on the state alone (stationary, no
robot action, no history), so the oracle can fold it into its model; it is memoised
per state, a pure cache.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from hg_marl.agents.humans.base import Distribution, StationaryHuman, check_p_idle, wait_index, with_idle
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.spec import format_spec, parse_spec

_MEMO_LIMIT = 500_000
_TIE = 1e-9
"""Scores closer than this are equal (the lowest action index wins)."""


@dataclass(frozen=True)
class _Tables:
    """What the scores need from one world, computed once."""

    robot_reaches: tuple[bool, ...]
    """Per spot: the robot reaches it from some location."""
    colour_match: tuple[bool, ...]
    """Per object: it has the preferred colour."""
    specs: tuple[tuple[Kind, int, int, float], ...]
    """The human's actions: kind, object, target, duration."""
    wait: int


class PreferenceHuman(StationaryHuman):
    """Acts on weighted events (see the module docstring for the rules).

    Args:
        handover: worth of handing the held object to the robot.
        shared: worth of putting an object within the robot's reach (a shared spot).
        self_work: worth of throwing an object into a bin oneself.
        keep: worth of putting an object where only the human reaches (negative: never hoards).
        robot_side: added to picking an object the robot could reach itself.
        colour: objects of this colour get ``colour_bonus`` when picked ('' for none;
            a colour no object has gives no bonus, so a population carries over to
            another scenario).
        colour_bonus: added to picking an object of ``colour``.
        haste: seconds cost: each action's score is lowered by ``haste`` x its duration.
        accept: probability of taking what the robot offers.
        p_idle: probability of doing nothing at any turn.
        temperature: 0 takes the best action; > 0 draws from the softmax of the scores.
    """

    name = "preference"

    def __init__(
        self,
        handover: float = 1.0,
        shared: float = 0.5,
        self_work: float = 1.0,
        keep: float = -1.0,
        robot_side: float = -0.5,
        colour: str = "",
        colour_bonus: float = 0.0,
        haste: float = 0.0,
        accept: float = 1.0,
        p_idle: float = 0.0,
        temperature: float = 0.0,
    ) -> None:
        super().__init__()
        weights = {
            "handover": handover,
            "shared": shared,
            "self_work": self_work,
            "keep": keep,
            "robot_side": robot_side,
            "colour_bonus": colour_bonus,
            "haste": haste,
            "temperature": temperature,
        }
        for key, value in weights.items():
            if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
                raise ValueError(f"{key} must be a finite number, got {value!r}")
        if haste < 0:
            raise ValueError(f"haste must be >= 0 (a cost per second), got {haste}")
        if temperature < 0:
            raise ValueError(f"temperature must be >= 0, got {temperature}")
        if not isinstance(colour, str):
            raise ValueError(f"colour must be a colour name, got {colour!r}")
        self.handover, self.shared, self.self_work, self.keep = (
            float(handover),
            float(shared),
            float(self_work),
            float(keep),
        )
        self.robot_side, self.colour, self.colour_bonus = float(robot_side), colour, float(colour_bonus)
        self.haste, self.temperature = float(haste), float(temperature)
        if not 0.0 <= accept <= 1.0:
            raise ValueError(f"accept must be a probability in [0, 1], got {accept}")
        self.accept = float(accept)
        self.p_idle = check_p_idle(p_idle)
        self._world: World | None = None
        self._tables: _Tables | None = None
        self._memo: dict[State, Distribution] = {}

    def _tables_for(self, world: World) -> _Tables:
        if self._world is not world or self._tables is None:
            sc = world.scenario
            self._tables = _Tables(
                robot_reaches=tuple(bool(s.reach.robot_from) for s in sc.spots),
                colour_match=tuple(bool(self.colour) and c == self.colour for c in sc.object_colours),
                specs=tuple((s.kind, s.obj, s.target, s.duration) for s in world.table.specs[Agent.HUMAN]),
                wait=wait_index(world),
            )
            self._world = world
            self._memo = {}
        return self._tables

    def _held_score(self, kind: Kind, target: int, duration: float, robot_reaches: tuple[bool, ...]) -> float:
        """The worth of one action on the held object."""
        if kind is Kind.THROW:
            worth = self.self_work
        elif kind is Kind.GIVE:
            worth = self.handover
        else:  # PLACE
            worth = self.shared if robot_reaches[target] else self.keep
        return worth - self.haste * duration

    def scores(self, world: World, state: State) -> dict[int, float]:
        """Each feasible action's score (``take`` and worthless picks excluded; ``wait`` is 0)."""
        t = self._tables_for(world)
        table = world.table
        specs, robot_reaches = t.specs, t.robot_reaches
        out: dict[int, float] = {}
        for index in table.feasible_indices(state, Agent.HUMAN):
            kind, o, target, duration = specs[index]
            if kind is Kind.WAIT:
                out[index] = 0.0
            elif kind is Kind.TAKE:
                continue
            elif kind is Kind.PICK:
                after, _ = table.successor_feasible(state, Agent.HUMAN, index)
                origin = state.where[o]
                from_robot_side = robot_reaches[origin]
                best = -math.inf
                for follow in table.feasible_indices(after, Agent.HUMAN):
                    k2, _, t2, d2 = specs[follow]
                    if k2 is Kind.WAIT or (k2 is Kind.PLACE and (t2 == origin or robot_reaches[t2] == from_robot_side)):
                        continue
                    best = max(best, self._held_score(k2, t2, d2, robot_reaches))
                if best == -math.inf:
                    continue
                bonus = (self.robot_side if from_robot_side else 0.0) + (
                    self.colour_bonus if t.colour_match[o] else 0.0
                )
                out[index] = best + bonus - self.haste * duration
            else:
                out[index] = self._held_score(kind, target, duration, robot_reaches)
        return out

    def _choice(self, scores: dict[int, float], wait: int) -> Distribution:
        """The best-scoring action (> 0, lowest index on ties), or the softmax of the scores."""
        if self.temperature > 0.0:
            top = max(scores.values())
            weights = {i: math.exp((s - top) / self.temperature) for i, s in scores.items()}
            total = sum(weights.values())
            return sorted((i, w / total) for i, w in weights.items())
        best, best_score = wait, _TIE
        for index in sorted(scores):
            if index != wait and scores[index] > best_score + _TIE:
                best, best_score = index, scores[index]
        return [(best, 1.0)]

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """Take an offer with ``accept``; else the best-scoring action; mixed with ``wait`` by ``p_idle``."""
        self._tables_for(world)
        found = self._memo.get(state)
        if found is not None:
            return found
        t = self._tables
        assert t is not None
        dist = self._choice(self.scores(world, state), t.wait)
        hand = world.table.hand[Agent.HUMAN]
        if state.offer_by == Agent.ROBOT and hand not in state.where and self.accept > 0.0:
            take = world.table.action_index(Agent.HUMAN, Kind.TAKE, state.offer_obj)
            merged = {take: self.accept}
            for index, p in dist:
                merged[index] = merged.get(index, 0.0) + (1.0 - self.accept) * p
            dist = sorted((i, p) for i, p in merged.items() if p > 0.0)
        dist = with_idle(dist, world, self.p_idle)
        if len(self._memo) > _MEMO_LIMIT:
            self._memo.clear()
        self._memo[state] = dist
        return dist


def never_takes(spec: str) -> str:
    """``spec`` as the same partner who never takes what the robot offers (``accept=0``).

    The belief robot plans against a member this way once its partner has refused more
    offers than the member's ``accept`` explains: the member's exact best response then
    plans no handover to the partner. A spec of another human is returned unchanged (no
    parameter of theirs says it).
    """
    parsed = parse_spec(spec)
    if parsed.name != PreferenceHuman.name:
        return spec
    return format_spec(parsed.name, {**parsed.raw, "accept": "0.0"})
