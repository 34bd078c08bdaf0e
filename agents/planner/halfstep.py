"""Cost-optimal search over half-steps (the robot's action, then the human's reply).

A* over the cycles of the joint plan, with an admissible bound (:meth:`Space.sums`), so
the first terminal node taken from the queue is optimal. The transposition table keys
on the canonical state (symmetric states share an entry) and keeps the best cost-so-far;
a node reached more cheaply later is re-opened, which keeps optimality even where the
bound is not consistent. The tests check the optimum against an exhaustive
uniform-cost search over joint cycles (``tests/agents/reference_search.py``).

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
- **Transitions from the core's table.** Candidates are feasible by construction, so the
  search applies them with ``RuleTable.successor_feasible`` (the rule table ``World.step``
  uses, without the events and names that are for the environment).

Ties are broken by lower ``f``, then larger cost-so-far, then insertion order (which
follows the candidates' index order): the search is deterministic. The node count and
the budget are over robot nodes (cycle boundaries); human nodes are bounded by them.
A search that starts at the human's turn expands the root over the human's actions only;
the first cycle's duration is ``max(d_robot, d_human)`` with ``d_robot`` the duration of
the robot's action already under way (0 when the caller does not say which it was).
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass

from hg_marl.agents.planner.costs import cycle_cost
from hg_marl.agents.planner.space import Space
from hg_marl.core import Agent, State


@dataclass
class SearchOutcome:
    """Raw search result: the cycles of the best plan (None on failure) and statistics."""

    cycles: list[tuple[int, int]] | None
    cost: float
    nodes: int
    reason: str = ""
    states: list[tuple[State, State]] | None = None
    """Per cycle of the plan, the state after its robot action and the state after the cycle
    (what replaying the cycles from the root gives: the search applied the same rules)."""


def astar(space: Space, root: State, to_move: Agent, robot_part: tuple[float, int], budget: int) -> SearchOutcome:
    """Find a minimum-cost plan from ``root`` over half-steps (see the module docstring)."""
    world = space.world
    weights = space.weights.vector
    wait_r, wait_h = space.wait
    key_of = space.key
    is_clean = space.table.is_clean
    gives = space.robot_gives
    final_cost = cycle_cost(weights, world.durations.wait, False, world.durations.wait, False, False)
    sums = space.cached_sums
    robot_edges = space.robot_edges
    human_edges = space.human_edges

    # nodes: (state, parent, action, key, kind, robot duration, robot active); ``action`` is,
    # at a robot node, the human action that led there and, at a human node, the robot action;
    # ``kind`` 0 robot node, 1 human node, 2 terminal. One tuple per node: the inner loop's
    # cheapest record.
    nodes: list[tuple[State, int, int, object, int, float, bool]] = []
    best_r: dict[object, float] = {}
    best_h: dict[object, float] = {}
    heap: list[tuple[float, float, int]] = []
    push, pop, inf = heapq.heappush, heapq.heappop, math.inf
    new_node = nodes.append

    if to_move is Agent.HUMAN:
        d_r, ra = robot_part
        # the root is a human node; its replies are the first cycle (the robot's part given)
        new_node((root, -1, ra, None, 1, d_r, ra >= 0 and ra != wait_r))
        push(heap, (0.0, -0.0, 0))
    else:
        key = key_of(root)
        if sums(root, key) is None:
            return SearchOutcome(None, math.inf, 0, "unreachable")
        best_r[key] = 0.0
        new_node((root, -1, -1, key, 0, 0.0, False))
        push(heap, (0.0, -0.0, 0))
    expanded = 0

    while heap:
        _, neg_g, node = pop(heap)
        g = -neg_g
        s, parent, act, nkey, kind, d_r, active_r = nodes[node]
        if kind == 2:
            cycles, states = _path(nodes, node, wait_r)
            return SearchOutcome(cycles, g, expanded, states=states)
        if kind == 0:
            if g > best_r[nkey] + 1e-12:
                continue
        elif nkey is not None and g > best_h[nkey] + 1e-12:
            continue
        if kind == 1:  # a human node: the cycle's replies, priced
            noop = nodes[parent][0] if (act == wait_r and parent >= 0) else None
            give = act in gives
            for ah, s2, d_h, take, active_h, holding, key, h in human_edges(s):
                if noop is not None and s2 == noop:
                    continue  # a cycle in which nothing happens only costs time
                g2 = g + cycle_cost(weights, d_r, active_r and (not give or take), d_h, active_h, holding)
                if g2 >= best_r.get(key, inf) - 1e-12:
                    continue
                best_r[key] = g2
                push(heap, (g2 + h, -g2, len(nodes)))
                new_node((s2, node, ah, key, 0, 0.0, False))
            continue
        if expanded >= budget:
            return SearchOutcome(None, math.inf, expanded, "budget")
        expanded += 1
        if is_clean(s.where):
            g2 = g + final_cost
            push(heap, (g2, -g2, len(nodes)))
            new_node((s, node, wait_h, None, 2, 0.0, False))
            continue
        for ar, s1, d_r, key, h in robot_edges(s):
            if g >= best_h.get(key, inf) - 1e-12:
                continue
            best_h[key] = g
            push(heap, (g + h, -g, len(nodes)))
            new_node((s1, node, ar, key, 1, d_r, ar != wait_r))
    return SearchOutcome(None, math.inf, expanded, "no plan")


def _path(
    nodes: list[tuple[State, int, int, object, int, float, bool]], node: int, wait_r: int
) -> tuple[list[tuple[int, int]], list[tuple[State, State]]]:
    """The cycles from the root to terminal ``node``, with each cycle's (mid-cycle, next) states.

    The last cycle is the robot's completing ``wait`` and the human's ``wait`` on the clean
    table (no object in a hand, so no offer to lapse): both leave the state as it is.
    """
    done = nodes[node][0]
    out, states = [(wait_r, nodes[node][2])], [(done, done)]
    node = nodes[node][1]
    while node >= 0:
        h = nodes[node][1]  # robot node ``node`` was reached by a human reply from human node ``h``
        if h < 0:
            break  # the root (a robot node)
        ar = nodes[h][2] if nodes[h][1] >= 0 else -1
        out.append((ar, nodes[node][2]))
        states.append((nodes[h][0], nodes[node][0]))
        node = nodes[h][1]
    out.reverse()
    states.reverse()
    return out, states
