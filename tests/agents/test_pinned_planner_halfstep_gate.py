"""Pinned properties of the half-step search (``agents/planner/halfstep.py``) beyond the cost it finds.

The other tests check that the search finds a plan of optimal cost. A search can find
that cost and still do needless work or return the wrong cycles, so these tests pin:

- which nodes it expands, by two properties of best-first search:
  - A* with an admissible bound expands no node whose ``g* + h`` exceeds the optimum
    (``g*`` from a plain Dijkstra written here, over the same half-step graph, with the
    cycle costs of ``CostWeights.total(cycle_terms(...))``);
  - with the bound replaced by 0 (Dijkstra, positive cycle costs) no node is expanded twice;
- the first cycle of a search started at the human's turn.

The space is wrapped so that each expansion is seen: the search calls ``robot_edges``
once per robot node it expands and ``human_edges`` once per human node.
"""

from __future__ import annotations

import heapq
import math
from collections import Counter
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig, make_human_model
from hg_marl.agents.planner.costs import cycle_terms
from hg_marl.agents.planner.halfstep import astar
from hg_marl.agents.planner.space import Space
from hg_marl.core import Agent, State, World

SCENARIOS = ["paper2015", "generated:objects=3,seed=1,human_only=0.8", "generated:objects=3,seed=2,bins=2,locations=3"]
BUDGET = 200_000


class Watched:
    """A space whose expansions are recorded (and, with ``zero``, whose bound is 0)."""

    def __init__(self, space: Space, zero: bool = False) -> None:
        self.space, self.zero = space, zero
        self.robot_calls: list[State] = []
        self.human_calls: list[State] = []
        self.clean_calls: list[bool] = []
        self.table = _Table(space.table, self.clean_calls)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.space, name)

    def robot_edges(self, state: State) -> Any:
        self.robot_calls.append(state)
        return self._bounded(self.space.robot_edges(state))

    def human_edges(self, state: State) -> Any:
        self.human_calls.append(state)
        return self._bounded(self.space.human_edges(state))

    def _bounded(self, edges: Any) -> Any:
        return tuple(e._replace(h=0.0) for e in edges) if self.zero else edges


class _Table:
    """The rule table, with each clean-table check recorded (the search makes one per robot node)."""

    def __init__(self, table: Any, calls: list[bool]) -> None:
        self._table, self._calls = table, calls

    def __getattr__(self, name: str) -> Any:
        return getattr(self._table, name)

    def is_clean(self, where: Any) -> bool:
        out = bool(self._table.is_clean(where))
        self._calls.append(out)
        return out


def dijkstra(
    space: Space, weights: CostWeights, root: State, limit: float
) -> tuple[dict[object, float], dict[State, float]]:
    """Least cost from ``root`` to every robot node (by key) and human node (by mid-cycle state)
    within ``limit``: the cost of a cycle is charged at its human reply, as the planner's cost
    model says (``CostWeights.total`` of the cycle's terms)."""
    wait_r = space.wait[0]
    robot: dict[object, float] = {}
    human: dict[State, float] = {}
    heap: list[tuple[float, int, int, Any]] = [(0.0, 0, 0, (root, None))]
    count = 1
    while heap:
        g, kind, _, item = heapq.heappop(heap)
        if g > limit + 1e-9:
            break
        if kind == 0:
            state, _ = item
            key = space.key(state)
            if key in robot:
                continue
            robot[key] = g
            if space.table.is_clean(state.where):
                continue
            for e in space.robot_edges(state):
                heapq.heappush(heap, (g, 1, count, (e.state, (e.action, e.duration))))
                count += 1
        else:
            mid, (ar, d_r) = item
            human.setdefault(mid, g)
            for e in space.human_edges(mid):
                active_r = ar != wait_r and (ar not in space.robot_gives or e.take)
                cost = weights.total(cycle_terms(d_r, active_r, e.duration, e.active, e.holding))
                heapq.heappush(heap, (g + cost, 0, count, (e.state, None)))
                count += 1
    return robot, human


def roots(world: World) -> list[State]:
    return [world.initial_state(np.random.default_rng(seed)) for seed in range(3)]


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_no_node_is_expanded_whose_least_cost_plus_bound_exceeds_the_optimum(scenario: str) -> None:
    """A* with an admissible bound: every node it expands has ``g* + h <= C*`` (the optimal
    plan keeps a node with ``f <= C*`` in the queue until the plan's end is taken). A
    priority for human nodes other than ``g + h`` expands nodes past the optimum."""
    world = World(scenario)
    weights = CostWeights()
    planner = Planner(world, PlannerConfig(weights=weights), human_model=make_human_model("cooperative"))
    space = planner.space
    for root in roots(world):
        watched = Watched(space)
        out = astar(watched, root, Agent.ROBOT, (0.0, -1), BUDGET)
        assert out.cycles is not None
        best = out.cost
        g_robot, g_human = dijkstra(space, weights, root, best)
        assert g_robot[space.key(root)] == 0.0
        bound_of: dict[State, float] = {}
        for s in watched.robot_calls:
            for e in space.robot_edges(s):
                bound_of[e.state] = min(bound_of.get(e.state, math.inf), e.h)
        assert watched.human_calls, "the search expands human nodes"
        for s in watched.robot_calls:
            key = space.key(s)
            assert key in g_robot and g_robot[key] + space.bound(s, key) <= best + 1e-9
        for mid in watched.human_calls:
            assert mid in g_human and g_human[mid] + bound_of[mid] <= best + 1e-9


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_with_a_zero_bound_no_node_is_expanded_twice(scenario: str) -> None:
    """With the bound 0 the search is Dijkstra's, and cycle costs are positive: a node taken
    from the queue has its least cost, so a later entry for it (stale, or reached again at the
    same cost) must be skipped. The cost found is still the optimum."""
    world = World(scenario)
    planner = Planner(world, human_model=make_human_model("cooperative"))
    space = planner.space
    for root in roots(world):
        reference = astar(space, root, Agent.ROBOT, (0.0, -1), BUDGET)
        watched = Watched(space, zero=True)
        out = astar(watched, root, Agent.ROBOT, (0.0, -1), BUDGET)
        assert out.cost == pytest.approx(reference.cost, abs=1e-9)
        robot = Counter(space.key(s) for s in watched.robot_calls)
        assert robot and max(robot.values()) == 1
        # a human node is (mid-cycle key, robot duration, robot active): one state may stand for
        # several of them, never for more than the robot edges that lead to it
        human = Counter(watched.human_calls)
        keys_to: dict[State, set[object]] = {}
        for s in set(watched.robot_calls):
            for e in space.robot_edges(s):
                keys_to.setdefault(e.state, set()).add(e.key)
        assert human and all(n <= len(keys_to[mid]) for mid, n in human.items())
        # the search counts robot nodes (cycle boundaries): each one expanded is first looked
        # at for a clean table, and the ones not clean are expanded over the robot's moves
        assert out.nodes == len(watched.clean_calls)
        assert sum(not clean for clean in watched.clean_calls) == len(watched.robot_calls)


@pytest.mark.parametrize("scenario", ["paper2015", "generated:objects=3,seed=1,human_only=0.8"])
def test_a_search_from_the_humans_turn_plans_no_robot_action_for_its_first_cycle(scenario: str) -> None:
    """At the human's turn the robot's action is already under way: the search chooses only
    the human's reply for the first cycle, whose robot action is -1, and the robot's actions
    from the second cycle on."""
    world = World(scenario)
    planner = Planner(world, human_model=make_human_model("cooperative"))
    for root in roots(world):
        ar = next(a for a in world.feasible_indices(root, Agent.ROBOT) if a != world.table.wait[Agent.ROBOT])
        step = world.step(root, Agent.ROBOT, ar)
        out = astar(planner.space, step.state, Agent.HUMAN, (step.duration, ar), BUDGET)
        assert out.cycles is not None and len(out.cycles) >= 2
        assert out.cycles[0][0] == -1
        assert world.mask(step.state, Agent.HUMAN)[out.cycles[0][1]]
        assert all(r >= 0 for r, _ in out.cycles[1:])
