"""A reference for the half-step search: A* over joint cycles, on ``World.step``.

The planner searched this way before :mod:`hg_marl.agents.planner.halfstep`; the tests
keep it to check that both find plans of the same cost.

Best-first branch and bound (A*): nodes are cycle-boundary states (the robot to move),
edges are joint cycles (the robot's candidate, then each human action the model allows,
applied with ``World.step``), edge costs are the weighted cycle terms, and the bound is
:meth:`Space.bound`, admissible, so the first terminal node taken from the queue is
optimal. The transposition table keys on the canonical state (symmetric states share an
entry) and keeps the best cost-so-far; a node reached more cheaply later is re-opened,
which keeps optimality even where the bound is not consistent. Ties are broken by
larger cost-so-far (deeper first), then insertion order, which follows the candidates'
index order: the search is deterministic.

A search that starts at the human's turn expands the root over the human's actions only;
the first cycle's duration is ``max(d_robot, d_human)`` with ``d_robot`` the duration of
the robot's action already under way (0 when the caller does not say which it was).
"""

from __future__ import annotations

import heapq
import math

from hg_marl.agents.planner.halfstep import SearchOutcome
from hg_marl.agents.planner.space import Space
from hg_marl.core import Agent, State


def astar(space: Space, root: State, to_move: Agent, robot_part: tuple[float, int], budget: int) -> SearchOutcome:
    """Find a minimum-cost plan from ``root`` (see the module docstring)."""
    world, model = space.world, space.domain.human_model
    w = space.weights.vector
    w_time, w_eff, w_bal, w_idle, w_hold = w
    wait_r, wait_h = space.wait
    hand_h = world.hand[Agent.HUMAN]
    step = world.step
    robot, human = Agent.ROBOT, Agent.HUMAN

    # node arrays: state, parent id, joint action, cost so far
    states: list[State] = []
    parents: list[int] = []
    actions: list[tuple[int, int]] = []
    gs: list[float] = []
    keys: list[object] = []
    best: dict[object, float] = {}
    heap: list[tuple[float, float, int]] = []

    def push(state: State, parent: int, action: tuple[int, int], g: float, terminal: bool) -> None:
        key: object = None
        if terminal:
            h = 0.0
        else:
            key = space.key(state)
            if g >= best.get(key, math.inf) - 1e-12:
                return
            best[key] = g
            h = space.bound(state, key)
            if math.isinf(h):
                return
        node = len(states)
        states.append(state)
        parents.append(parent)
        actions.append(action)
        gs.append(g)
        keys.append(key)
        terminals.append(terminal)
        heapq.heappush(heap, (g + h, -g, node))

    terminals: list[bool] = []

    gives = space.robot_gives
    takes = space.human_takes

    def human_replies(s1: State, d_r: float, active_r: bool, g: float, parent: int, ar: int) -> None:
        cands = space.candidates(s1, human)
        for _, choice in model.choices(world, s1, cands):
            for ah in choice:
                out = step(s1, human, ah)
                s2 = out.state
                if ar == wait_r and parent >= 0 and s2 == root_state_of[parent]:
                    continue  # a cycle in which nothing happens only costs time
                d_h = out.duration
                dt = d_r if d_r > d_h else d_h
                e_h = d_h if ah != wait_h else 0.0
                e_r = d_r if active_r and (ar not in gives or ah in takes) else 0.0
                c = w_time * dt + w_eff * e_h + w_idle * (dt - e_h)
                if e_h > e_r:
                    c += w_bal * (e_h - e_r)
                if hand_h in s2.where:
                    c += w_hold * dt
                push(s2, parent, (ar if parent >= 0 else -1, ah), g + c, False)

    # root_state_of[parent] is the state a parent node stands for (for the no-op check)
    root_state_of: dict[int, State] = {}
    if to_move is human:
        root_state_of[-1] = root
        d_r, ra = robot_part
        human_replies(root, d_r, ra >= 0 and ra != wait_r, 0.0, -1, ra)
        if not heap:
            return SearchOutcome(None, math.inf, 0, "unreachable")
    else:
        if math.isinf(space.bound(root)):
            return SearchOutcome(None, math.inf, 0, "unreachable")
        push(root, -1, (-1, -1), 0.0, False)

    expanded = 0
    while heap:
        _, neg_g, node = heapq.heappop(heap)
        g = -neg_g
        if terminals[node]:
            return SearchOutcome(_path(parents, actions, node), g, expanded)
        s = states[node]
        if g > best[keys[node]] + 1e-12:
            continue  # superseded by a cheaper path to the same (canonical) state
        if expanded >= budget:
            return SearchOutcome(None, math.inf, expanded, "budget")
        expanded += 1
        root_state_of[node] = s
        if world.is_clean(s):
            out = step(s, robot, wait_r)
            final = min(
                _final_cost(space, s, out.duration, ah) for _, ch in model.choices(world, s, (wait_h,)) for ah in ch
            )
            push(s, node, (wait_r, wait_h), g + final, True)
            continue
        for ar in space.candidates(s, robot):
            out = step(s, robot, ar)
            human_replies(out.state, out.duration, ar != wait_r, g, node, ar)
    return SearchOutcome(None, math.inf, expanded, "no plan")


def _final_cost(space: Space, state: State, d_r: float, ah: int) -> float:
    d_h = space.world.step(state, Agent.HUMAN, ah).duration
    w = space.weights
    dt = max(d_r, d_h)
    return w.time * dt + w.human_idle * dt


def _path(parents: list[int], actions: list[tuple[int, int]], node: int) -> list[tuple[int, int]]:
    out = []
    while node >= 0:
        out.append(actions[node])
        node = parents[node]
    out.reverse()
    if out and out[0] == (-1, -1):
        out.pop(0)  # the root's own entry
    return out
