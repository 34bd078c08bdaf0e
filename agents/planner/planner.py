"""The goal-directed expert: a cost-optimal, human-aware planner for the two agents.

:class:`Planner` binds a world, a cost model and a human model, and answers
``plan(state, to_move)`` with a :class:`PlanResult`. Deterministic human models
(cooperative, restrictions) are searched with A* over half-steps (:mod:`.halfstep`); stochastic ones with
expectimax value iteration (:mod:`.expectimax`).

Memoisation: the runner replans at every robot decision, usually from a state the last
plan predicted. By Bellman's principle the remainder of an optimal plan is optimal from
every state it passes through, so after a search the planner caches the plan's suffix
for each of those states, at the robot's turn and at the human's (the latter keyed by the
robot action under way). Repeated or predicted states then cost a dictionary look-up.
A cached suffix is *an* optimal plan; a cold search from that state may break ties
differently but has the same cost. Stochastic models cache exact queries only.
"""

from __future__ import annotations

import logging
import math
import time
from collections import OrderedDict
from dataclasses import replace
from typing import NamedTuple

from hg_marl.agents.planner.costs import PlannerConfig, Terms
from hg_marl.agents.planner.expectimax import expectimax
from hg_marl.agents.planner.halfstep import astar
from hg_marl.agents.planner.models import HumanModel, cooperative
from hg_marl.agents.planner.plan import NO_ACTION, Plan, PlanResult, build_plan, failure
from hg_marl.agents.planner.space import Relabel, shared_space
from hg_marl.core import Agent, State, World

logger = logging.getLogger(__name__)

_Key = tuple[State, Agent, int]
_INTENT_LIMIT = 200_000


class Intent(NamedTuple):
    """What a plan says to do next, without the plan: the planner-driven humans' question.

    The same answer :meth:`Planner.plan` gives (``robot_action``, ``human_action``,
    ``plan.duration``, ``cost``) for a fraction of its price: no streams, links or terms.
    """

    success: bool
    robot_action: int
    human_action: int
    duration: float
    cost: float


class Planner:
    """A human-aware HTN planner for the robot and the human.

    Args:
        world: the task's rules (shared with the environment).
        config: search settings and cost weights.
        human_model: what the human is assumed to do; None means cooperative.
    """

    def __init__(
        self, world: World, config: PlannerConfig | None = None, human_model: HumanModel | None = None
    ) -> None:
        self.world = world
        self.config = config or PlannerConfig()
        self.human_model: HumanModel = human_model if human_model is not None else cooperative()
        self.space = shared_space(world, self.human_model, self.config.weights)
        self.domain = self.space.domain
        self._cache: OrderedDict[_Key, tuple[PlanResult, int]] = OrderedDict()
        self._intents: dict[_Key, Intent] = {}
        self._relabel = Relabel(world)
        # ground actions ruled out by name are not invariant under relabelling objects
        self._has_blocked = bool(getattr(self.human_model, "blocked", None))
        self._wait = self.space.wait

    def plan(self, state: State, to_move: Agent = Agent.ROBOT, *, robot_action: int | None = None) -> PlanResult:
        """Plan from ``state`` with ``to_move`` about to act.

        Args:
            state: the current symbolic state.
            to_move: ``ROBOT`` at a cycle boundary; ``HUMAN`` when the robot has already
                acted this cycle (``state`` includes its effect) and the human is next.
            robot_action: with ``to_move=HUMAN``, the robot action under way this cycle,
                assumed successful; it sets the first cycle's duration
                ``max(d_robot, d_human)``. If None the first cycle lasts the human's action.

        Returns:
            The result; on failure ``success`` is False and ``reason`` says why.
        """
        start = time.perf_counter()
        ra = robot_action if (to_move is Agent.HUMAN and robot_action is not None) else NO_ACTION
        key = (state, to_move, ra)
        hit = self._cache.get(key)
        if hit is not None:
            self._cache.move_to_end(key)
            return self._from_cache(hit, to_move, ra, start)
        result = self._plan(state, to_move, ra, start)
        self._store(key, result)
        return result

    def intent(self, state: State, to_move: Agent = Agent.ROBOT, *, robot_action: int | None = None) -> Intent:
        """The next actions, the duration and the cost of the plan :meth:`plan` would return.

        Deterministic human models run the search alone (no :class:`Plan` is built), on
        the state with its interchangeable objects in canonical order (:class:`.Relabel`;
        the actions are mapped back), and memoise the queries; stochastic ones ask
        :meth:`plan`. The answer is a function of the state alone.
        """
        ra = robot_action if (to_move is Agent.HUMAN and robot_action is not None) else NO_ACTION
        if self._relabel.active and not self.human_model.stochastic and not self._has_blocked:
            canonical, orig = self._relabel.canonical(state)
            if canonical != state:
                answer = self.intent(canonical, to_move, robot_action=robot_action)
                back = self._relabel.action_back
                return answer._replace(
                    robot_action=back(0, answer.robot_action, orig), human_action=back(1, answer.human_action, orig)
                )
        key = (state, to_move, ra)
        out = self._intents.get(key)
        if out is not None:
            return out
        hit = self._cache.get(key)
        if self.human_model.stochastic or hit is not None:
            res = self.plan(state, to_move, robot_action=robot_action)
            if res.plan is None:
                out = Intent(False, self._wait[0], -1, math.inf, math.inf)
            else:
                out = Intent(True, res.robot_action, res.human_action, res.plan.duration, res.cost)
        else:
            part = self._robot_part(ra)
            found = astar(self.space, state, to_move, part, self.config.node_budget)
            cycles = found.cycles
            if cycles is None:
                out = Intent(False, self._wait[0], -1, math.inf, math.inf)
            else:
                robot_next = (
                    cycles[0][0] if to_move is Agent.ROBOT else (cycles[1][0] if len(cycles) > 1 else self._wait[0])
                )
                out = Intent(True, robot_next, cycles[0][1], self._duration(cycles, part[0]), found.cost)
        if len(self._intents) > _INTENT_LIMIT:
            self._intents.clear()
        self._intents[key] = out
        return out

    def _duration(self, cycles: list[tuple[int, int]], first_robot: float) -> float:
        """Seconds of a plan's cycles: each lasts its longer action (what ``Plan.duration`` sums)."""
        specs = self.world.table.specs
        total = 0.0
        for ar, ah in cycles:
            d_r = first_robot if ar == NO_ACTION else specs[0][ar].duration
            d_h = specs[1][ah].duration
            total += d_r if d_r > d_h else d_h
        return total

    def _robot_part(self, ra: int) -> tuple[float, int]:
        if ra == NO_ACTION:
            return (0.0, NO_ACTION)
        return (self.world.durations.of(self.world.actions(Agent.ROBOT)[ra].kind), ra)

    def _plan(self, state: State, to_move: Agent, ra: int, start: float) -> PlanResult:
        cfg, model = self.config, self.human_model
        part = self._robot_part(ra)
        if model.stochastic:
            out = expectimax(self.space, state, to_move, part, cfg.node_budget, cfg.value_tolerance, cfg.max_sweeps)
            cycles, nodes, reason, terms, replayed = out.cycles, out.nodes, out.reason, out.terms, None
        else:
            res = astar(self.space, state, to_move, part, cfg.node_budget)
            cycles, nodes, reason, terms, replayed = res.cycles, res.nodes, res.reason, None, res.states
        elapsed = time.perf_counter() - start
        if cycles is None:
            result = failure(self._reason(state, reason, nodes), nodes, elapsed, self._wait[0])
            logger.debug("planning failed after %d nodes: %s", nodes, result.reason)
            return result
        plan = build_plan(self.world, state, to_move, cycles, part, replayed)
        weights = cfg.weights
        if terms is None:
            terms = plan.totals
        result = self._result(plan, weights.total(terms), weights.breakdown(terms), nodes, elapsed, False)
        if model.stochastic:
            result.extras["nominal_plan_cost"] = plan.cost(weights)
        logger.debug("planned %d cycles, cost %.3f, %d nodes, %.2f ms", len(plan), result.cost, nodes, elapsed * 1e3)
        return result

    def _result(
        self, plan: Plan, cost: float, breakdown: dict[str, float], nodes: int, elapsed: float, cached: bool
    ) -> PlanResult:
        cycles = plan.cycles
        if plan.first_to_move is Agent.ROBOT:
            robot_next, human_next = cycles[0][0], cycles[0][1]
        else:
            robot_next = cycles[1][0] if len(cycles) > 1 else self._wait[0]
            human_next = cycles[0][1]
        return PlanResult(True, plan, cost, breakdown, nodes, elapsed, "", True, robot_next, human_next, cached)

    def _reason(self, state: State, reason: str, nodes: int) -> str:
        if reason == "budget":
            budget = self.config.node_budget
            return f"budget: node budget of {budget} exhausted ({nodes} nodes) before the optimum was proven"
        why = self.domain.explain_unreachable(state)
        if why:
            return f"unreachable: {why}"
        return (
            f"no plan: all {nodes} states reachable with the '{self.human_model.name}' human were explored "
            "and none completes the task"
        )

    # ---- cache -------------------------------------------------------------------
    def _store(self, key: _Key, result: PlanResult) -> None:
        size = self.config.cache_size
        if size == 0:
            return
        self._put(key, (result, 0))
        plan = result.plan
        if plan is None or self.human_model.stochastic or not self.config.cache_suffixes:
            return
        for k, (ar, _) in enumerate(plan.cycles):
            if ar == NO_ACTION:
                continue
            if k > 0:
                self._put((plan.states[k], Agent.ROBOT, NO_ACTION), (result, k))
            self._put((plan.mids[k], Agent.HUMAN, ar), (result, k))

    def _put(self, key: _Key, value: tuple[PlanResult, int]) -> None:
        if key in self._cache:
            return
        self._cache[key] = value
        if len(self._cache) > self.config.cache_size:
            self._cache.popitem(last=False)

    def _from_cache(self, hit: tuple[PlanResult, int], to_move: Agent, ra: int, start: float) -> PlanResult:
        base, k = hit
        if base.plan is None:
            return replace(base, cached=True, nodes=0, wall_time=time.perf_counter() - start)
        plan = base.plan
        if k == 0 and plan.first_to_move is to_move:
            sub = plan
        else:
            cycles = list(plan.cycles[k:])
            root = plan.states[k]
            if to_move is Agent.HUMAN:
                root = self.world.table.successor(root, Agent.ROBOT, cycles[0][0])[0]
                cycles[0] = (NO_ACTION, cycles[0][1])
            sub = build_plan(self.world, root, to_move, cycles, self._robot_part(ra))
        terms: Terms = sub.totals
        weights = self.config.weights
        if self.human_model.stochastic:
            cost, breakdown = base.cost, base.breakdown
        else:
            cost, breakdown = weights.total(terms), weights.breakdown(terms)
        out = self._result(sub, cost, breakdown, 0, time.perf_counter() - start, True)
        if not base.optimal:
            out = replace(out, optimal=False)
        return out

    def clear_cache(self) -> None:
        """Forget memoised plans (e.g. after changing nothing but wanting cold timings)."""
        self._cache.clear()
        self._intents.clear()
