"""The planner's search as it was before its inner loop was compiled: a reference to time against.

:class:`ReferenceSpace` computes the search space's edges and candidates as before
(``RuleTable.successor_feasible`` per edge, the bound's sums by ``math.fsum``, the candidate
loop as it was) and :func:`reference_astar` is the search loop as it was (seven parallel
node arrays). ``benchmarks/planner_latency.py`` times cold plans with both in the same run,
so the ratio holds on a loaded machine, and checks that they find the same plans.
"""

from __future__ import annotations

import heapq
import math

from hg_marl.agents.planner.costs import CostWeights, cycle_cost
from hg_marl.agents.planner.domain import Domain
from hg_marl.agents.planner.halfstep import SearchOutcome
from hg_marl.agents.planner.space import HumanEdge, RobotEdge, Space
from hg_marl.agents.planner.tables import candidate_entries
from hg_marl.core import Agent, Kind, State


class ReferenceSpace(Space):
    """The search space's edges as computed before the transitions were compiled (a reference)."""

    def __init__(self, domain: Domain, weights: CostWeights) -> None:
        super().__init__(domain, weights)
        self._exact.packed = None  # the bound's sums by ``fsum``
        self._entries = candidate_entries(self)  # every kind per entry, as the loop was

    def robot_edges(self, state: State) -> tuple[RobotEdge, ...]:
        out = self._robot_edges.get(state)
        if out is None:
            apply, key_of, base = self.table.successor_feasible, self.key, self.base
            cr = [c for c, _ in self.coefs]
            edges = []
            for ar in self.candidates(state, Agent.ROBOT):
                s1, d_r = apply(state, Agent.ROBOT, ar)
                key = key_of(s1)
                sm = self.cached_sums(s1, key)
                if sm is not None:
                    h = base + max(v + c * d_r for v, c in zip(sm, cr, strict=True))
                    edges.append(RobotEdge(ar, s1, d_r, key, h))
            out = self._robot_edges[state] = tuple(edges)
        return out

    def human_edges(self, state: State) -> tuple[HumanEdge, ...]:
        out = self._human_edges.get(state)
        if out is None:
            apply, key_of, base = self.table.successor_feasible, self.key, self.base
            hand_h, wait_h = self.table.hand[Agent.HUMAN], self.wait[Agent.HUMAN]
            edges = []
            for ah in self.allowed(state):
                s2, d_h = apply(state, Agent.HUMAN, ah)
                key = key_of(s2)
                sm = self.cached_sums(s2, key)
                if sm is not None:
                    take, holding = ah in self.human_takes, hand_h in s2.where
                    edges.append(HumanEdge(ah, s2, d_h, take, ah != wait_h, holding, key, base + max(sm)))
            out = self._human_edges[state] = tuple(edges)
        return out

    def _candidates(self, state: State, agent: int) -> tuple[int, ...]:
        where, at, by, obj = state
        table = self.table
        hand = table.hand[agent]
        statuses = list(where)
        if obj >= 0:
            d = self.domain
            statuses[obj] = d.human_offer if by == 1 else d.robot_offer
        empty = hand not in where
        partner_offer = by >= 0 and by != agent
        rows = self._entries[agent][at]
        seen: set[object] = set()
        out: list[int] = []
        for o, st in enumerate(statuses):
            for kind, i, sig, spot in rows[o][st]:
                if kind is Kind.PICK:
                    if not empty or sig in seen:
                        continue
                    seen.add(sig)
                elif kind is Kind.TAKE:
                    if not (partner_offer and obj == o and empty):
                        continue
                elif kind is Kind.PLACE:
                    if where[o] != hand or sig in seen or spot in where:
                        continue
                    seen.add(sig)
                elif where[o] != hand:  # THROW, GIVE
                    continue
                out.append(i)
        if agent == 0:
            n = table.n_objects
            goto = table.action_index(0, Kind.GOTO, target=0)
            dests: set[int] = set()
            per_place = table.goto_obj[at]
            for t, p in enumerate(where):
                dest = per_place[p]
                if dest >= 0 and dest not in dests:
                    dests.add(dest)
                    out.append(goto + t)
            for k, dest in enumerate(table.goto_static[at]):
                if dest >= 0 and dest not in dests:
                    dests.add(dest)
                    out.append(goto + n + k)
        out.sort()
        out.append(self.wait[agent])
        return tuple(out)


def reference_astar(
    space: Space, root: State, to_move: Agent, robot_part: tuple[float, int], budget: int
) -> SearchOutcome:
    """Find a minimum-cost plan from ``root`` over half-steps (see the module docstring)."""
    world = space.world
    weights = space.weights.vector
    wait_r, wait_h = space.wait
    key_of = space.key
    done = space.table.done
    gives = space.robot_gives
    final_cost = cycle_cost(weights, world.durations.wait, False, world.durations.wait, False, False)
    sums = space.cached_sums
    robot_edges = space.robot_edges
    human_edges = space.human_edges

    # node arrays
    states: list[State] = []
    parents: list[int] = []
    acts: list[int] = []  # robot nodes: the human action that led here; human nodes: the robot action
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
        keys.append(key)
        kinds.append(kind)
        durs.append(dr)
        actives.append(act)
        push(heap, (f, -g, node))

    def expand_r(node: int, g: float, s: State) -> None:
        for ar, s1, d_r, k1, h in robot_edges(s):
            active = ar != wait_r
            key = (k1, d_r, active)
            if g >= best_h.get(key, math.inf) - 1e-12:
                continue
            best_h[key] = g
            add(s1, node, ar, g, 1, key, g + h, d_r, active)

    def expand_h(node: int, g: float) -> None:
        s1 = states[node]
        d_r = durs[node]
        active_r = actives[node]
        ar = acts[node]
        parent = parents[node]
        noop = states[parent] if (ar == wait_r and parent >= 0) else None
        give = ar in gives
        for ah, s2, d_h, take, active_h, holding, key, h in human_edges(s1):
            if noop is not None and s2 == noop:
                continue  # a cycle in which nothing happens only costs time
            g2 = g + cycle_cost(weights, d_r, active_r and (not give or take), d_h, active_h, holding)
            if g2 >= best_r.get(key, math.inf) - 1e-12:
                continue
            best_r[key] = g2
            add(s2, node, ah, g2, 0, key, g2 + h, 0.0, False)

    if to_move is Agent.HUMAN:
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
            return SearchOutcome(_reference_path(states, parents, acts, kinds, node, wait_r), g, expanded)
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
        if all(p in done[o] for o, p in enumerate(where)):
            add(s, node, wait_h, g + final_cost, 2, None, g + final_cost, 0.0, False)
            continue
        expand_r(node, g, s)
    return SearchOutcome(None, math.inf, expanded, "no plan")


def _reference_path(
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
