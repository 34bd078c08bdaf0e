"""Adaptation headroom: how much a scenario rewards knowing one's partner, before any robot runs.

For an *assumed* partner ``A`` and a *true* partner ``T`` (stationary humans), the entry
``M[A, T]`` is the exact long-run rate of the robot policy optimal against ``A`` when it
plays with ``T``, divided by the optimum against ``T`` (:func:`~hg_marl.agents.oracle.oracle_rate`'s
rate). The diagonal is 1; ``M[A, T] < 1`` is what a robot loses by expecting ``A``.

Where the policy is defined. ``T`` leads the table to states ``A``'s own model never
reaches, so the policy "optimal against A" must be defined there too. It is defined as
the robot that *believes* A at every state: the model is built over the states reachable
from the scenario's layouts under the robot's actions and the answers of *every* human
of the matrix (a set closed under each human's dynamics), ``A``'s semi-MDP is solved on
that whole set (the oracle's value iteration: expected seconds to the next success), and
``pi_A(s)`` is the action minimising ``A``'s expected time from ``s``. This is exact and
does not depend on which other humans are in the matrix: ``A``'s values at ``s`` depend
only on the states reachable from ``s`` under ``A``, a subset closed under ``A``. Ties
(actions within :data:`TIE` seconds of the best) go to the lowest action index, the
oracle robot's rule; where no action completes with certainty under ``A`` the lowest
index among the robot's options is taken.

Evaluation. ``pi_A`` against ``T`` is a Markov chain on the same set; the states from
which it completes with probability 1 are found by graph search (others: infinite time),
and the expected seconds to the next success are the solution of the sparse linear
system ``(I - P) V = c`` on them (no iteration tolerance). By the renewal-reward argument
of :mod:`hg_marl.agents.oracle`, the rate is ``3600 / E[tau + V(s')]`` over the re-drawn
tables and ``T``'s first answer.

The *adaptation headroom* of a scenario for a set of held-out partners is ``1 - IQM``
over them of ``M[cooperative, T]`` (the cooperative model is the one the fixed-model
planner plans with). No symmetry reduction is used (population members are not
equivariant), so the model is the full one: keep scenarios small (see
``hg-marl headroom --help``).
"""

from __future__ import annotations

import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from tqdm import tqdm

from hg_marl.agents.models import AnswerTable, Model, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.chains import Chain, certain_states, policy_rate, reached_rate, transitions
from hg_marl.agents.models.forked import Forked
from hg_marl.agents.models.solve import TIE, sweeps
from hg_marl.agents.oracle import (
    DEFAULT_MEMORY,
    DEFAULT_SECONDS,
    Budget,
    OracleTooLarge,
    layout_distribution,
)
from hg_marl.core import Agent, Scenario, State, World
from hg_marl.core.cycle import cycle_length
from hg_marl.core.errors import HumanError
from hg_marl.core.scenario import layout_count

COOPERATIVE = "cooperative"
"""The assumed partner of the headroom number: the model the fixed-model planner plans with."""


@dataclass
class _Dynamics:
    """One human's transitions on the joint model (pairs as in the oracle)."""

    t_pair: list[int] = field(default_factory=list)
    t_next: list[int] = field(default_factory=list)
    t_prob: list[float] = field(default_factory=list)
    t_tau: list[float] = field(default_factory=list)
    regen: list[tuple[int, float, float]] = field(default_factory=list)
    """(state id, probability, cycle seconds) of the cycle that re-draws the table."""


class JointModel:
    """Robot-turn states closed under the robot's options and every given human's answers.

    Args:
        world: the world.
        humans: stationary humans (instances with ``distribution``), in matrix order.
        failed_actions: model the deliberately infeasible robot action (as the oracle).
        max_states: refuse beyond this many states.
        budget: wall-time and memory budget.
        progress: show a progress bar on stderr.
    """

    def __init__(
        self,
        world: World,
        humans: Sequence[Any],
        failed_actions: bool = True,
        max_states: int = 1_500_000,
        budget: Budget | None = None,
        progress: bool = False,
    ) -> None:
        self.world, self.humans = world, list(humans)
        self.failed_actions, self.max_states = failed_actions, max_states
        self.budget = budget or Budget(None, None, None)
        self.index: dict[State, int] = {}
        self.states: list[State] = []
        self.pair_start: list[int] = []
        self.pair_action: list[int] = []
        self.pair_terminal: list[bool] = []
        self.dynamics = [_Dynamics() for _ in self.humans]
        self.model: Model | None = None
        """Set by :meth:`from_model`; the Python enumeration keeps lists in ``dynamics``."""
        self.budget.refuse_count("layouts", layout_count(world.scenario), "initial layouts")
        layouts = layout_distribution(world, self.budget)
        table = world.table
        wait = table.wait[Agent.ROBOT]
        for dyn, human in zip(self.dynamics, self.humans, strict=True):
            seen = wait if getattr(human, "uses_robot_action", False) else -1
            for n, (state, q) in enumerate(layouts):  # a planner-driven human answers each with a search
                self.budget.check("first answers", n, len(layouts), "layouts", memory=n % 2048 == 0)
                for h, p in human.distribution(world, state, seen):
                    if p > 0.0:
                        nxt, _, d = table.successor(state, Agent.HUMAN, h)
                        dyn.regen.append((self._id(nxt), q * p, cycle_length(world.durations.wait, d)))
        for state, _ in layouts:
            self._id(state)
        self._explore(progress)

    def _id(self, state: State) -> int:
        k = self.index.get(state)
        if k is None:
            if len(self.states) >= self.max_states:
                raise OracleTooLarge(
                    f"the headroom model of {self.world.scenario.name!r} exceeds max_states={self.max_states} "
                    "states; use a smaller scenario or fewer humans"
                )
            k = self.index[state] = len(self.states)
            self.states.append(state)
        return k

    def _options(self, state: State) -> list[int]:
        feasible = self.world.feasible_indices(state, Agent.ROBOT)
        if self.failed_actions:
            taken = set(feasible)
            failing = next((i for i in range(self.world.n_actions(Agent.ROBOT)) if i not in taken), None)
            if failing is not None:
                feasible.append(failing)
        return feasible

    def _explore(self, progress: bool) -> None:
        table = self.world.table
        bar = tqdm(
            desc=f"headroom {self.world.scenario.name}: states",
            unit=" states",
            disable=not progress,
            file=sys.stderr,
            leave=False,
        )
        k = 0
        try:
            while k < len(self.states):
                self.budget.check("explore", k, unit="states explored", memory=k % 2048 == 0)
                if k % 64 == 0:
                    bar.update(k - bar.n)
                state = self.states[k]
                self.pair_start.append(len(self.pair_action))
                for a in self._options(state):
                    pair = len(self.pair_action)
                    self.pair_action.append(a)
                    mid, ok, d_robot = table.successor(state, Agent.ROBOT, a)
                    terminal = ok and table.solves(state, Agent.ROBOT, a)
                    self.pair_terminal.append(terminal)
                    if terminal:
                        continue
                    for dyn, human in zip(self.dynamics, self.humans, strict=True):
                        seen = a if ok and getattr(human, "uses_robot_action", False) else -1
                        for h, p in human.distribution(self.world, mid, seen):
                            if p > 0.0:
                                nxt, _, d_human = table.successor(mid, Agent.HUMAN, h)
                                dyn.t_pair.append(pair)
                                dyn.t_next.append(self._id(nxt))
                                dyn.t_prob.append(p)
                                dyn.t_tau.append(cycle_length(d_robot, d_human))
                k += 1
            bar.update(k - bar.n)
        finally:
            bar.close()
        self.n = len(self.states)
        self.n_pairs = len(self.pair_action)
        self.starts = np.array(self.pair_start, dtype=np.int64)
        self.pair_state = np.repeat(np.arange(self.n), np.diff([*self.pair_start, self.n_pairs]))
        self.terminal = np.array(self.pair_terminal, dtype=bool)
        self.actions = np.array(self.pair_action, dtype=np.int64)

    @classmethod
    def from_model(cls, world: World, model: Model, budget: Budget | None = None) -> JointModel:
        """The joint model read from the array builder's :class:`~hg_marl.agents.models.Model`."""
        self = cls.__new__(cls)
        self.world, self.budget = world, budget or Budget(None, None, None)
        self.n, self.n_pairs = model.n, model.n_pairs
        self.starts = model.pair_start[:-1]
        self.pair_state = model.pair_state()
        self.terminal = model.pair_terminal
        self.actions = model.pair_action
        self.model = model
        return self

    def chain(self, i: int) -> Chain:
        """Human ``i``'s transitions as CSR rows per pair (:class:`~hg_marl.agents.models.chains.Chain`)."""
        if self.model is not None:
            return self.model.chain(i)
        d = self.dynamics[i]  # the Python enumeration appends transitions in pair order
        regen = np.array(d.regen, dtype=float).reshape(-1, 3)
        t_pair = np.array(d.t_pair, dtype=np.int64)
        return Chain(
            np.concatenate([[0], np.cumsum(np.bincount(t_pair, minlength=self.n_pairs))]).astype(np.int64),
            np.array(d.t_next, dtype=np.int64),
            np.array(d.t_prob, dtype=float),
            np.array(d.t_tau, dtype=float),
            regen[:, 0].astype(np.int64),
            regen[:, 1].copy(),
            regen[:, 2].copy(),
        )

    def arrays(self, i: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Human ``i``'s transitions as arrays: pair, next state, probability, seconds."""
        c = self.chain(i)
        return np.repeat(np.arange(self.n_pairs), np.diff(c.t_start)), c.t_next, c.t_prob, c.t_tau

    def optimal_policy(self, i: int, tolerance: float = 1e-9, max_iterations: int = 200_000) -> np.ndarray:
        """The pair index chosen at every state by the policy optimal against human ``i``.

        Value iteration from 0 with self-loops solved in closed form (the oracle's sweeps,
        :mod:`hg_marl.agents.models.solve`); the policy is greedy on the plain operator's
        ``q`` from the converged values. Each product sums a pair's transitions in their
        order (one CSR product), so the Python joint model gets the same floats.
        """
        chain = self.chain(i)
        n = self.n
        # each pair's sum in transition order from 0, as the CSR product of the sweeps adds
        cost = np.bincount(chain.t_pair, weights=chain.t_prob * chain.t_tau, minlength=self.n_pairs)
        alive, ok = certain_states(n, self.pair_state, self.terminal, chain)
        matrix = transitions(chain, n)

        def q_of(v: np.ndarray) -> np.ndarray:
            q = matrix @ np.where(alive, v, 0.0)
            q += cost
            return np.where(ok, np.where(self.terminal, 0.0, q), np.inf)

        values, _, _ = sweeps(
            self.pair_state,
            chain.t_start,
            chain.t_next,
            chain.t_prob,
            cost,
            self.terminal,
            alive,
            ok,
            self.starts,
            tolerance=tolerance,
            max_iterations=max_iterations,
            budget=self.budget,
            t_pair=chain.t_pair,
        )  # the oracle's sweeps (agents/models/solve.py): self-loops in closed form
        q = q_of(values)
        best = np.minimum.reduceat(q, self.starts)
        tied = (q <= best[self.pair_state] + TIE) | ~np.isfinite(best[self.pair_state])  # nothing certain: all tied
        key = np.where(tied, self.actions, np.iinfo(np.int64).max)
        lowest = np.minimum.reduceat(key, self.starts)
        mask = tied & (self.actions == lowest[self.pair_state])  # a state's actions are distinct
        choice = np.full(n, -1, dtype=np.int64)
        choice[self.pair_state[mask]] = np.flatnonzero(mask)
        return choice

    def rate(self, choice: np.ndarray, i: int) -> float:
        """Exact tasks per hour of the policy ``choice`` (a pair per state) against human ``i``."""
        if self.model is not None:  # only the chosen pairs' transitions from the states reached are read
            model = self.model
            chain = Chain(*([np.zeros(0)] * 4), *model.regen(i))
            return reached_rate(chain, self.terminal[choice], lambda states: model.gather(i, choice[states]))
        chain = self.chain(i)
        lo, size = chain.t_start[choice], np.diff(chain.t_start)[choice]
        at = np.repeat(lo - np.concatenate([[0], np.cumsum(size)[:-1]]), size) + np.arange(size.sum())
        starts = np.concatenate([[0], np.cumsum(size)])
        return policy_rate(chain, self.terminal[choice], (starts, chain.t_next[at], chain.t_prob[at], chain.t_tau[at]))


@dataclass(frozen=True)
class HeadroomResult:
    """The matrix ``ratio[A][T]`` and the rates it is made of."""

    scenario: str
    assumed: tuple[str, ...]
    """Row labels: the partners the robot's policy is optimal against."""
    true: tuple[str, ...]
    """Column labels: the partners it plays with."""
    rates: np.ndarray
    """``rates[a, t]``: tasks per hour of ``pi_assumed[a]`` against ``true[t]``."""
    optimum: np.ndarray
    """``optimum[t]``: the optimal tasks per hour against ``true[t]``."""
    held_out: tuple[str, ...]
    """The columns the headroom number is taken over."""
    n_states: int
    seconds: float

    @property
    def ratio(self) -> np.ndarray:
        """``rates / optimum`` (NaN where the optimum is 0: no robot completes with that partner)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(self.optimum > 0, self.rates / np.where(self.optimum > 0, self.optimum, 1.0), np.nan)

    @property
    def headroom(self) -> float:
        """``1 - IQM`` over the held-out columns of the cooperative row (NaN if none is defined)."""
        from scipy.stats import trim_mean

        row = self.ratio[self.assumed.index(COOPERATIVE)]
        values = [row[self.true.index(h)] for h in self.held_out]
        values = [v for v in values if not np.isnan(v)]
        return float("nan") if not values else 1.0 - float(trim_mean(np.array(values), 0.25))  # rliable's IQM


def headroom(
    scenario: str | Scenario | World,
    true: Sequence[tuple[str, str]],
    held_out: Sequence[str] | None = None,
    *,
    assumed: Sequence[tuple[str, str]] = (),
    failed_actions: bool = True,
    max_states: int = 1_500_000,
    max_seconds: float | None = DEFAULT_SECONDS,
    max_memory: int | None = DEFAULT_MEMORY,
    progress: bool = False,
    jobs: int = 1,
    started: float | None = None,
) -> HeadroomResult:
    """The headroom matrix of ``scenario``.

    Args:
        scenario: scenario name / path / Scenario / World.
        true: (label, human spec) of the true partners (the columns).
        held_out: labels of the columns the headroom number is taken over (default: all).
        assumed: extra (label, spec) rows; the cooperative model and every true partner
            are always rows (cooperative first).
        failed_actions: as :func:`~hg_marl.agents.oracle.oracle_rate`.
        max_states, max_seconds, max_memory: the model's budget (:class:`OracleTooLarge` beyond).
        progress: progress bars on stderr.
        jobs: worker processes (0: one per CPU) for the live partners' answers, the policies
            and the rates (:class:`~hg_marl.agents.models.forked.Forked`); the result does not
            depend on it. The memory budget counts this process and what each worker holds on its own.
        started: when ``max_seconds`` began, on :func:`time.perf_counter`'s scale (default:
            now); the command passes its process's start
            (:func:`~hg_marl.agents.models.budget.process_start`).

    Raises:
        HumanError: a label names two specs (``cooperative`` is the cooperative model's label).
    """
    start = time.perf_counter()
    world = scenario if isinstance(scenario, World) else World(scenario)
    rows: dict[str, str] = {COOPERATIVE: COOPERATIVE}
    for label, spec in [*assumed, *true]:
        # one label, one partner: a second spec under a label would be played as the first
        if rows.setdefault(label, spec) != spec:
            raise HumanError(
                f"headroom: the label {label!r} names two partners ({rows[label]!r} and {spec!r}); "
                "give each its own label"
            )
    labels = list(rows)
    humans = [stationary_human(rows[label], world) for label in labels]
    budget = Budget(
        max_seconds,
        max_memory,
        max_states,
        subject=f"the headroom model of {world.scenario.name!r}",
        hint="use a smaller scenario or fewer humans",
        start=start if started is None else started,
    )
    with budget.deadline():
        budget.refuse_count("layouts", layout_count(world.scenario), "initial layouts")
        layouts = layout_distribution(world, budget)
        packer = StatePacker(world)
        tables = [AnswerTable(world, h, packer, budget, jobs=jobs) for h in humans]
        try:
            built = build_model(
                world,
                tables,
                layouts,
                failed_actions=failed_actions,
                budget=budget,
                progress=progress,
                label="headroom",
                keep=False,  # 21 partners' transitions would not fit: each is read from its answer table
            )
        finally:
            for table in tables:
                table.close()
        model = JointModel.from_model(world, built, budget)
        col = [labels.index(label) for label, _ in true]
        assumed_rows = [labels.index(label) for label in rows]
        bar = tqdm(total=len(rows) + len(col), desc="headroom: policies, rates", disable=not progress, file=sys.stderr)

        def step(phase: str, unit: str, done: int, total: int) -> None:
            budget.check(phase, done, total, unit)
            bar.update(min(done, 1))  # the first call comes before any result

        with Forked(model.optimal_policy, jobs) as workers:  # a policy per row (forked workers share the model)
            policies = workers.map(assumed_rows, lambda done: step("policies", "policies", done, len(rows)))
        with Forked(lambda j: [model.rate(p, j) for p in policies], jobs) as workers:
            # partner by partner: its table's positions are read once (Model.gather)
            by_column = workers.map(col, lambda done: step("rates", "partners", done, len(col)))
        bar.close()
        rates = np.array(by_column, dtype=float).T.reshape(len(rows), len(col))
        optimum = np.array([rates[list(rows).index(label), t] for t, (label, _) in enumerate(true)])
    return HeadroomResult(
        scenario=world.scenario.name,
        assumed=tuple(rows),
        true=tuple(label for label, _ in true),
        rates=rates,
        optimum=optimum,
        held_out=tuple(held_out) if held_out is not None else tuple(label for label, _ in true),
        n_states=model.n,
        seconds=time.perf_counter() - start,
    )
