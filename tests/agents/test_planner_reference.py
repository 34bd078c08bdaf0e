"""An exhaustive reference for the planner's tests: uniform-cost search over joint cycles.

Independent of the planner's domain, bound and symmetry reduction: every feasible
robot action (``World.feasible_indices``), then every feasible human action the model
allows, applied with ``World.step``, and priced by :func:`reference_terms`, a second
implementation of the cost model written from its definition (not the planner's
``cycle_terms``/``CostWeights.total``), so a mistake in the planner's pricing shows.
"""

from __future__ import annotations

import heapq
import itertools
import math

import numpy as np

from hg_marl.agents.planner import CostWeights, HumanModel
from hg_marl.core import Agent, State, World


def reference_terms(
    world: World, d_r: float, ar: int, d_h: float, ah: int, holding: bool
) -> tuple[float, float, float, float, float]:
    """One cycle's raw terms (time, human effort, effort balance, human idle, holding).

    From the cost model's definition: ``dt = max(d_r, d_h)``; the human is active unless it
    waits; the robot is active unless it waits, has no action in the cycle (``ar < 0``), or
    gives and the human does not take in reply.
    """
    robot_kind = "none" if ar < 0 else world.action_names[Agent.ROBOT][ar].split("(")[0]
    human_kind = world.action_names[Agent.HUMAN][ah].split("(")[0]
    robot_idle = robot_kind in ("none", "wait") or (robot_kind == "give" and human_kind != "take")
    e_r = 0.0 if robot_idle else d_r
    e_h = 0.0 if human_kind == "wait" else d_h
    dt = max(d_r, d_h)
    return (dt, e_h, max(0.0, e_h - e_r), dt - e_h, dt if holding else 0.0)


def reference_price(weights: CostWeights, terms: tuple[float, ...]) -> float:
    """Weighted sum of one cycle's terms, field by field."""
    time, effort, balance, idle, holding = terms
    return (
        weights.time * time
        + weights.human_effort * effort
        + weights.effort_balance * balance
        + weights.human_idle * idle
        + weights.human_holding * holding
    )


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
    hand_h = world.hand[Agent.HUMAN]

    def human_moves(s1: State) -> list[int]:
        cands = world.feasible_indices(s1, Agent.HUMAN)
        if model is None:
            return cands
        allowed: list[int] = []
        for _, choice in model.choices(world, s1, cands):
            allowed += choice
        return sorted(set(allowed))

    answered: dict[State, list[tuple[int, float, State]]] = {}

    def answers(s1: State) -> list[tuple[int, float, State]]:
        # the human's moves from a mid-cycle state, stepped once (many (state, robot action)
        # pairs lead to the same mid-cycle state); priced per robot action below
        out = answered.get(s1)
        if out is None:
            out = answered[s1] = []
            for ah in human_moves(s1):
                o = world.step(s1, Agent.HUMAN, ah)
                out.append((ah, o.duration, o.state))
        return out

    def replies(s1: State, d_r: float, ar: int, g: float) -> list[tuple[float, State]]:
        out = []
        for ah, d_h, s2 in answers(s1):
            t = reference_terms(world, d_r, ar, d_h, ah, hand_h in s2.where)
            out.append((g + reference_price(weights, t), s2))
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
) -> tuple[float, list[tuple[float, ...]], float]:
    """Run cycles with ``World.step``; return (clock, per-cycle reference terms, reward of the last robot action).

    Asserts every action succeeds.
    """
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
        parts.append(reference_terms(world, d_r, r_act, o.duration, ah, hand_h in state.where))
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
