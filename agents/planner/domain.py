"""The HTN domain: ``clean_table`` -> ``dispose(o)`` for every object not in its bin.

``dispose(o)`` has one method per way an object can travel from where it is to its bin.
Methods are plain functions declared to a :class:`Domain` instance (no module-level
registry; declaration order is the deterministic tie-break). Each method, given an
object's status and the robot's location, answers two questions for the search:

- which primitive step each agent may take next on ``o`` (the *relevance filter*: an
  action is a candidate only if it is the next step of an applicable method), and
- how much robot and human work is left at least (the *admissible bound*).

Primitive actions are the task core's ground actions, applied with ``World.step``: the
planner cannot drift from the environment's rules. Status codes extend the core's place
codes (spot, bin, robot's hand, human's hand) with "offered by the human/robot".

Why the per-method work is a valid lower bound: every way of moving an object starts
with a pick by whoever reaches its spot and ends with a throw by whoever reaches its
bin; the robot cannot place, so robot-to-human transfers are handovers; human-to-robot
ones are handovers or a place on a spot the robot reaches. Each coordinate (robot work,
human work) of any such chain is at least that of one method below. The robot holds one
object at a time, so a move made while holding ``o`` belongs to ``o`` alone, and so does
the empty-handed move that must precede acquiring ``o`` (picking it from a spot, or
taking it at the handover location) where no place the robot ever releases an object
(:attr:`Domain.release`: a bin, or the handover location when some object can go
robot-to-human) is in reach: only the robot's first acquisition can save it, which the
bound allows for. An object may go into any bin that accepts it, so its bins' reach is
the union of theirs.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

from hg_marl.agents.planner.models import HumanModel
from hg_marl.core import Agent, Kind, State, World


class Work(NamedTuple):
    """What is left of a method: least robot and human work, next steps, least holding time.

    ``holding`` counts the seconds of the cycles that must end with the human holding
    the object (the human holds one object at a time, so they are the object's own).
    """

    robot: float
    human: float
    robot_next: frozenset[Kind]
    human_next: frozenset[Kind]
    holding: float = 0.0


MethodFn = Callable[["Domain", int, int, int], "Work | None"]
"""A method: ``(domain, obj, status, robot_at) -> Work``, or None when not applicable."""

_NONE: frozenset[Kind] = frozenset()


def robot_alone(d: Domain, o: int, status: int, at: int) -> Work | None:
    """The robot picks ``o`` (moving there), carries it to its bin and throws it."""
    t = d.dur
    bins = d.bin_locs[o]
    if not bins:
        return None
    if status < d.n_spots:
        spot = d.spot_locs[status]
        if not spot:
            return None
        carry = t.goto if not spot & bins else 0.0
        return Work(t.pick + t.throw + carry + d.empty_move[status], 0.0, frozenset({Kind.PICK}), _NONE)
    if status == d.robot_hand:
        return Work(t.throw + (t.goto if at not in bins else 0.0), 0.0, frozenset({Kind.THROW}), _NONE)
    return None


def human_alone(d: Domain, o: int, status: int, at: int) -> Work | None:
    """The human picks ``o`` from its side and throws it into a bin it reaches.

    An object already in the human's hand (or its own offer) needs only the throw: a human
    who takes but never picks still throws what it took.
    """
    t = d.dur
    if not d.bin_human[o] or not d.human_can({Kind.THROW}):
        return None
    if status < d.n_spots and d.spot_human[status]:
        if not d.human_can({Kind.PICK}):
            return None
        return Work(0.0, t.pick + t.throw, _NONE, frozenset({Kind.PICK}), t.pick)
    if status in (d.human_hand, d.human_offer):
        return Work(0.0, t.throw, _NONE, frozenset({Kind.THROW}))
    return None


def handover_r2h(d: Domain, o: int, status: int, at: int) -> Work | None:
    """The robot picks ``o``, gives it at the handover location; the human takes and throws it."""
    t = d.dur
    if not d.bin_human[o] or not d.human_can({Kind.TAKE, Kind.THROW}):
        return None
    after = t.take + t.throw
    if status < d.n_spots:
        spot = d.spot_locs[status]
        if not spot:
            return None
        carry = t.goto if not spot & d.handover else 0.0
        return Work(t.pick + t.give + carry + d.empty_move[status], after, frozenset({Kind.PICK}), _NONE, t.take)
    if status == d.robot_hand:
        move = t.goto if at not in d.handover else 0.0
        return Work(t.give + move, after, frozenset({Kind.GIVE}), _NONE, t.take)
    if status == d.robot_offer:
        return Work(0.0, after, _NONE, frozenset({Kind.TAKE}), t.take)
    return None


def handover_h2r(d: Domain, o: int, status: int, at: int) -> Work | None:
    """The human picks ``o`` and gives it; the robot takes it, carries it to its bin and throws it."""
    t = d.dur
    bins = d.bin_locs[o]
    if not bins or not d.human_can({Kind.GIVE}):
        return None
    after = t.take + t.throw + (t.goto if not d.handover & bins else 0.0)
    if status < d.n_spots and d.spot_human[status]:
        if not d.human_can({Kind.PICK}):
            return None  # on a spot, it must be picked first (as in :func:`human_alone`)
        return Work(after + d.handover_empty, t.pick + t.give, _NONE, frozenset({Kind.PICK}), t.pick + t.give)
    if status == d.human_hand:
        return Work(after + d.handover_empty, t.give, _NONE, frozenset({Kind.GIVE}), t.give)
    if status == d.human_offer:
        return Work(after, 0.0, frozenset({Kind.TAKE}), _NONE)
    return None


def human_places(d: Domain, o: int, status: int, at: int) -> Work | None:
    """The human puts ``o`` on a spot the robot reaches; the robot then disposes of it."""
    t = d.dur
    if math.isinf(d.place_then_robot[o]) or not d.human_can({Kind.PLACE}):
        return None
    robot = d.place_then_robot[o]
    if status < d.n_spots and d.spot_human[status]:
        if not d.human_can({Kind.PICK}):
            return None
        return Work(robot, t.pick + t.place, _NONE, frozenset({Kind.PICK}), t.pick)
    if status in (d.human_hand, d.human_offer):
        return Work(robot, t.place, _NONE, frozenset({Kind.PLACE}))
    return None


DEFAULT_METHODS: tuple[tuple[str, MethodFn], ...] = (
    ("robot_alone", robot_alone),
    ("handover_h2r", handover_h2r),
    ("handover_r2h", handover_r2h),
    ("human_alone", human_alone),
    ("human_places", human_places),
)
"""The methods of ``dispose(o)`` in declaration (tie-break) order."""


class Domain:
    """The HTN domain bound to a world and a human model, with its precomputed tables.

    Args:
        world: the task's rules.
        human_model: restricts which human methods apply (``allowed_kinds``).
        methods: ``(name, function)`` pairs for ``dispose(o)``; defaults to
            :data:`DEFAULT_METHODS`. More can be added with :meth:`declare` before the
            first query.
    """

    def __init__(
        self,
        world: World,
        human_model: HumanModel,
        methods: tuple[tuple[str, MethodFn], ...] = DEFAULT_METHODS,
    ) -> None:
        self.world = world
        self.human_model = human_model
        self.dur = world.durations
        sc = world.scenario
        self.n_objects, self.n_spots, self.n_bins = world.n_objects, world.n_spots, world.n_bins
        self.robot_hand, self.human_hand = world.hand
        self.human_offer = self.human_hand + 1
        self.robot_offer = self.human_hand + 2
        self.n_status = self.human_hand + 3
        self.handover = sc.handover_locations
        self.spot_locs = tuple(s.reach.robot_from for s in sc.spots)
        self.spot_human = tuple(s.reach.human for s in sc.spots)
        # an object may go into any bin that accepts it: the union of their reach
        self.bin_locs = tuple(frozenset().union(*(sc.bins[b].reach.robot_from for b in bins)) for bins in world.bins_of)
        self.bin_human = tuple(any(sc.bins[b].reach.human for b in bins) for bins in world.bins_of)
        self.release = self._release_locations()
        """Where the robot can end an object's journey: at a bin it throws into, or at the
        handover location when some object may go robot-to-human."""
        self.empty_move = tuple(self.dur.goto if locs and not locs & self.release else 0.0 for locs in self.spot_locs)
        self.handover_empty = self.dur.goto if self.handover and not self.handover & self.release else 0.0
        """The empty-handed trip to the handover location before a take from the human."""
        self.place_then_robot = tuple(self._place_then_robot(o) for o in range(self.n_objects))
        self.methods: list[tuple[str, MethodFn]] = list(methods)

    def declare(self, name: str, method: MethodFn) -> None:
        """Add a method of ``dispose(o)`` (after the existing ones in tie-break order)."""
        self.methods.append((name, method))

    def human_can(self, kinds: set[Kind]) -> bool:
        """Whether the human model performs every kind in ``kinds``."""
        return kinds <= self.human_model.allowed_kinds

    def _release_locations(self) -> frozenset[int]:
        """Robot locations where it can let go of an object (see :attr:`release`)."""
        out = frozenset().union(*self.bin_locs)
        if any(self.bin_human) and self.human_can({Kind.TAKE, Kind.THROW}):
            out |= self.handover
        return out

    def _place_then_robot(self, o: int) -> float:
        """Least robot work to dispose of ``o`` after the human placed it within robot reach."""
        t, bins = self.dur, self.bin_locs[o]
        best = math.inf
        if not bins:
            return best
        for s, locs in enumerate(self.spot_locs):
            if locs and self.spot_human[s]:
                carry = t.goto if not locs & bins else 0.0
                best = min(best, t.pick + t.throw + carry + self.empty_move[s])
        return best

    def status(self, state: State, o: int) -> int:
        """Status code of object ``o``: its place code, or an offer code when offered."""
        if state.offer_obj == o:
            return self.human_offer if state.offer_by == Agent.HUMAN else self.robot_offer
        return state.where[o]

    def works(self, o: int, status: int, robot_at: int) -> list[tuple[str, Work]]:
        """The applicable methods of ``dispose(o)`` with what is left of each."""
        if status in self.world.table.done[o]:
            return [("done", Work(0.0, 0.0, _NONE, _NONE))]
        out = []
        for name, method in self.methods:
            work = method(self, o, status, robot_at)
            if work is not None:
                out.append((name, work))
        return out

    def explain_unreachable(self, state: State) -> str:
        """Why some object has no applicable method in ``state`` ('' if all have one)."""
        world = self.world
        for o in range(self.n_objects):
            status = self.status(state, o)
            if not self.works(o, status, state.robot_at):
                where = world.place_name(state.where[o])
                return (
                    f"no decomposition of dispose({world.scenario.objects[o]}): it is on {where} and no "
                    f"method (robot alone, handovers, human alone, human places) applies with the "
                    f"'{self.human_model.name}' human"
                )
        return ""
