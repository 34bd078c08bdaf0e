"""The search space over joint cycles: candidates, symmetry, the admissible bound.

:class:`Space` turns the HTN domain into what the search needs, precomputed once per
planner and memoised per state (states are hashable ``NamedTuple`` s):

- ``candidates(state, agent)``: the agent's feasible actions (``World.feasible_indices``,
  so the rules are the core's) that are the next step of some applicable method, minus
  symmetric duplicates (two objects of the same bin on spots of the same reach class are
  interchangeable; two gotos to the same location are the same move), plus ``wait``;
- ``key(state)``: a canonical transposition-table key, equal for states that are the
  same up to those symmetries (they have the same cost-to-go);
- ``bound(state)``: an admissible lower bound on the cost-to-go from a cycle boundary.

The bound. With ``a = w_time + w_idle`` and ``b = w_effort - w_idle`` the cost of the rest
of the plan is at least ``a T + b E_h`` (``T`` the remaining time, ``E_h`` the human's
work, since idle = T - E_h); the final cycle (the robot's completing ``wait``) costs at
least ``a * d_wait``. In the cycles before it, ``T >= sum max(d_r, d_h) >=
lam R + (1 - lam) E_h`` for any ``lam`` in [0, 1], ``R`` the robot's work. Each object's
remaining work is at least that of one of its methods, so
``cost >= a d_wait + sum_o min_m [a lam r_m + (a (1 - lam) + b) h_m + w_hold hold_m]``
(with ``b < 0``, ``E_h <= T`` gives the same form with ``a + b``; ``hold_m`` is the
method's least holding time). We take the best of a few ``lam``: the
relaxation of a two-machine schedule, tabulated per object, status and robot location.
"""

from __future__ import annotations

import math

from hg_marl.agents.planner.costs import CostWeights
from hg_marl.agents.planner.domain import Domain
from hg_marl.core import Agent, Kind, State

LAMBDAS: tuple[float, ...] = (0.0, 0.25, 0.5, 0.75, 1.0)
"""Mixing weights of robot and human work tried by the bound."""

_CACHE_LIMIT = 500_000
_getitem = list.__getitem__


class Space:
    """Candidates, canonical keys and the admissible bound for one domain and cost model."""

    def __init__(self, domain: Domain, weights: CostWeights) -> None:
        self.domain = domain
        self.world = world = domain.world
        self.weights = weights
        self.wait = (world.n_actions(Agent.ROBOT) - 1, world.n_actions(Agent.HUMAN) - 1)
        self._acts = (world.actions(Agent.ROBOT), world.actions(Agent.HUMAN))
        sc = world.scenario
        classes: dict[tuple[frozenset[int], bool], int] = {}
        self.spot_class = tuple(classes.setdefault((s.reach.robot_from, s.reach.human), len(classes)) for s in sc.spots)
        n_cls = len(classes)
        # canonical code of each place: spot class, or a distinct code for bins and hands
        self.place_code = (*self.spot_class, *range(n_cls, n_cls + world.n_bins + 2))
        self.n_bins = world.n_bins
        self.bin_of = world.bin_of
        self.symmetric = len(set(self.spot_class)) < len(self.spot_class) or len(set(self.bin_of)) < len(self.bin_of)
        a = weights.time + weights.human_idle
        b = weights.human_effort - weights.human_idle
        c = a if b >= 0 else a + b
        self.base = a * world.durations.wait
        self.coefs = tuple((c * lam, c * (1.0 - lam) + max(b, 0.0)) for lam in LAMBDAS)
        self.n_locs = len(sc.robot_locations)
        self._codes = [[self.place_code[p] * self.n_bins + b for p in range(len(self.place_code))] for b in self.bin_of]
        self._table = self._tabulate()
        self._next = self._tabulate_next()
        self._index = tuple(
            {(a.kind, a.obj, a.target if a.kind is Kind.PLACE else -1): i for i, a in enumerate(acts)}
            for acts in self._acts
        )
        self.robot_gives = frozenset(i for i, a in enumerate(self._acts[0]) if a.kind is Kind.GIVE)
        """Robot give indices (an unanswered give is not robot activity, see ``robot_active``)."""
        self.human_takes = frozenset(i for i, a in enumerate(self._acts[1]) if a.kind is Kind.TAKE)
        self._gotos = tuple(i for i, a in enumerate(self._acts[0]) if a.kind is Kind.GOTO)
        # spots worth placing on: the robot can pick from them (other human moves are not steps of any method)
        self._place_spots = tuple(sp for sp, locs in enumerate(domain.spot_locs) if locs and domain.spot_human[sp])
        self._empty_move_coef = tuple(cr * world.durations.goto for cr, _ in self.coefs)
        self._cand: tuple[dict[State, tuple[int, ...]], dict[State, tuple[int, ...]]] = ({}, {})
        self._bound: dict[object, float] = {}

    # ---- bound -------------------------------------------------------------------
    def _tabulate(self) -> list[list[list[list[float]]]]:
        """``table[k][robot_at][o][status]``: least weighted work of ``o`` for ``LAMBDAS[k]``."""
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

    def _tabulate_next(self) -> tuple[list[list[list[tuple[Kind, ...]]]], ...]:
        """``next[agent][robot_at][o][status]``: kinds that are a next step of an applicable method."""
        d = self.domain
        out: tuple[list[list[list[tuple[Kind, ...]]]], ...] = ([], [])
        for at in range(self.n_locs):
            per_agent: tuple[list[list[tuple[Kind, ...]]], ...] = ([], [])
            for o in range(d.n_objects):
                rows: tuple[list[tuple[Kind, ...]], ...] = ([], [])
                for st in range(d.n_status):
                    robot: set[Kind] = set()
                    human: set[Kind] = set()
                    for _, w in d.works(o, st, at):
                        robot |= w.robot_next
                        human |= w.human_next
                    rows[0].append(tuple(sorted(robot)))
                    rows[1].append(tuple(sorted(human)))
                per_agent[0].append(rows[0])
                per_agent[1].append(rows[1])
            out[0].append(per_agent[0])
            out[1].append(per_agent[1])
        return out

    def statuses(self, state: State) -> list[int]:
        """Status code of every object (see :meth:`Domain.status`)."""
        out = list(state.where)
        if state.offer_obj >= 0:
            d = self.domain
            out[state.offer_obj] = d.human_offer if state.offer_by == Agent.HUMAN else d.robot_offer
        return out

    def bound(self, state: State, key: object = None) -> float:
        """Admissible lower bound on the cost-to-go of a cycle-boundary state (inf: dead end)."""
        if key is None:
            key = self.key(state)
        value = self._bound.get(key)
        if value is not None:
            return value
        d = self.domain
        at = state.robot_at
        statuses = self.statuses(state)
        exception = d.robot_hand not in state.where and any(
            s < d.n_spots and d.empty_move[s] and at in d.spot_locs[s] for s in state.where
        )
        best = 0.0
        for k, table in enumerate(self._table):
            total = sum(map(_getitem, table[at], statuses))
            if exception:
                total -= self._empty_move_coef[k]
            if total > best:
                best = total
        value = self.base + best if not math.isinf(best) else math.inf
        if len(self._bound) > _CACHE_LIMIT:
            self._bound.clear()
        self._bound[key] = value
        return value

    # ---- symmetry ----------------------------------------------------------------
    def key(self, state: State) -> object:
        """Canonical transposition key: equal for states equal up to object/spot symmetry."""
        if not self.symmetric:
            return state
        return (tuple(sorted(map(_getitem, self._codes, state.where))), state.robot_at, state.offer_by)

    # ---- candidates --------------------------------------------------------------
    def candidates(self, state: State, agent: Agent) -> tuple[int, ...]:
        """Relevant, symmetry-reduced feasible actions of ``agent`` in ``state`` (``wait`` last)."""
        cache = self._cand[agent]
        out = cache.get(state)
        if out is None:
            out = self._candidates(state, agent)
            if len(cache) > _CACHE_LIMIT:
                cache.clear()
            cache[state] = out
        return out

    def _candidates(self, state: State, agent: Agent) -> tuple[int, ...]:
        world = self.world
        nxt = self._next[agent][state.robot_at]
        index = self._index[agent]
        acts = self._acts[agent]
        cleared = state
        if state.offer_by == agent.other:
            cleared = state._replace(offer_by=-1, offer_obj=-1)
        seen: set[tuple[int, ...]] = set()
        out: list[int] = []
        for o, status in enumerate(self.statuses(state)):
            for kind in nxt[o][status]:
                if kind is Kind.PLACE:
                    for spot in self._place_spots:
                        i = index[(kind, o, spot)]
                        sig: tuple[int, ...] = (kind, self.spot_class[spot])
                        if sig not in seen and world.feasible(cleared, agent, acts[i]):
                            seen.add(sig)
                            out.append(i)
                    continue
                i = index[(kind, o, -1)]
                # picks of interchangeable objects (same bin, same spot class) are one choice
                sig = (kind, self.spot_class[status], self.bin_of[o]) if kind is Kind.PICK else (kind, o)
                if sig in seen:
                    continue
                s = state if (kind is Kind.TAKE and state.offer_obj == o) else cleared
                if world.feasible(s, agent, acts[i]):
                    seen.add(sig)
                    out.append(i)
        if agent is Agent.ROBOT:
            dests: set[int] = set()
            for i in self._gotos:
                dest = world.goto_destination(cleared, acts[i].target)
                if dest >= 0 and dest not in dests:
                    dests.add(dest)
                    out.append(i)
        out.sort()
        out.append(self.wait[agent])
        return tuple(out)
