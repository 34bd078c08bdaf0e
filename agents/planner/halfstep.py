"""Cost-optimal search over half-steps (the robot's action, then the human's reply).

Same problem, costs and answers as :mod:`.search`, solved with fewer and cheaper nodes:

- **Half-steps.** A cycle is split into a robot node (a cycle-boundary state, the robot
  to move) and a human node (the state after the robot's action, with that action's
  duration and whether it counts as robot activity). A robot node generates only the
  robot's candidates; a human node only the human's replies, and the cycle's cost is
  charged there. Human nodes whose bound is already above the optimum are never
  expanded, so most joint successors are never generated. A human node's identity is
  (canonical state, robot duration, robot active): its cost-to-go depends on nothing else
  (whether the robot's action was a give is in the state: the robot is offering).
- **Bound at a human node.** :meth:`Space.bound`'s relaxation holds from the middle of a
  cycle too, with the current cycle's robot duration added to the robot's work (the
  cycle lasts at least that long), and with an object the robot is offering allowed to
  go back to the robot's hand (the human may let the offer lapse).
- **Compiled transitions.** Candidates are feasible by construction, so the search
  applies them with a small table-driven transition instead of ``World.step`` (whose
  events and names are for the environment); a test checks it against ``World.step``.

Ties are broken as in :mod:`.search`: lower ``f``, then larger cost-so-far, then
insertion order (which follows the candidates' index order): the search is deterministic.
Among equal-cost optima it may return another plan than :mod:`.search` (the order in
which nodes are expanded differs); the cost is the same (a test checks it). The node
count and the budget are over robot nodes (cycle boundaries, as in :mod:`.search`);
human nodes are bounded by them.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable
from operator import getitem
from typing import TypeVar

from hg_marl.agents.planner.search import SearchOutcome
from hg_marl.agents.planner.space import Space
from hg_marl.core import Agent, Kind, State

_CACHE_LIMIT = 500_000
_T = TypeVar("_T")


class Transitions:
    """Table-driven successor function for actions known to be feasible (the candidates)."""

    def __init__(self, space: Space) -> None:
        world = space.world
        dur = world.durations
        n_spots = world.n_spots
        handover = world.scenario.handover_locations
        spot_robot = tuple(s.reach.robot_from for s in world.scenario.spots)
        self.spot_dest = tuple(min(locs) if locs else -1 for locs in spot_robot) + (-1,) * (world.n_bins + 2)
        n = world.n_objects
        specs: list[list[tuple[int, int, int, float]]] = [[], []]
        for agent in Agent:
            hand = world.hand[agent]
            for a in world.actions(agent):
                kind, o = a.kind, a.obj
                d = dur.of(kind)
                if kind is Kind.PICK or kind is Kind.TAKE:
                    specs[agent].append((int(kind), o, hand, d))
                elif kind is Kind.THROW:
                    specs[agent].append((int(kind), o, n_spots + world.bin_of[o], d))
                elif kind is Kind.PLACE:
                    specs[agent].append((int(kind), o, a.target, d))
                elif kind is Kind.GOTO:
                    t = a.target
                    if t < n:
                        specs[agent].append((int(kind), t, -1, d))  # destination depends on where t is
                    elif t < n + world.n_bins:
                        reach = world.scenario.bins[t - n].reach.robot_from
                        specs[agent].append((int(kind), -1, min(reach) if reach else -1, d))
                    else:
                        specs[agent].append((int(kind), -1, min(handover) if handover else -1, d))
                else:
                    specs[agent].append((int(kind), o, -1, d))
        self.specs = (tuple(specs[0]), tuple(specs[1]))

    def apply(self, state: State, agent: int, index: int) -> tuple[State, float]:
        """Next state and duration of a *feasible* action (an offer by the partner may lapse)."""
        kind, o, arg, d = self.specs[agent][index]
        where, at, by, obj = state
        if by >= 0 and by != agent and not (kind == 3 and o == obj):
            by = obj = -1
        if kind <= 1 or kind == 4:  # PICK, THROW, PLACE
            where = (*where[:o], arg, *where[o + 1 :])
        elif kind == 3:  # TAKE
            where = (*where[:o], arg, *where[o + 1 :])
            by = obj = -1
        elif kind == 2:  # GIVE
            by, obj = agent, o
        elif kind == 5:  # GOTO
            at = self.spot_dest[where[o]] if o >= 0 else arg
        return State(where, at, by, obj), d


def astar(space: Space, root: State, to_move: Agent, robot_part: tuple[float, int], budget: int) -> SearchOutcome:
    """Find a minimum-cost plan from ``root`` over half-steps (see the module docstring)."""
    world, model = space.world, space.domain.human_model
    w_time, w_eff, w_bal, w_idle, w_hold = space.weights.vector
    wait_r, wait_h = space.wait
    hand_h = world.hand[Agent.HUMAN]
    robot_hand = world.hand[Agent.ROBOT]
    trans = _compiled(space, "_half_transitions", Transitions)
    apply = trans.apply
    robot, human = Agent.ROBOT, Agent.HUMAN
    cands = _compiled(space, "_half_candidates", Candidates)
    key_of = space.key
    n_spots = world.n_spots
    bin_of = world.bin_of
    gives = space.robot_gives
    takes = space.human_takes
    final_cost = (w_time + w_idle) * world.durations.wait  # both agents wait: one wait long

    base = space.base
    tables = space._table
    n_k = len(tables)
    cr = tuple(c for c, _ in space.coefs)
    em = space._empty_move_coef
    d = space.domain
    empty_move, spot_locs = d.empty_move, d.spot_locs
    offer_r = d.robot_offer
    h_at = _compiled(space, "_half_offer_tables", _offer_tables)
    sums_cache: dict[object, tuple[float, ...] | None] = {}
    allowed_cache: dict[State, tuple[int, ...]] = {}

    def sums(s: State, key: object) -> tuple[float, ...] | None:
        """Per-lambda weighted remaining work of ``s`` (None: a dead end)."""
        out = sums_cache.get(key, 0)
        if out != 0:
            return out  # type: ignore[return-value]
        at = s.robot_at
        where = s.where
        statuses = list(where)
        if s.offer_obj >= 0:
            statuses[s.offer_obj] = d.human_offer if s.offer_by == 1 else offer_r
        exception = robot_hand not in where and any(p < n_spots and empty_move[p] and at in spot_locs[p] for p in where)
        tabs = tables if s.offer_by != 0 else h_at
        vals = [sum(map(getitem, tab[at], statuses)) for tab in tabs]
        if math.inf in vals:
            res = None
        elif exception:
            res = tuple(v - e for v, e in zip(vals, em, strict=True))
        else:
            res = tuple(vals)
        sums_cache[key] = res
        return res

    def allowed(s1: State) -> tuple[int, ...]:
        out = allowed_cache.get(s1)
        if out is None:
            out = ()
            for _, choice in model.choices(world, s1, cands(s1, human)):
                out += tuple(choice)
            allowed_cache[s1] = out
        return out

    # node arrays
    states: list[State] = []
    parents: list[int] = []
    acts: list[int] = []  # robot nodes: the human action that led here; human nodes: the robot action
    gs: list[float] = []
    keys: list[object] = []
    kinds: list[int] = []  # 0 robot node, 1 human node, 2 terminal
    durs: list[float] = []
    actives: list[bool] = []
    best_r: dict[object, float] = {}
    best_h: dict[object, float] = {}
    heap: list[tuple[float, float, int]] = []
    push = heapq.heappush

    def add(
        state: State, parent: int, action: int, g: float, kind: int, key: object, f: float, dr: float, act: bool
    ) -> None:
        node = len(states)
        states.append(state)
        parents.append(parent)
        acts.append(action)
        gs.append(g)
        keys.append(key)
        kinds.append(kind)
        durs.append(dr)
        actives.append(act)
        push(heap, (f, -g, node))

    def push_h(s1: State, parent: int, ar: int, g: float, d_r: float, active: bool) -> None:
        key = (key_of(s1), d_r, active)
        if g >= best_h.get(key, math.inf) - 1e-12:
            return
        sm = sums(s1, key[0])
        if sm is None:
            return
        best_h[key] = g
        h = max(sm[k] + cr[k] * d_r for k in range(n_k))
        add(s1, parent, ar, g, 1, key, g + base + h, d_r, active)

    def expand_h(node: int, g: float) -> None:
        s1 = states[node]
        d_r = durs[node]
        active_r = actives[node]
        ar = acts[node]
        parent = parents[node]
        noop = states[parent] if (ar == wait_r and parent >= 0) else None
        give = ar in gives
        for ah in allowed(s1):
            s2, d_h = apply(s1, 1, ah)
            if noop is not None and s2 == noop:
                continue  # a cycle in which nothing happens only costs time
            dt = d_r if d_r > d_h else d_h
            e_h = d_h if ah != wait_h else 0.0
            e_r = d_r if active_r and (not give or ah in takes) else 0.0
            c = w_time * dt + w_eff * e_h + w_idle * (dt - e_h)
            if e_h > e_r:
                c += w_bal * (e_h - e_r)
            if hand_h in s2.where:
                c += w_hold * dt
            g2 = g + c
            key = key_of(s2)
            if g2 >= best_r.get(key, math.inf) - 1e-12:
                continue
            sm = sums(s2, key)
            if sm is None:
                continue
            best_r[key] = g2
            add(s2, node, ah, g2, 0, key, g2 + base + max(sm), 0.0, False)

    if to_move is human:
        d_r, ra = robot_part
        # the root is a human node; its replies are the first cycle (the robot's part given)
        add(root, -1, ra, 0.0, 1, None, 0.0, d_r, ra >= 0 and ra != wait_r)
    else:
        key = key_of(root)
        if sums(root, key) is None:
            return SearchOutcome(None, math.inf, 0, "unreachable")
        best_r[key] = 0.0
        add(root, -1, -1, 0.0, 0, key, 0.0, 0.0, False)
    expanded = 0

    while heap:
        _, neg_g, node = heapq.heappop(heap)
        g = -neg_g
        kind = kinds[node]
        if kind == 2:
            return SearchOutcome(_path(states, parents, acts, kinds, node, wait_r), g, expanded)
        if kind == 0:
            if g > best_r[keys[node]] + 1e-12:
                continue
        elif keys[node] is not None and g > best_h[keys[node]] + 1e-12:
            continue
        if kind == 1:
            expand_h(node, g)
            continue
        if expanded >= budget:
            return SearchOutcome(None, math.inf, expanded, "budget")
        expanded += 1
        s = states[node]
        where = s.where
        if all(where[o] == n_spots + bin_of[o] for o in range(len(where))):
            add(s, node, wait_h, g + final_cost, 2, None, g + final_cost, 0.0, False)
            continue
        for ar in cands(s, robot):
            s1, d_r = apply(s, 0, ar)
            push_h(s1, node, ar, g, d_r, ar != wait_r)
    return SearchOutcome(None, math.inf, expanded, "no plan")


def prepare(space: Space) -> None:
    """Build the space's compiled tables now (the planner does it at construction, so
    that a first ``plan`` call only searches)."""
    _compiled(space, "_half_candidates", Candidates)
    _compiled(space, "_half_transitions", Transitions)
    _compiled(space, "_half_offer_tables", _offer_tables)


def _compiled(space: Space, name: str, factory: Callable[[Space], _T]) -> _T:
    """A compiled helper of the space, built on first use and kept with it."""
    out = space.__dict__.get(name)
    if out is None:
        out = space.__dict__[name] = factory(space)
    return out


def _offer_tables(space: Space) -> list[list[list[list[float]]]]:
    """``space._table`` for states where the robot is offering: the offered object may also
    go back to the robot's hand (the human lets the offer lapse), so its entry is the least of both."""
    d = space.domain
    out = []
    for table in space._table:
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


def _path(
    states: list[State], parents: list[int], acts: list[int], kinds: list[int], node: int, wait_r: int
) -> list[tuple[int, int]]:
    """The cycles from the root to terminal ``node``."""
    out = [(wait_r, acts[node])]
    node = parents[node]
    while node >= 0:
        h = parents[node]  # robot node ``node`` was reached by a human reply from human node ``h``
        if h < 0:
            break  # the root (a robot node)
        ar = acts[h] if parents[h] >= 0 else -1
        out.append((ar, acts[node]))
        node = parents[h]
    out.reverse()
    return out


class Candidates:
    """:meth:`Space.candidates`, compiled: the same actions in the same order, from tables
    of each (agent, robot location, object, status) with only the hand, offer and free-spot
    checks left for the state (a test checks it against ``Space.candidates``)."""

    def __init__(self, space: Space) -> None:
        world = space.world
        d = space.domain
        sc = world.scenario
        n_spots = world.n_spots
        handover = sc.handover_locations
        self.hands = world.hand
        self.wait = space.wait
        self.n_objects = world.n_objects
        self.human_offer, self.robot_offer = d.human_offer, d.robot_offer
        n_locs = len(sc.robot_locations)
        index = space._index
        # entries: (kind, index, sig or None, place spot or -1)
        table: list[list[list[list[tuple[tuple[int, int, object, int], ...]]]]] = [[], []]
        for agent in Agent:
            acts_idx = index[agent]
            for at in range(n_locs):
                per_o = []
                for o in range(world.n_objects):
                    b = world.bin_of[o]
                    per_st = []
                    for st in range(d.n_status):
                        entries: list[tuple[int, int, object, int]] = []
                        for kind in space._next[agent][at][o][st]:
                            if kind is Kind.PLACE:
                                if agent is Agent.HUMAN:
                                    for spot in space._place_spots:
                                        if sc.spots[spot].reach.human:
                                            i = acts_idx[(kind, o, spot)]
                                            entries.append((4, i, (4, space.spot_class[spot]), spot))
                                continue
                            i = acts_idx[(kind, o, -1)]
                            if kind is Kind.PICK:
                                if st >= n_spots:
                                    continue
                                ok = at in d.spot_locs[st] if agent is Agent.ROBOT else d.spot_human[st]
                                if ok:
                                    entries.append((0, i, (0, space.spot_class[st], b), -1))
                            elif kind is Kind.THROW:
                                ok = (
                                    at in sc.bins[b].reach.robot_from
                                    if agent is Agent.ROBOT
                                    else sc.bins[b].reach.human
                                )
                                if ok:
                                    entries.append((1, i, None, -1))
                            elif kind is Kind.GIVE:
                                if at in handover:
                                    entries.append((2, i, None, -1))
                            elif kind is Kind.TAKE:
                                entries.append((3, i, None, -1))
                        per_st.append(tuple(entries))
                    per_o.append(per_st)
                table[agent].append(per_o)
        self.table = table
        # gotos: per location, object targets (index, destination per spot) then static ones
        gotos = [i for i in space._gotos]
        acts = world.actions(Agent.ROBOT)
        n = world.n_objects
        self.goto_objs: list[tuple[tuple[int, int, tuple[int, ...]], ...]] = []
        self.goto_static: list[tuple[tuple[int, int], ...]] = []
        for at in range(n_locs):
            objs, static = [], []
            for i in gotos:
                t = acts[i].target
                if t < n:
                    dests = tuple(
                        (min(locs) if locs and at not in locs else -1)
                        for locs in (s.reach.robot_from for s in sc.spots)
                    ) + (-1,) * (world.n_bins + 2)
                    objs.append((i, t, dests))
                else:
                    reach = sc.bins[t - n].reach.robot_from if t < n + world.n_bins else handover
                    static.append((i, min(reach) if reach and at not in reach else -1))
            self.goto_objs.append(tuple(objs))
            self.goto_static.append(tuple(static))
        self.cache: tuple[dict[State, tuple[int, ...]], dict[State, tuple[int, ...]]] = ({}, {})

    def __call__(self, state: State, agent: int) -> tuple[int, ...]:
        cache = self.cache[agent]
        out = cache.get(state)
        if out is None:
            out = self._compute(state, agent)
            if len(cache) > _CACHE_LIMIT:
                cache.clear()
            cache[state] = out
        return out

    def _compute(self, state: State, agent: int) -> tuple[int, ...]:
        where, at, by, obj = state
        hand = self.hands[agent]
        statuses = list(where)
        if obj >= 0:
            statuses[obj] = self.human_offer if by == 1 else self.robot_offer
        empty = hand not in where
        partner_offer = by >= 0 and by != agent
        rows = self.table[agent][at]
        seen: set[object] = set()
        out: list[int] = []
        for o, st in enumerate(statuses):
            for kind, i, sig, spot in rows[o][st]:
                if kind == 0:  # PICK
                    if not empty or sig in seen:
                        continue
                    seen.add(sig)
                elif kind == 3:  # TAKE
                    if not (partner_offer and obj == o and empty):
                        continue
                elif kind == 4:  # PLACE
                    if where[o] != hand or sig in seen or spot in where:
                        continue
                    seen.add(sig)
                elif where[o] != hand:  # THROW, GIVE
                    continue
                out.append(i)
        if agent == 0:
            dests: set[int] = set()
            for i, t, per_spot in self.goto_objs[at]:
                dest = per_spot[where[t]]
                if dest >= 0 and dest not in dests:
                    dests.add(dest)
                    out.append(i)
            for i, dest in self.goto_static[at]:
                if dest >= 0 and dest not in dests:
                    dests.add(dest)
                    out.append(i)
        out.sort()
        out.append(self.wait[agent])
        return tuple(out)
