"""The search space: candidates, symmetry, the admissible bound, all compiled per planner.

:class:`Space` turns the HTN domain into what the search needs, precomputed once per
planner from the world's :class:`~hg_marl.core.table.RuleTable` (so the rules are the
core's) and memoised per state (states are hashable ``NamedTuple`` s):

- ``candidates(state, agent)``: the agent's feasible actions that are the next step of
  some applicable method, minus symmetric duplicates (two objects accepted by the same
  bins on spots of the same reach class are interchangeable; two gotos to the same
  location are the same move; two placements on spots of the same class are one choice),
  plus ``wait``. Everything that depends on (agent, robot location, object, status) is
  tabulated; only the hand, offer and free-spot checks are left for the state;
- ``key(state)``: a canonical transposition-table key, equal for states that are the
  same up to those symmetries (they have the same cost-to-go);
- ``bound(state)``: an admissible lower bound on the cost-to-go from a cycle boundary.

Every cache here holds a pure function of its key, so a search's answer never depends
on which searches ran before it (the planner-driven humans rely on this to be
stationary). The bound is cached per canonical key, so it must be *exactly* equal for
all states of a key: its per-object sums are added with ``math.fsum`` (exactly rounded,
hence independent of the objects' order), not ``sum`` (whose last bits follow the order
and, via A*'s ``f`` ties, chose between interchangeable objects by cache history).

The bound. With ``a = w_time + w_idle`` and ``b = w_effort - w_idle`` the cost of the rest
of the plan is at least ``a T + b E_h`` (``T`` the remaining time, ``E_h`` the human's
work, since idle = T - E_h); the final cycle (the robot's completing ``wait``) costs at
least ``a * d_wait``. In the cycles before it, ``T >= sum max(d_r, d_h) >=
lam R + (1 - lam) E_h`` for any ``lam`` in [0, 1], ``R`` the robot's work. Each object's
remaining work is at least that of one of its methods, so
``cost >= a d_wait + sum_o min_m [a lam r_m + (a (1 - lam) + b) h_m + w_hold hold_m]``
(with ``b < 0``, ``E_h <= T`` gives the same form with ``a + b``; ``hold_m`` is the
method's least holding time). We take the best of a few ``lam``: the relaxation of a
two-machine schedule, tabulated per object, status and robot location. The methods'
robot work includes the empty-handed trips that must precede acquiring an object
(see :mod:`.domain`); the robot's first acquisition may save one, so the bound gives
one back when the robot stands, empty-handed, where it could acquire something.
"""

from __future__ import annotations

import math
from math import fsum
from operator import getitem, sub
from typing import NamedTuple

from hg_marl.agents.planner.costs import CostWeights
from hg_marl.agents.planner.domain import Domain
from hg_marl.agents.planner.exactsum import ExactSums
from hg_marl.agents.planner.models import HumanModel
from hg_marl.agents.planner.steps import Steps, Successor
from hg_marl.agents.planner.tables import candidate_entries, next_kinds, split_entries
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.relabel import Relabel

__all__ = ["HumanEdge", "Relabel", "RobotEdge", "Space", "shared_space"]

LAMBDAS: tuple[float, ...] = (0.0, 0.25, 0.5, 0.75, 1.0)
"""Mixing weights of robot and human work tried by the bound (five: the edges unroll them)."""

_CACHE_LIMIT = 500_000
_PLACE, _HUMAN = Kind.PLACE, int(Agent.HUMAN)
"""Read once: an enum member read through its class costs a look-up per call in the inner loop."""
_new = tuple.__new__
"""Builds the edges' ``NamedTuple`` s without their Python-level ``__new__`` (same values)."""


_SPACES = "_planner_spaces"
"""Attribute of a :class:`World` holding its spaces: they live and die with the world (a
``WeakKeyDictionary`` keyed by the world cannot, as each space refers to its world)."""


def shared_space(world: World, human_model: HumanModel, weights: CostWeights) -> Space:
    """The one :class:`Space` of a world, human model and cost model, shared by every planner.

    Its caches (candidates, bounds, allowed replies) are pure functions of the state, so
    the robot's planner and the planner-driven humans on the same layout share them
    without changing any answer. A model that is not hashable gets a space of its own.

    A shared space plans on a twin of ``world`` (:func:`_twin`): the world holds the space,
    and a space holding the world back would make every world that planned a reference
    cycle, left for the garbage collector (whose passes over the worlds left behind then
    fall inside later plans) instead of freed when its last user lets it go.
    """
    try:
        key = (human_model, weights)
        hash(key)
    except TypeError:
        return Space(Domain(world, human_model), weights)
    per_world: dict[tuple[object, CostWeights], Space] = world.__dict__.setdefault(_SPACES, {})
    space = per_world.get(key)
    if space is None:
        space = per_world[key] = Space(Domain(_twin(world), human_model), weights)
    return space


def _twin(world: World) -> World:
    """A :class:`World` sharing every attribute of ``world`` (its rule table, scenario,
    durations and caches) but not the spaces it holds: the same rules, no way back to them."""
    twin = object.__new__(type(world))
    twin.__dict__.update((k, v) for k, v in world.__dict__.items() if k != _SPACES)
    return twin


class RobotEdge(NamedTuple):
    """A robot candidate from a cycle-boundary state, with what the search needs of its result."""

    action: int
    state: State
    duration: float
    key: object
    """The human node's key: the mid-cycle state's canonical key with the cycle's robot
    duration and whether the robot was active (what the cost-to-go depends on)."""
    h: float
    """Bound on the cost-to-go after it (the cycle's robot duration counted)."""


class HumanEdge(NamedTuple):
    """A human reply from a mid-cycle state, with what the search needs of its result."""

    action: int
    state: State
    duration: float
    take: bool
    active: bool
    holding: bool
    """Whether the human holds an object after it."""
    key: object
    h: float
    """Bound on the cost-to-go from the next cycle boundary."""


class Space:
    """Candidates, canonical keys and the admissible bound for one domain and cost model."""

    def __init__(self, domain: Domain, weights: CostWeights) -> None:
        self.domain = domain
        self.world = world = domain.world
        self.table = table = world.table
        self.weights = weights
        self.wait = table.wait
        sc = world.scenario
        classes: dict[tuple[frozenset[int], bool], int] = {}
        self.spot_class = tuple(classes.setdefault((s.reach.robot_from, s.reach.human), len(classes)) for s in sc.spots)
        n_cls = len(classes)
        # canonical code of each place: spot class; every bin is "disposed of" (objects only
        # enter bins that accept them); the hands are distinct
        self.place_code = (*self.spot_class, *(n_cls,) * world.n_bins, n_cls + 1, n_cls + 2)
        n_codes = n_cls + 3
        accept: dict[tuple[int, ...], int] = {}
        self.object_class = tuple(accept.setdefault(bins, len(accept)) for bins in world.bins_of)
        """Objects accepted by the same bins are interchangeable."""
        self.symmetric = len(set(self.spot_class)) < len(self.spot_class) or len(set(self.object_class)) < len(
            self.object_class
        )
        width = max(world.n_objects, 1).bit_length()
        low = 2 + max(len(sc.robot_locations), 1).bit_length()
        self._codes = [
            [1 << ((code * len(accept) + c) * width + low) for code in self.place_code] for c in self.object_class
        ]
        """Per object and place, its term of the canonical key: one bit field per (place code,
        object class), wide enough to count every object without a carry, so the sum over
        the objects is the multiset of their codes and equal sums are equal multisets. The
        fields start above the ``low`` bits that hold ``4 * robot_at + offer_by + 1`` (see
        :meth:`key`): the key is one integer (hashed faster than a tuple, and not tracked by
        the garbage collector)."""
        del n_codes
        a = weights.time + weights.human_idle
        b = weights.human_effort - weights.human_idle
        c = a if b >= 0 else a + b
        self.base = a * world.durations.wait
        """Cost of the final cycle (the robot's completing ``wait``) at least."""
        self.coefs = tuple((c * lam, c * (1.0 - lam) + max(b, 0.0)) for lam in LAMBDAS)
        """Per ``LAMBDAS[k]``: the weight of robot work and of human work in the bound."""
        self.n_locs = len(sc.robot_locations)
        self.tables = self._tabulate()
        """``tables[k][robot_at][o][status]``: least weighted work of ``o`` for ``LAMBDAS[k]``."""
        self.offer_tables = self._offer_tables()
        """``tables`` for states where the robot is offering: the offered object may also go
        back to the robot's hand (the human lets the offer lapse)."""
        self._exact = ExactSums(self.tables, self.offer_tables, world.n_objects)
        """The same sums as ``fsum`` over :attr:`tables`, by integer addition."""
        self.empty_move_coef = tuple(cr * world.durations.goto for cr, _ in self.coefs)
        """What one saved empty-handed move is worth in the bound, per ``LAMBDAS[k]``."""
        self.saves_at = tuple(
            (
                at in domain.handover and domain.handover_empty > 0.0,
                tuple(domain.empty_move[s] > 0.0 and at in locs for s, locs in enumerate(domain.spot_locs)),
            )
            for at in range(self.n_locs)
        )
        self._saves_places = tuple(
            (handover, frozenset(p for p, ok in enumerate(spots) if ok)) for handover, spots in self.saves_at
        )
        """:attr:`saves_at` with the spots as a set of place codes (spots come first)."""
        self._next = next_kinds(self)
        self.steps = Steps(table)
        """The rule table's transitions decoded per action index (the inner loop's)."""
        self._cr = tuple(c for c, _ in self.coefs)
        wait_r = self.wait[0]
        cycles: dict[tuple[float, bool], int] = {}
        self._cycle_code = tuple(
            cycles.setdefault((spec[3], i != wait_r), len(cycles)) for i, spec in enumerate(table.specs[0])
        )
        """Per robot action, a code of its (duration, active): with an integer canonical key
        ``k``, a human node's key is ``k * len(cycles) + code`` (one integer, no tuple per edge)."""
        self._n_cycle_codes = len(cycles)
        acts = table.actions
        self.robot_gives = frozenset(i for i, a in enumerate(acts[0]) if a.kind is Kind.GIVE)
        """Robot give indices (an unanswered give is not robot activity, see ``robot_active``)."""
        self.human_takes = frozenset(i for i, a in enumerate(acts[1]) if a.kind is Kind.TAKE)
        # spots worth placing on: the robot can pick from them (other human moves are not steps of any method)
        self.place_spots = tuple(sp for sp, locs in enumerate(domain.spot_locs) if locs and domain.spot_human[sp])
        self._picks, self._takes, self._held = split_entries(candidate_entries(self))
        self._goto = table.action_index(0, Kind.GOTO, target=0)
        self._goto_static = tuple(
            tuple((self._goto + world.n_objects + k, dest) for k, dest in enumerate(row) if dest >= 0)
            for row in table.goto_static
        )
        """Per robot location, the gotos to bins and the human that lead somewhere: (index, destination)."""
        self._cand: tuple[dict[State, tuple[int, ...]], dict[State, tuple[int, ...]]] = ({}, {})
        self._bound: dict[object, float] = {}
        self._sums: dict[object, tuple[float, ...] | None] = {}
        self._robot_edges: dict[State, tuple[RobotEdge, ...]] = {}
        self._human_edges: dict[State, tuple[HumanEdge, ...]] = {}
        self._allowed: dict[State, tuple[int, ...]] = {}

    # ---- bound -------------------------------------------------------------------
    def _tabulate(self) -> list[list[list[list[float]]]]:
        d = self.domain
        hold = self.weights.human_holding
        works = [
            [[d.works(o, s, at) for s in range(d.n_status)] for o in range(d.n_objects)] for at in range(self.n_locs)
        ]
        return [
            [
                [
                    [
                        min((cr * w.robot + ch * w.human + hold * w.holding for _, w in ws), default=math.inf)
                        for ws in per_o
                    ]
                    for per_o in per_at
                ]
                for per_at in works
            ]
            for cr, ch in self.coefs
        ]

    def _offer_tables(self) -> list[list[list[list[float]]]]:
        d = self.domain
        out = []
        for table in self.tables:
            per_k = []
            for per_at in table:
                rows = []
                for row in per_at:
                    row = list(row)
                    row[d.robot_offer] = min(row[d.robot_offer], row[d.robot_hand])
                    rows.append(row)
                per_k.append(rows)
            out.append(per_k)
        return out

    def statuses(self, state: State) -> list[int]:
        """Status code of every object (see :meth:`Domain.status`)."""
        out = list(state.where)
        if state.offer_obj >= 0:
            d = self.domain
            out[state.offer_obj] = d.human_offer if state.offer_by == Agent.HUMAN else d.robot_offer
        return out

    def cached_sums(self, state: State, key: object) -> tuple[float, ...] | None:
        """:meth:`sums` memoised by canonical key (symmetric states have the same sums)."""
        out = self._sums.get(key, 0)
        if out == 0:
            return self._new_sums(state, key)
        return out  # type: ignore[return-value]

    def _new_sums(self, state: State, key: object) -> tuple[float, ...] | None:
        """:meth:`sums` stored under a key the memo does not hold (the successors look it up first)."""
        if len(self._sums) > _CACHE_LIMIT:
            self._sums.clear()
        out = self._sums[key] = self.sums(state)
        return out

    def robot_edges(self, state: State) -> tuple[RobotEdge, ...]:
        """The robot's candidates at ``state`` applied (dead ends left out), memoised.

        A pure function of the state, so successive searches (the humans plan at every
        turn, from neighbouring states) reuse each other's expansions.
        """
        out = self._robot_edges.get(state)
        if out is None:
            base = self.base
            c0, c1, c2, c3, c4 = self._cr
            code, n_codes = self._cycle_code, self._n_cycle_codes
            symmetric = self.symmetric
            out = tuple(
                [
                    _new(
                        RobotEdge,
                        (
                            ar,
                            s1,
                            d_r,
                            key * n_codes + code[ar] if symmetric else (key, code[ar]),
                            base + max(v0 + c0 * d_r, v1 + c1 * d_r, v2 + c2 * d_r, v3 + c3 * d_r, v4 + c4 * d_r),
                        ),
                    )
                    for ar, s1, d_r, key, (v0, v1, v2, v3, v4) in self._successors(state, 0, self.candidates(state, 0))
                ]
            )
            if len(self._robot_edges) > _CACHE_LIMIT:
                self._robot_edges.clear()
            self._robot_edges[state] = out
        return out

    def human_edges(self, state: State) -> tuple[HumanEdge, ...]:
        """The replies the human model allows at mid-cycle ``state`` applied (dead ends left out), memoised."""
        out = self._human_edges.get(state)
        if out is None:
            base = self.base
            hand_h = self.table.hand[_HUMAN]
            wait_h = self.wait[_HUMAN]
            takes = self.human_takes
            out = tuple(
                [
                    _new(HumanEdge, (ah, s2, d_h, ah in takes, ah != wait_h, hand_h in s2.where, key, base + max(sm)))
                    for ah, s2, d_h, key, sm in self._successors(state, 1, self.allowed(state))
                ]
            )
            if len(self._human_edges) > _CACHE_LIMIT:
                self._human_edges.clear()
            self._human_edges[state] = out
        return out

    def _successors(self, state: State, agent: int, actions: tuple[int, ...]) -> list[Successor]:
        """``actions`` applied with their canonical keys and sums (:meth:`.Steps.successors`)."""
        codes = self._codes if self.symmetric else None
        return self.steps.successors(state, agent, actions, self.key, self._new_sums, codes, self._sums)

    def allowed(self, state: State) -> tuple[int, ...]:
        """The human replies a deterministic model allows at ``state`` (its candidates, filtered)."""
        out = self._allowed.get(state)
        if out is None:
            out = ()
            for _, choice in self.domain.human_model.choices(self.world, state, self.candidates(state, _HUMAN)):
                out += tuple(choice)
            if len(self._allowed) > _CACHE_LIMIT:
                self._allowed.clear()
            self._allowed[state] = out
        return out

    def sums(self, state: State) -> tuple[float, ...] | None:
        """Per ``LAMBDAS[k]``, the weighted remaining work of ``state`` (None: a dead end).

        Valid at a cycle boundary and, with the robot's offer allowed to lapse
        (:attr:`offer_tables`), in the middle of a cycle.
        """
        d = self.domain
        where, at, by, obj = state
        status = d.human_offer if by == 1 else d.robot_offer  # the offered object's, if any
        if self._exact.packed is not None:  # ``fsum``'s value by one integer sum
            vals = self._exact.of_places(by == 0, at, where, obj, status)
            if vals is None:
                return None
        else:
            statuses = list(where)
            if obj >= 0:
                statuses[obj] = status
            tabs = self.tables if by != 0 else self.offer_tables
            vals = tuple([fsum(map(getitem, tab[at], statuses)) for tab in tabs])  # exactly rounded: order-free
            if math.inf in vals:
                return None
        if d.robot_hand not in where:
            handover, spots = self._saves_places[at]
            if handover or not spots.isdisjoint(where):
                return tuple(map(sub, vals, self.empty_move_coef))
        return vals

    def bound(self, state: State, key: object = None) -> float:
        """Admissible lower bound on the cost-to-go of a cycle-boundary state (inf: dead end)."""
        if key is None:
            key = self.key(state)
        value = self._bound.get(key)
        if value is not None:
            return value
        sm = self.cached_sums(state, key)
        value = math.inf if sm is None else self.base + max(0.0, *sm)
        if len(self._bound) > _CACHE_LIMIT:
            self._bound.clear()
        self._bound[key] = value
        return value

    # ---- symmetry ----------------------------------------------------------------
    def key(self, state: State) -> object:
        """Canonical transposition key: equal for states equal up to object/spot symmetry."""
        if not self.symmetric:
            return state
        return sum(map(getitem, self._codes, state.where)) + 4 * state.robot_at + state.offer_by + 1

    # ---- candidates --------------------------------------------------------------
    def candidates(self, state: State, agent: int) -> tuple[int, ...]:
        """Relevant, symmetry-reduced feasible actions of ``agent`` in ``state`` (``wait`` last)."""
        cache = self._cand[agent]
        out = cache.get(state)
        if out is None:
            out = self._candidates(state, agent)
            if len(cache) > _CACHE_LIMIT:
                cache.clear()
            cache[state] = out
        return out

    def _candidates(self, state: State, agent: int) -> tuple[int, ...]:
        where, at, by, obj = state
        hand = self.table.hand[agent]
        seen: set[object] = set()
        out: list[int] = []
        # a hand holds one object: while it does, only that object's steps can pass (a pick
        # or a take needs the hand empty, the others the object in it): :func:`.split_entries`
        if hand in where:
            held = where.index(hand)
            st = where[held]
            if held == obj:
                d = self.domain
                st = d.human_offer if by == 1 else d.robot_offer
            place = _PLACE
            for kind, i, sig, spot in self._held[agent][at][held][st]:
                if kind is place:
                    if sig in seen or spot in where:
                        continue
                    seen.add(sig)
                out.append(i)
        else:
            # an offered object is in its giver's hand, never on a spot, so its picks are
            # those of its place as of its offer status: none
            for per_st, p in zip(self._picks[agent][at], where, strict=True):
                for _, i, sig, _ in per_st[p]:
                    if sig not in seen:
                        seen.add(sig)
                        out.append(i)
            if by >= 0 and by != agent:  # the partner's offer: its takes
                d = self.domain
                out += [e[1] for e in self._takes[agent][at][obj][d.human_offer if by == 1 else d.robot_offer]]
        if agent == 0:
            goto = self._goto
            dests: set[int] = set()
            per_place = self.table.goto_obj[at]
            for t, p in enumerate(where):
                dest = per_place[p]
                if dest >= 0 and dest not in dests:
                    dests.add(dest)
                    out.append(goto + t)
            for i, dest in self._goto_static[at]:
                if dest not in dests:
                    dests.add(dest)
                    out.append(i)
        out.sort()
        out.append(self.wait[agent])
        return tuple(out)
