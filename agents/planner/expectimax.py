"""Planning against a stochastic human: expectation over the human, minimum over the robot.

A stochastic model (e.g. "idles with probability p, else cooperative") turns the task
into a stochastic shortest-path problem with loops (the human may idle forever), so
instead of a tree-shaped expectimax the planner enumerates the cycle-boundary states
reachable under the model (each counts as a node against the budget) and solves the
Bellman equations by Gauss-Seidel value iteration,
``V(s) = min_r sum_k p_k min_{h in set_k} [c(r, h) + V(s')]``, starting from the
admissible bound (so values rise monotonically to the optimum). The robot's action is
the minimising one; the returned nominal plan follows it and, for the human, the most
permissive choice set (the human acting as hoped), while the cost and its breakdown
are expectations under the model, obtained by evaluating the final policy.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from hg_marl.agents.planner.costs import Terms, cycle_terms, robot_active
from hg_marl.agents.planner.space import Space
from hg_marl.core import Agent, State

# per robot action: (robot action, branches); per branch: (p, [(human action, terms, cost, next state)])
Edge = tuple[int, Terms, float, State]
Branches = list[tuple[float, list[Edge]]]


@dataclass
class ExpectimaxOutcome:
    """Value-iteration result: nominal cycles (None on failure), expected cost and terms."""

    cycles: list[tuple[int, int]] | None
    cost: float
    terms: Terms
    nodes: int
    reason: str = ""


class _Graph:
    def __init__(self, space: Space) -> None:
        self.space = space
        self.world = space.world
        self.trans: dict[State, list[tuple[int, Branches]]] = {}

    def replies(self, s1: State, d_r: float, ar: int) -> Branches:
        world, space = self.world, self.space
        wait_h = space.wait[1]
        hand_h = world.hand[Agent.HUMAN]
        cands = space.candidates(s1, Agent.HUMAN)
        out: Branches = []
        for p, choice in space.domain.human_model.choices(world, s1, cands):
            edges = []
            for ah in choice:
                o = world.step(s1, Agent.HUMAN, ah)
                active_r = robot_active(world, ar, ah)
                t = cycle_terms(d_r, active_r, o.duration, ah != wait_h, hand_h in o.state.where)
                edges.append((ah, t, space.weights.total(t), o.state))
            out.append((p, edges))
        return out

    def expand(self, s: State) -> list[tuple[int, Branches]]:
        world, space = self.world, self.space
        wait_r = space.wait[0]
        if world.is_clean(s):
            o = world.step(s, Agent.ROBOT, wait_r)
            return [(wait_r, self.replies(o.state, o.duration, wait_r))]
        out = []
        for ar in space.candidates(s, Agent.ROBOT):
            o = world.step(s, Agent.ROBOT, ar)
            out.append((ar, self.replies(o.state, o.duration, ar)))
        return out


def _q(branches: Branches, value: dict[State, float], terminal: bool) -> float:
    total = 0.0
    for p, edges in branches:
        total += p * min(c + (0.0 if terminal else value[s2]) for _, _, c, s2 in edges)
    return total


def expectimax(
    space: Space, root: State, to_move: Agent, robot_part: tuple[float, int], budget: int, tol: float, max_sweeps: int
) -> ExpectimaxOutcome:
    """Optimal robot policy in expectation against the space's stochastic human model."""
    world = space.world
    graph = _Graph(space)
    root_branches = graph.replies(root, *robot_part) if to_move is Agent.HUMAN else None
    frontier = [e[3] for _, edges in root_branches for e in edges] if root_branches else [root]
    order: list[State] = []
    while frontier:
        s = frontier.pop()
        if s in graph.trans:
            continue
        if len(order) >= budget:
            return ExpectimaxOutcome(None, math.inf, Terms(), len(order), "budget")
        graph.trans[s] = graph.expand(s)
        order.append(s)
        if not world.is_clean(s):
            frontier.extend(e[3] for _, br in graph.trans[s] for _, edges in br for e in edges)
    clean = {s: world.is_clean(s) for s in order}
    value = {s: space.bound(s) for s in order}
    for _ in range(max_sweeps):
        delta = 0.0
        for s in order:
            if math.isinf(value[s]) and not clean[s]:
                continue  # no method left for some object: a dead end for good
            new = min(_q(br, value, clean[s]) for _, br in graph.trans[s])
            if not math.isinf(new):
                delta = max(delta, abs(new - value[s]))
            value[s] = new
        if delta <= tol:
            break
    else:
        return ExpectimaxOutcome(None, math.inf, Terms(), len(order), "budget")

    def best_action(s: State) -> tuple[int, Branches]:
        return min(graph.trans[s], key=lambda item: _q(item[1], value, clean[s]))

    def best_edge(edges: list[Edge], terminal: bool) -> Edge:
        return min(edges, key=lambda e: e[2] + (0.0 if terminal else value[e[3]]))

    policy = {s: best_action(s) for s in order}
    cost = _q(root_branches, value, False) if root_branches else value[root]
    if math.isinf(cost):
        return ExpectimaxOutcome(None, math.inf, Terms(), len(order), "no plan")
    finite = [s for s in order if not math.isinf(value[s])]
    terms = _evaluate(finite, policy, clean, best_edge, tol, max_sweeps)
    if root_branches:
        root_terms = Terms()
        for p, edges in root_branches:
            e = best_edge(edges, False)
            root_terms = root_terms + tuple(p * (a + b) for a, b in zip(e[1], terms[e[3]], strict=True))
    else:
        root_terms = terms[root]
    # nominal plan: the robot's policy, the human's most permissive choice set
    cycles: list[tuple[int, int]] = []
    s = root
    if root_branches:
        e = best_edge(max(root_branches, key=lambda b: len(b[1]))[1], False)
        cycles.append((-1, e[0]))
        s = e[3]
    for _ in range(len(order) + 1):
        ar, branches = policy[s]
        e = best_edge(max(branches, key=lambda b: len(b[1]))[1], clean[s])
        cycles.append((ar, e[0]))
        if clean[s]:
            return ExpectimaxOutcome(cycles, cost, root_terms, len(order))
        s = e[3]
    return ExpectimaxOutcome(None, math.inf, Terms(), len(order), "no plan")


def _evaluate(
    order: list[State],
    policy: dict[State, tuple[int, Branches]],
    clean: dict[State, bool],
    best_edge: Callable[[list[Edge], bool], Edge],
    tol: float,
    max_sweeps: int,
) -> dict[State, Terms]:
    """Expected raw terms of each state under the fixed policy (iterative policy evaluation)."""
    terms: dict[State, Terms] = {s: Terms() for s in order}
    for _ in range(max_sweeps):
        delta = 0.0
        for s in order:
            _, branches = policy[s]
            acc = [0.0] * 5
            for p, edges in branches:
                e = best_edge(edges, clean[s])
                nxt = Terms() if clean[s] else terms[e[3]]
                for i in range(5):
                    acc[i] += p * (e[1][i] + nxt[i])
            new = Terms(*acc)
            delta = max(delta, max(abs(a - b) for a, b in zip(new, terms[s], strict=True)))
            terms[s] = new
        if delta <= tol:
            break
    return terms
