"""The partner's own answers where it has answered, a member's elsewhere: a model solved exactly.

Why. The learned partner (:mod:`~hg_marl.agents.partner_model`) counts the *kind* of the
partner's answers in a few abstract contexts: it can say "this partner never takes", not
"this partner clears the objects from the last one down" or "this partner stops when the
robot stops". Such habits are a function of the state (and of the robot's move under way),
so on a table whose states recur, the partner's answer at each (state, robot move) it has
been seen at is the best predictor of its next answer there. This model keeps those
answers (certainty-equivalent model-based learning, as in R-max or Dyna without the
exploration bonus), answers like a *base* partner where the partner was never seen (the
belief's most probable member, so that what the family knows is kept), and is small
enough on the bundled small tables to be solved exactly, like the members
(:func:`~hg_marl.agents.oracle.oracle_rate`); on ``roboergosum`` (members of 86,000 to
530,000 states) it is not solved, and the robot plans as the planner does.

The model:

- **Counts** per (mid-cycle state, robot action seen), each key's counts multiplied by
  ``forget`` at each of its observations (a partner who changes is followed within a few
  visits of each state).
- **Pauses**: a wait at a key where the partner has done something else is a pause, not
  an answer, and is not counted (:meth:`ObservedPartner.update`): a partner who rests is
  back with the habits it had.
- **Predictive** at a seen key: ``p(a) = (n_a + weight * base(a)) / (N + weight)``; at an
  unseen key: the base's answer. With ``weight`` 0.5 one answer seen gives it 2/3 of the
  mass, two the same answers 1.8/2.3, about 0.78 (the first counts 0.8 once forgotten);
  the base's answers share the rest.
- **Surprises**: an answer the model gave less than half its mass before seeing it. The
  exact solution changes only where the model does, so :attr:`version` counts surprises
  and :class:`ObservedSolver` solves again only after one (see there).
- **Stationary or not**: a partner whose answers follow a clock or its own history
  answers the same state differently from one visit to the next; once a tenth of the
  recent repeats contradict the earlier answers there, the model is not planned with
  (:meth:`ObservedPartner.stationary`).
- **Solved without failed moves**: where the partner was never seen after a failed move,
  it answers as the base does, so a failed move would "work" in the model where a wait
  does not; the robot plans feasible moves only (``failed_actions=False``).

:meth:`ObservedPartner.predict`-then-:meth:`~ObservedPartner.update` is a prequential
likelihood, so the model competes with the members in the belief's posterior
(``belief:open_world=observed``) exactly as the learned partner does.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from hg_marl.agents.humans.base import Distribution, StationaryHuman
from hg_marl.agents.member_models import Replies, backup, expand
from hg_marl.agents.models.budget import OverBudget
from hg_marl.agents.models.builder import Dynamics, Model
from hg_marl.agents.models.packing import StatePacker
from hg_marl.agents.models.python_model import PythonModel
from hg_marl.agents.models.solve import solve
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, State, World

Key = tuple[State, int]

WEIGHT = 0.5
"""Pseudo-count of the base partner's answer at a key the partner was seen at."""
FORGET = 0.8
"""Weight a key's earlier counts keep at each of its observations."""


def prior(base: Any, world: World, state: State, robot_action: int) -> Distribution:
    """The base's answer at (``state``, ``robot_action``); ``base`` None: uniform over the feasible answers."""
    if base is None:
        feasible = world.feasible_indices(state, Agent.HUMAN)
        return [(i, 1.0 / len(feasible)) for i in feasible]
    return list(base.distribution(world, state, robot_action))  # a base that does not look ignores it


def answer(
    base: Any, counts: Mapping[Key, Mapping[int, float]], weight: float, world: World, state: State, robot_action: int
) -> Distribution:
    """The predictive at (``state``, ``robot_action``): its counts with ``weight`` pseudo-counts spread as
    the base's :func:`prior` there."""
    base_answer = prior(base, world, state, robot_action)
    seen = counts.get((state, robot_action))
    if not seen:
        return base_answer
    total = sum(seen.values()) + weight
    out = {a: weight * p for a, p in base_answer}
    for a, n in seen.items():
        out[a] = out.get(a, 0.0) + n
    return [(a, v / total) for a, v in out.items()]


class ObservedPartner:
    """Per (mid-cycle state, robot action seen) counts of the partner's answers over a base partner.

    Args:
        weight: pseudo-count of the base's answer at a seen key (> 0).
        forget: weight a key's earlier counts keep at each of its observations, in (0, 1].
    """

    name = "observed"
    uses_robot_action = True

    def __init__(self, weight: float = WEIGHT, forget: float = FORGET) -> None:
        if not (math.isfinite(weight) and weight > 0):
            raise ValueError(f"observed partner: weight must be > 0, got {weight!r}")
        if not (math.isfinite(forget) and 0 < forget <= 1):
            raise ValueError(f"observed partner: forget must be in (0, 1], got {forget!r}")
        self.weight, self.forget = float(weight), float(forget)
        self.base: Any = None
        """The partner answering where this one was never seen (None: uniform over the feasible answers)."""
        self.reset()

    def reset(self) -> None:
        """Forget every answer (a new run)."""
        self.counts: dict[Key, dict[int, float]] = {}
        self.version = 0
        """Surprises so far: the model changed where it mattered (see the module docstring)."""
        self.surprised: dict[Key, int] = {}
        """Per key, the :attr:`version` its last surprise made."""
        self.observations = 0
        self.touched: dict[Key, int] = {}
        """Per key, the number of :attr:`observations` when it was last counted (its answers
        may have changed then: the solver expands again the states that read it)."""
        self.repeats = 0.0
        self.contradictions = 0.0
        """Answers at keys answered before, and those of them most earlier answers there
        contradict (each weighted by :data:`REPEATS_KEPT` per later one)."""

    def stationary(self) -> bool:
        """Whether the partner answers as it answered before where it answered before.

        A partner whose answers follow a clock or its own history (it works in bursts, it
        watches before joining in) answers the same state differently from one visit to
        the next: the model's certainty there is false, and a solution planned on it plans
        for a partner who is not there. :data:`CONTRADICTED` or more of the recent repeats
        contradicted means the model is not planned with.
        """
        return self.contradictions < CONTRADICTED * max(self.repeats, MIN_REPEATS)

    def seen_at(self, world: World, state: State) -> bool:
        """Whether the partner has answered one of the robot's feasible moves at ``state``.

        Where it has not, the model answers as its base does, a member that explains this
        partner worse than the model (or the robot would not be planning with the model): a
        best response there is a guess, and the robot plans as the planner does
        (:class:`~hg_marl.agents.robots.belief.BeliefRobot`).
        """
        for a in world.feasible_indices(state, Agent.ROBOT):
            if (world.table.successor(state, Agent.ROBOT, a)[0], a) in self.counts:
                return True
        return False

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """The predicted answer at mid-cycle ``state`` while the robot does ``robot_action``."""
        return answer(self.base, self.counts, self.weight, world, state, robot_action)

    def predict(self, world: World, state: State, robot_action: int, human_action: int) -> float:
        """Probability the model gives ``human_action`` (0 if infeasible)."""
        return dict(self.distribution(world, state, robot_action)).get(human_action, 0.0)

    def update(self, world: World, state: State, robot_action: int, human_action: int) -> None:
        """Count the answer (after :meth:`predict`, for a prequential evidence); a pause is not counted.

        A wait where the partner has done something else (at this state, to this move) is a
        pause (a rest, a look away), not its answer to the robot's move. Counted, the pauses
        of a partner who rests would teach the model that the partner no longer answers as
        it did, and once it is back the robot would plan around a partner who stops (waiting
        with an object in hand, fetching a handover). The model's answer there stays what the
        partner did; the posterior still weighs the wait (:meth:`predict` came first), so a
        member who idles can explain a partner who has stopped for good. A wait where the
        partner has only ever waited is its answer (a partner who stops when the robot stops).
        """
        counts = self.counts.setdefault((state, robot_action), {})
        wait = world.n_actions(Agent.HUMAN) - 1
        if human_action == wait and any(a != wait for a in counts):
            return  # a pause: the model, its surprises and its stationarity are unchanged
        if self.predict(world, state, robot_action, human_action) < 0.5:
            self.version += 1
            self.surprised[(state, robot_action)] = self.version
        if counts:  # an answer where the partner answered before: as before, or not
            total = sum(counts.values())
            contradicted = counts.get(human_action, 0.0) < 0.5 * total
            self.repeats = REPEATS_KEPT * self.repeats + 1.0
            self.contradictions = REPEATS_KEPT * self.contradictions + float(contradicted)
        for a in counts:
            counts[a] *= self.forget
        counts[human_action] = counts.get(human_action, 0.0) + 1.0
        self.observations += 1
        self.touched[(state, robot_action)] = self.observations

    def snapshot(self) -> ObservedSnapshot:
        """The model as it stands, frozen: a stationary human the oracle can solve.

        Where the partner was seen, the snapshot answers as it was seen (its counts alone, no
        pseudo-counts): the base's other answers there would only add states the partner
        does not go to (a model several times the base's own on the hard layouts).
        """
        return ObservedSnapshot({k: dict(v) for k, v in self.counts.items()}, self.base)


class ObservedSnapshot(StationaryHuman):
    """An :class:`ObservedPartner`'s answers as a stationary human: its counts alone where the
    partner was seen, the base's answer elsewhere (:meth:`ObservedPartner.snapshot` copies the
    counts; the solver's one-step backups read the partner's own, as they are now)."""

    name = "observed"
    uses_robot_action = True

    def __init__(self, counts: dict[Key, dict[int, float]], base: Any) -> None:
        super().__init__()
        self.counts, self.base = counts, base

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        seen = self.counts.get((state, robot_action))
        if not seen:
            return prior(self.base, world, state, robot_action)
        total = sum(seen.values())
        return [(a, n / total) for a, n in seen.items()]


REPEATS_KEPT = 0.98
"""Weight an earlier repeat keeps per later one in :meth:`ObservedPartner.stationary` (a memory of about 50)."""
CONTRADICTED = 0.1
"""Share of contradicted repeats from which the partner is not taken for stationary."""
MIN_REPEATS = 5.0
"""The share of contradicted repeats is taken over at least this many: a contradiction among
the first repeats stops the model from being planned with until about ten repeats have
agreed after it (``0.98 ** k < 0.1 * (k + 1)`` from k = 8)."""

MAX_TABLES = 256
"""Solutions kept by the table they were solved from (all dropped when more are wanted)."""

MAX_STATES = 20_000
"""Largest model the robot solves for the observed partner (states), checked against the base
member's own model before building: the small bundled tables' members have hundreds of
states, ``roboergosum``'s hundreds of thousands (there the robot plans as the planner does)."""


@dataclass(frozen=True)
class Solved:
    """The observed model's optimal expected seconds to the next success, by state (one solve)."""

    values: dict[State, float]

    @property
    def n_states(self) -> int:
        return len(self.values)

    def value_at(self, world: World, state: State, relabel: Relabel | None = None) -> float:
        """Optimal expected seconds to the next success from ``state`` (inf outside the solve)."""
        return self.values.get(state, math.inf)


class ObservedSolver:
    """The exact best response to an :class:`ObservedPartner`, solved again only when it must be.

    - **From the table in front of the robot.** A solve holds the states reachable from the
      current state until the task is solved: the value of a state, the expected seconds to
      the next success, does not depend on the tables drawn after it, and one table's
      states are fewer than every layout's. It is the oracle's model and solver
      (:func:`~hg_marl.agents.models.solve.solve`, the same values as
      ``oracle_rate(snapshot, failed_actions=False, roots=(state,))``).
    - **Expanded once, kept across solves.** A state's expansion (per feasible robot move,
      the partner's answers and where they lead: :func:`~hg_marl.agents.member_models.expand`)
      is kept until the partner's answers at one of the keys it read are counted again
      (:attr:`ObservedPartner.touched`) or the base member changes; a solve expands only the
      states new to it and those, and sweeps the values over the kept expansions. A solve is
      charged as a planner call of one node per state it expands: the values are swept over
      expansions already made, as the planner's arithmetic over its expanded nodes is not
      charged apart from them.
    - **Kept by table.** Each solution is kept under the table it was solved from and the
      :attr:`~ObservedPartner.version` it was solved at, so a table dealt again under the
      same model (no surprise since) is not solved again.
    - **Solved again only after a surprise at the current state.** A decision backs the
      solution's values up one step through the partner's answers *as observed now*
      (:meth:`ObservedPartner.snapshot`'s rule, read live). The model is solved again when
      the state is not in the solution, or when the partner surprised the model, since the
      solve, at an answer to one of this state's moves: a surprise elsewhere is used when
      the table gets there. A stationary deterministic partner surprises at most once per
      (state, move), so the solves are bounded by the states where the base was wrong and
      the tables dealt, never one per decision.
    """

    def __init__(self, max_states: int = MAX_STATES) -> None:
        self.max_states = max_states
        self.reset()

    def reset(self) -> None:
        """Forget the solution and the expansions (a new run)."""
        self.key = -1
        """The partner's :attr:`~ObservedPartner.version` the solution was solved at (-1: none yet)."""
        self.result: Solved | None = None
        self.tables: dict[State, tuple[int, Solved | None]] = {}
        """Solutions by the table they were solved from, with the version each was solved at
        (reused at that version only; None: over the limit)."""
        self.solves = 0
        """Models solved in this run."""
        self.expanded = 0
        """States expanded in this run (what the solves are charged)."""
        self.graph: dict[State, list[tuple[int, Replies | None]]] = {}
        """The kept expansions, by robot-turn state."""
        self.readers: dict[Key, set[State]] = {}
        """Per partner key (mid-cycle state, robot move), the kept states whose expansion read it."""
        self.synced = 0
        """The partner's :attr:`~ObservedPartner.observations` the expansions are up to date with."""
        self.base: Any = None
        """The base member the expansions were made with."""

    def q_values(
        self, world: World, state: State, partner: ObservedPartner, base_states: int, relabel: Relabel
    ) -> tuple[dict[int, float], int, bool]:
        """Expected seconds to the next success per feasible robot action, the states expanded
        for it, and whether the model was solved for it.

        Empty (and 0, False) when the base's own model has more than :attr:`max_states`
        states or the observed model grows past them: the caller plans otherwise.
        """
        if base_states > self.max_states or not partner.stationary():
            return {}, 0, False
        if self.result is None or state not in self.result.values:
            kept = self.tables.get(state)  # solved from this table (its root) before, under the same model?
            if kept is None or kept[0] != partner.version:
                self.result = None
            elif kept[1] is None:
                return {}, 0, False  # this table's model was over the limit under this very model
            else:
                self.key, self.result = kept
        expanded, solved = 0, False
        if self.result is None or (partner.version != self.key and self._stale(world, state, partner)):
            self.key, solved = partner.version, True
            before = self.expanded
            try:
                self.result = self._solve(world, state, partner)
            except OverBudget:
                self.result = None
                self.tables[state] = (self.key, None)  # not tried again until the model changes
                return {}, self.expanded - before, True
            if len(self.tables) >= MAX_TABLES:
                self.tables.clear()
            self.tables[state] = (self.key, self.result)
            self.solves += 1
            expanded = self.expanded - before
        live = PythonModel(world, ObservedSnapshot(partner.counts, partner.base), True, max_states=0)  # replies only
        return backup(world, state, self.result, live, relabel), expanded, solved

    def _sync(self, partner: ObservedPartner) -> None:
        """Drop the expansions that read answers counted since the last solve (all, when the base changed)."""
        if partner.base is not self.base or len(self.graph) >= self.max_states:
            self.graph.clear()
            self.readers.clear()
            self.base = partner.base
        else:
            for key, seen in partner.touched.items():
                if seen > self.synced:
                    for s in self.readers.pop(key, ()):
                        self.graph.pop(s, None)
        self.synced = partner.observations

    def _solve(self, world: World, root: State, partner: ObservedPartner) -> Solved:
        """The observed model's values from ``root`` until a success (states expanded counted in :attr:`expanded`)."""
        self._sync(partner)
        live = PythonModel(world, ObservedSnapshot(partner.counts, partner.base), True, max_states=0)
        ids, order = {root: 0}, [root]
        pair_start, pair_action, terminal = [0], [], []
        t_start: list[int] = [0]
        t_next: list[int] = []
        t_prob: list[float] = []
        t_tau: list[float] = []
        k = 0
        while k < len(order):
            state = order[k]
            k += 1
            options = self.graph.get(state)
            if options is None:
                options = self.graph[state] = expand(world, state, live)
                self.expanded += 1
                for a, replies in options:
                    if replies is not None:
                        mid = world.table.successor(state, Agent.ROBOT, a)[0]
                        self.readers.setdefault((mid, a), set()).add(state)
            for a, replies in options:
                pair_action.append(a)
                terminal.append(replies is None)
                for nxt, p, tau in replies or ():
                    j = ids.get(nxt)
                    if j is None:
                        if len(order) >= self.max_states:
                            raise OverBudget(f"the observed model exceeds {self.max_states} states")
                        j = ids[nxt] = len(order)
                        order.append(nxt)
                    t_next.append(j)
                    t_prob.append(p)
                    t_tau.append(tau)
                t_start.append(len(t_next))
            pair_start.append(len(pair_action))
        n = len(order)
        chain = Dynamics(
            np.array(t_start, dtype=np.int64),
            np.array(t_next, dtype=np.int64),
            np.array(t_prob),
            np.array(t_tau),
            # the re-draw after a success makes only the solver's rate, not read here
            regen_next=np.zeros(1, dtype=np.int64),
            regen_prob=np.ones(1),
            regen_tau=np.zeros(1),
        )
        model = Model(
            StatePacker(world),
            np.arange(n, dtype=np.int64),
            np.array(pair_start, dtype=np.int64),
            np.array(pair_action, dtype=np.int64),
            np.array(terminal, dtype=bool),
            [chain],
            n_layouts=1,
        )
        return Solved(dict(zip(order, solve(model).values.tolist(), strict=True)))

    def _stale(self, world: World, state: State, partner: ObservedPartner) -> bool:
        """Whether the partner surprised the model, since the last solve, at an answer to a move of this state."""
        for a in world.feasible_indices(state, Agent.ROBOT):  # feasible: the partner sees ``a`` done
            mid = world.table.successor(state, Agent.ROBOT, a)[0]
            if partner.surprised.get((mid, a), 0) > self.key:
                return True
        return False
