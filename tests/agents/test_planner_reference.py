"""An exhaustive reference for the planner's tests: uniform-cost search over joint cycles.

Independent of the planner's domain, bound and symmetry reduction: every feasible
robot action (``World.feasible_indices``), then every feasible human action the model
allows, applied with ``World.step``, costed with the same cycle terms and weights.
"""

from __future__ import annotations

import heapq
import itertools
import math

import numpy as np

from hg_marl.agents.planner import CostWeights, HumanModel
from hg_marl.agents.planner.costs import cycle_terms, robot_active
from hg_marl.core import Agent, State, World


def reference_cost(
    world: World,
    root: State,
    weights: CostWeights,
    model: HumanModel | None = None,
    to_move: Agent = Agent.ROBOT,
    robot_part: tuple[float, int] = (0.0, -1),
    limit: int = 2_000_000,
) -> float:
    """Minimum total cost to complete the task from ``root`` (inf if impossible)."""
    wait_h = world.n_actions(Agent.HUMAN) - 1
    hand_h = world.hand[Agent.HUMAN]

    def human_moves(s1: State) -> list[int]:
        cands = world.feasible_indices(s1, Agent.HUMAN)
        if model is None:
            return cands
        allowed: list[int] = []
        for _, choice in model.choices(world, s1, cands):
            allowed += choice
        return sorted(set(allowed))

    def replies(s1: State, d_r: float, ar: int, g: float) -> list[tuple[float, State]]:
        out = []
        for ah in human_moves(s1):
            o = world.step(s1, Agent.HUMAN, ah)
            t = cycle_terms(d_r, robot_active(world, ar, ah), o.duration, ah != wait_h, hand_h in o.state.where)
            out.append((g + weights.total(t), o.state))
        return out

    counter = itertools.count()
    heap: list[tuple[float, int, State | None]] = []
    best: dict[State, float] = {}
    starts = replies(root, *robot_part, 0.0) if to_move is Agent.HUMAN else [(0.0, root)]
    for g, s in starts:
        if g < best.get(s, math.inf):
            best[s] = g
            heapq.heappush(heap, (g, next(counter), s))
    pops = 0
    while heap:
        g, _, s = heapq.heappop(heap)
        if s is None:
            return g
        if g > best.get(s, math.inf):
            continue
        pops += 1
        if pops > limit:
            raise RuntimeError("reference search too large")
        for ar in world.feasible_indices(s, Agent.ROBOT):
            o = world.step(s, Agent.ROBOT, ar)
            if o.reward == 1.0:
                done = min(c for c, _ in replies(o.state, o.duration, ar, g))
                heapq.heappush(heap, (done, next(counter), None))
                continue
            for c, s2 in replies(o.state, o.duration, ar, g):
                if c < best.get(s2, math.inf):
                    best[s2] = c
                    heapq.heappush(heap, (c, next(counter), s2))
    return math.inf


def execute(
    world: World,
    plan_cycles: tuple[tuple[int, int], ...],
    root: State,
    robot_part: tuple[float, int] = (0.0, -1),
) -> tuple[float, list[tuple[float, bool, float, bool, bool]], float]:
    """Run cycles with ``World.step``; return (clock, per-cycle raw inputs, reward of the last robot action).

    Asserts every action succeeds.
    """
    wait_h = world.n_actions(Agent.HUMAN) - 1
    hand_h = world.hand[Agent.HUMAN]
    state, clock, reward, parts = root, 0.0, 0.0, []
    for ar, ah in plan_cycles:
        if ar < 0:
            d_r, r_act = robot_part
        else:
            o = world.step(state, Agent.ROBOT, ar)
            assert o.ok, f"robot {world.action_names[0][ar]} failed"
            state, d_r, r_act, reward = o.state, o.duration, ar, o.reward
        o = world.step(state, Agent.HUMAN, ah)
        assert o.ok, f"human {world.action_names[1][ah]} failed"
        state = o.state
        parts.append((d_r, robot_active(world, r_act, ah), o.duration, ah != wait_h, hand_h in state.where))
        clock += max(d_r, o.duration)
    return clock, parts, reward


def initial_states(world: World, seeds: range) -> list[State]:
    """Distinct initial states drawn with seeded generators."""
    out: list[State] = []
    for seed in seeds:
        s = world.initial_state(np.random.default_rng(seed))
        if s not in out:
            out.append(s)
    return out
