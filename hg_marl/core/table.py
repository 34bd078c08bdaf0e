"""The task's rules compiled into one table: feasibility and transitions by action index.

:class:`RuleTable` is built once per :class:`~hg_marl.core.World` from its scenario and
durations, and it is the only place where the rules are written. ``World.step``, the
action masks, the planner's search, the oracle and the humans all ask it, so none of
them can drift from the environment. The rules (see ``docs/task.md``):

- ``pick(o)``: hand empty, ``o`` on a spot the agent reaches.
- ``throw(o)``: holding ``o``, and some bin that accepts ``o``'s colour reachable; ``o``
  goes into the first such bin in scenario order (the robot's reach depends on where it
  stands, so *which* bin is chosen by where the thrower is).
- ``give(o)``: holding ``o``, robot at a handover location; the agent is then offering.
- ``take(o)``: the partner offered ``o`` on its last turn, hand empty. Any other reply
  (a failed action included) lets the offer lapse and the giver keeps ``o``.
- ``place(o, s)`` (human): holding ``o``, ``s`` free and within the human's reach.
- ``goto(x)`` (robot): ``x`` (an object on a spot, a bin, the human) is out of reach
  now and reachable from some location; the robot moves to the first such location in
  scenario order.
- ``wait``: always feasible.

Everything that depends only on the scenario (who reaches what from where, where a
throw lands, where a goto leads) is tabulated here, indexed by agent, robot location,
object and place code; what is left for a state is a few tuple look-ups. Adding an
action kind means: a :class:`~hg_marl.core.Kind` member, its ground actions in
:meth:`RuleTable.actions`, its precondition in :meth:`RuleTable.feasible` and
:meth:`RuleTable.feasible_indices`, its effect in :meth:`RuleTable.successor`.
"""

from __future__ import annotations

from operator import contains
from typing import NamedTuple

from hg_marl.core.durations import Durations
from hg_marl.core.scenario import Scenario
from hg_marl.core.types import WAIT, Action, Agent, Kind, State


class Spec(NamedTuple):
    """One ground action as the table stores it: kind, object, target and duration."""

    kind: Kind
    obj: int
    target: int
    duration: float


def accepting_bins(scenario: Scenario) -> tuple[tuple[int, ...], ...]:
    """Per object, every bin that accepts its colour (an empty bin colour accepts any)."""
    return tuple(
        tuple(b for b, bn in enumerate(scenario.bins) if bn.colour in ("", colour))
        for colour in scenario.object_colours
    )


class RuleTable:
    """Feasibility and transitions of both agents' ground actions, by action index.

    Args:
        scenario: the task's layout (objects, spots, bins, robot locations).
        durations: how long each action kind takes.

    Place codes (``State.where``): spots ``0..M-1``, bins ``M..M+B-1``, the robot's hand
    ``M+B``, the human's hand ``M+B+1``.
    """

    def __init__(self, scenario: Scenario, durations: Durations) -> None:
        sc = scenario
        self.n_objects = n = len(sc.objects)
        self.n_spots = m = len(sc.spots)
        self.n_bins = b = len(sc.bins)
        self.n_places = m + b + 2
        self.hand = (m + b, m + b + 1)
        """Place codes of the robot's and the human's hands, indexed by Agent."""
        self.durations = durations
        self.bins_of = accepting_bins(sc)
        """Per object, the bins that accept it."""
        self.done = tuple(frozenset(m + k for k in bins) for bins in self.bins_of)
        """Per object, the place codes where it is disposed of."""
        self.n_locations = n_locs = len(sc.robot_locations)
        self.handover = sc.handover_locations
        spot_robot = tuple(s.reach.robot_from for s in sc.spots)
        self.spot_human = tuple(s.reach.human for s in sc.spots)
        self.bin_robot = tuple(bn.reach.robot_from for bn in sc.bins)
        self.bin_human = tuple(bn.reach.human for bn in sc.bins)
        self.spot_robot = spot_robot
        # reach[agent][robot_at][spot]: whether the agent reaches the spot
        self.reach = (
            tuple(tuple(at in locs for locs in spot_robot) for at in range(n_locs)),
            tuple(self.spot_human for _ in range(n_locs)),
        )
        # throw_to[agent][robot_at][o]: the bin place code a throw of o lands in, or -1
        self.throw_to = tuple(
            tuple(
                tuple(next((m + k for k in self.bins_of[o] if self._bin_reached(agent, at, k)), -1) for o in range(n))
                for at in range(n_locs)
            )
            for agent in Agent
        )
        self.give_ok = tuple(at in self.handover for at in range(n_locs))
        # goto: objects' destination by (robot_at, place of the object); bins and the human by robot_at
        self.goto_obj = tuple(
            tuple(self._dest(at, spot_robot[p]) if p < m else -1 for p in range(self.n_places)) for at in range(n_locs)
        )
        statics = (*self.bin_robot, self.handover)
        self.goto_static = tuple(tuple(self._dest(at, reach) for reach in statics) for at in range(n_locs))
        self.actions = (self._robot_actions(), self._human_actions())
        """Each agent's ground actions; position = the Discrete action index."""
        self.specs = tuple(
            tuple(Spec(a.kind, a.obj, a.target, durations.of(a.kind)) for a in acts) for acts in self.actions
        )
        self.index = tuple({a: i for i, a in enumerate(acts)} for acts in self.actions)
        self.wait = (len(self.actions[0]) - 1, len(self.actions[1]) - 1)
        """Index of ``wait`` per agent (always the last action)."""
        self._first = tuple(
            {k: min(i for i, a in enumerate(acts) if a.kind is k) for k in Kind if any(a.kind is k for a in acts)}
            for acts in self.actions
        )

    # ---- construction ------------------------------------------------------------
    def _bin_reached(self, agent: Agent, at: int, k: int) -> bool:
        return at in self.bin_robot[k] if agent is Agent.ROBOT else self.bin_human[k]

    @staticmethod
    def _dest(at: int, reach: frozenset[int]) -> int:
        return min(reach) if reach and at not in reach else -1

    def _robot_actions(self) -> tuple[Action, ...]:
        n = self.n_objects
        acts = [Action(k, o) for k in (Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE) for o in range(n)]
        acts += [Action(Kind.GOTO, -1, t) for t in range(n + self.n_bins + 1)]
        return (*acts, WAIT)

    def _human_actions(self) -> tuple[Action, ...]:
        n = self.n_objects
        acts = [Action(k, o) for k in (Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE) for o in range(n)]
        acts += [Action(Kind.PLACE, o, s) for o in range(n) for s in range(self.n_spots)]
        return (*acts, WAIT)

    def action_index(self, agent: int, kind: Kind, obj: int = -1, target: int = -1) -> int:
        """Index of a ground action from its parts (no ``Action`` object needed)."""
        first = self._first[agent][kind]
        if kind is Kind.WAIT:
            return first
        if kind is Kind.GOTO:
            return first + target
        if kind is Kind.PLACE:
            return first + obj * self.n_spots + target
        return first + obj

    # ---- state questions -----------------------------------------------------------
    def is_clean(self, where: tuple[int, ...]) -> bool:
        """Every object is in a bin that accepts it."""
        return all(map(contains, self.done, where))

    def solves(self, state: State, agent: int, index: int) -> bool:
        """Whether ``agent``'s action ``index`` completes the task in ``state``: the robot waits on a clean table.

        The task's one reward rule (``wait`` is always feasible, so nothing else is asked);
        ``World.step`` rewards it, the robot-turn models end an episode on it.
        """
        return agent == Agent.ROBOT and index == self.wait[agent] and self.is_clean(state.where)

    def goto_destination(self, state: State, target: int) -> int:
        """Where ``goto(target)`` takes the robot from ``state``, or -1 if infeasible."""
        n = self.n_objects
        if target < n:
            return self.goto_obj[state.robot_at][state.where[target]]
        return self.goto_static[state.robot_at][target - n]

    # ---- rules -------------------------------------------------------------------
    def feasible(self, state: State, agent: int, index: int) -> bool:
        """Whether action ``index``'s preconditions hold for ``agent`` in ``state``."""
        kind, o, target, _ = self.specs[agent][index]
        if kind is Kind.WAIT:
            return True
        where, at = state.where, state.robot_at
        if kind is Kind.GOTO:
            return self.goto_destination(state, target) >= 0
        hand = self.hand[agent]
        if kind is Kind.PICK:
            p = where[o]
            return p < self.n_spots and hand not in where and self.reach[agent][at][p]
        if kind is Kind.TAKE:
            return state.offer_by == 1 - agent and state.offer_obj == o and hand not in where
        if where[o] != hand:
            return False
        if kind is Kind.THROW:
            return self.throw_to[agent][at][o] >= 0
        if kind is Kind.GIVE:
            return self.give_ok[at]
        # PLACE
        return self.spot_human[target] and target not in where

    def successor(self, state: State, agent: int, index: int) -> tuple[State, bool, float]:
        """The transition: next state, whether the action succeeded, its duration.

        A pending offer by the partner lapses unless this is its ``take``; an infeasible
        action changes nothing else and lasts ``durations.failed``.
        """
        where, at, by, obj = state
        if by == 1 - agent:
            spec = self.specs[agent][index]
            if not (spec.kind is Kind.TAKE and spec.obj == obj):
                state = State(where, at)
        if not self.feasible(state, agent, index):
            return State(where, at) if state.offer_by == 1 - agent else state, False, self.durations.failed
        nxt, d = self.successor_feasible(state, agent, index)
        return nxt, True, d

    def successor_feasible(self, state: State, agent: int, index: int) -> tuple[State, float]:
        """Next state and duration of an action known to be feasible (the planner's fast path)."""
        kind, o, target, d = self.specs[agent][index]
        where, at, by, obj = state
        if by >= 0 and by != agent and not (kind is Kind.TAKE and o == obj):
            by = obj = -1
        if kind is Kind.PICK:
            where = (*where[:o], self.hand[agent], *where[o + 1 :])
        elif kind is Kind.THROW:
            where = (*where[:o], self.throw_to[agent][at][o], *where[o + 1 :])
        elif kind is Kind.PLACE:
            where = (*where[:o], target, *where[o + 1 :])
        elif kind is Kind.TAKE:
            where = (*where[:o], self.hand[agent], *where[o + 1 :])
            by = obj = -1
        elif kind is Kind.GIVE:
            by, obj = agent, o
        elif kind is Kind.GOTO:
            n = self.n_objects
            at = self.goto_obj[at][where[target]] if target < n else self.goto_static[at][target - n]
        return State(where, at, by, obj), d

    def feasible_indices(self, state: State, agent: int) -> list[int]:
        """Sorted indices of the actions whose preconditions hold.

        Enumerates what the agent's hand and reach allow instead of testing every
        action, so it costs O(objects + spots), not O(actions); a property test checks
        it against :meth:`feasible` action by action.
        """
        where, at, by, obj = state
        hand = self.hand[agent]
        first = self._first[agent]
        out: list[int] = []
        if hand not in where:
            reach = self.reach[agent][at]
            m = self.n_spots
            pick = first[Kind.PICK]
            out += [pick + o for o, p in enumerate(where) if p < m and reach[p]]
            if by == 1 - agent:
                out.append(first[Kind.TAKE] + obj)
        else:
            held = where.index(hand)
            if self.throw_to[agent][at][held] >= 0:
                out.append(first[Kind.THROW] + held)
            if self.give_ok[at]:
                out.append(first[Kind.GIVE] + held)
            if agent == Agent.HUMAN:
                place = first[Kind.PLACE] + held * self.n_spots
                out += [place + s for s, ok in enumerate(self.spot_human) if ok and s not in where]
        if agent == Agent.ROBOT:
            goto = first[Kind.GOTO]
            dest = self.goto_obj[at]
            out += [goto + t for t, p in enumerate(where) if dest[p] >= 0]
            n = self.n_objects
            out += [goto + n + k for k, d in enumerate(self.goto_static[at]) if d >= 0]
        out.sort()
        out.append(self.wait[agent])
        return out
