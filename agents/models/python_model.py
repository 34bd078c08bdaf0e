"""The oracle's model enumerated one Python state at a time: the reference the array builder is tested against.

``oracle_rate`` builds its model with :func:`~hg_marl.agents.models.build_model`. This
enumeration (a dict of states, a list per transition field) is the simpler
implementation the tests compare the array builder with (same states, transitions and
rates), and :meth:`PythonModel.replies` is the belief robot's one-step backup through a
member's answers.
"""

from __future__ import annotations

import sys
from typing import Any

import numpy as np
from tqdm import tqdm

from hg_marl.agents.models.budget import Budget, OverBudget
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, State, World
from hg_marl.core.cycle import cycle_length


class PythonModel:
    """The explored semi-MDP, one Python state at a time: the reference the array builder is tested against.

    ``oracle_rate`` builds its model with :func:`~hg_marl.agents.models.build_model`; this
    enumeration stays as the simpler implementation the tests compare it with, and for
    :meth:`replies` (the belief robot's one-step backups).
    """

    def __init__(
        self,
        world: World,
        human: Any,
        failed_actions: bool,
        max_states: int,
        progress: bool = False,
        relabel: Relabel | None = None,
        budget: Budget | None = None,
    ) -> None:
        self.world, self.human = world, human
        self.relabel = relabel
        """Set when states are kept in canonical order (an equivariant human)."""
        self.budget = budget or Budget(None, None, None)
        self.progress = progress
        self.failed_actions, self.max_states = failed_actions, max_states
        self.robot_acts, self.human_acts = world.actions(Agent.ROBOT), world.actions(Agent.HUMAN)
        self.index: dict[State, int] = {}
        self.states: list[State] = []
        self.pair_start: list[int] = []
        self.pair_action: list[int] = []
        self.pair_terminal: list[bool] = []
        self.t_pair: list[int] = []
        self.t_next: list[int] = []
        self.t_prob: list[float] = []
        self.t_tau: list[float] = []
        self._answers: dict[tuple[State, int], list[tuple[int, float, float]]] = {}
        """The human's answers at a (mid-cycle state, robot action seen), as (next state's id,
        duration, probability): a mid-cycle state recurs from many robot-turn states, and the
        ids point at states the index holds anyway, so nothing is stored twice."""
        self._uses_robot_action = bool(getattr(human, "uses_robot_action", False))

    def canonical(self, state: State) -> State:
        """The state the model keeps for ``state`` (itself without symmetry reduction)."""
        return state if self.relabel is None else self.relabel.canonical(state)[0]

    def _id(self, state: State) -> int:
        if self.relabel is not None:
            state = self.relabel.canonical(state)[0]
        k = self.index.get(state)
        if k is None:
            if len(self.states) >= self.max_states:
                raise OverBudget(
                    f"the oracle's model of {self.world.scenario.name!r} exceeds max_states={self.max_states} "
                    f"robot-turn states ({self.world.n_objects} objects); raise max_states (memory and minutes "
                    "grow with it) or use a smaller scenario"
                )
            k = self.index[state] = len(self.states)
            self.states.append(state)
        return k

    def replies(self, mid: State, d_robot: float, robot_action: int) -> list[tuple[State, float, float]]:
        """The human's answers at ``mid``: (next robot-turn state, probability, cycle seconds).

        ``robot_action`` is the robot's action of the cycle if it succeeded, else -1: what
        the human sees in the environment (``base.robot_action_of``).
        """
        seen = robot_action if self._uses_robot_action else -1
        out = []
        for h, p in self.human.distribution(self.world, mid, seen):
            if p > 0.0:
                nxt, _, duration = self.world.table.successor(mid, Agent.HUMAN, h)
                out.append((nxt, p, cycle_length(d_robot, duration)))
        return out

    def _answer_ids(self, mid: State, robot_action: int) -> list[tuple[int, float, float]]:
        """:meth:`replies` without the cycle's robot part, as state ids, memoised (the explore loop's)."""
        key = (mid, robot_action if self._uses_robot_action else -1)
        answers = self._answers.get(key)
        if answers is None:
            answers = self._answers[key] = [(self._id(nxt), tau, p) for nxt, p, tau in self.replies(mid, 0.0, key[1])]
        return answers

    def robot_options(self, state: State) -> list[int]:
        """The feasible robot actions, plus the first infeasible one standing for them all (``failed_actions``)."""
        feasible = self.world.feasible_indices(state, Agent.ROBOT)
        if self.failed_actions:
            taken = set(feasible)
            failing = next((i for i in range(len(self.robot_acts)) if i not in taken), None)
            if failing is not None:
                feasible.append(failing)
        return feasible

    def build(self, roots: list[State]) -> None:
        for root in roots:
            self._id(root)
        bar = tqdm(
            desc=f"oracle {self.world.scenario.name}: states",
            unit=" states",
            disable=not self.progress,
            file=sys.stderr,
            dynamic_ncols=True,
            leave=False,  # transient: the result (or a refusal) is the one line that stays
        )
        try:
            self._explore(bar)
            bar.update(len(self.states) - bar.n)  # the last, partial block of states
            bar.set_postfix(known=len(self.states))
        finally:
            bar.close()

    def _explore(self, bar: tqdm) -> None:
        """Breadth-first over robot-turn states; the bar shows states explored and known."""
        table = self.world.table
        k = 0
        while k < len(self.states):
            # a state may cost planner searches: the clock is read at every one
            self.budget.check("explore", k, unit="states explored", memory=k % 2048 == 0)
            if k % 2048 == 0:
                bar.update(k - bar.n)
                bar.set_postfix(known=len(self.states), refresh=False)
            state = self.states[k]
            self.pair_start.append(len(self.pair_action))
            for a in self.robot_options(state):
                pair = len(self.pair_action)
                self.pair_action.append(a)
                mid, ok, duration = table.successor(state, Agent.ROBOT, a)
                terminal = ok and table.solves(state, Agent.ROBOT, a)  # the completing wait
                self.pair_terminal.append(terminal)
                if terminal:
                    continue
                for nxt, d_human, p in self._answer_ids(mid, a if ok else -1):
                    self.t_pair.append(pair)
                    self.t_next.append(nxt)
                    self.t_prob.append(p)
                    self.t_tau.append(duration if duration > d_human else d_human)
            k += 1


def certain_states(
    n: int, pair_state: np.ndarray, terminal: np.ndarray, t_pair: np.ndarray, t_next: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """States from which some policy completes with probability 1, and the pairs it may use."""
    n_pairs = len(terminal)
    alive = np.ones(n, dtype=bool)
    while True:
        leaks = np.bincount(t_pair, weights=~alive[t_next], minlength=n_pairs) > 0
        ok = terminal | ~leaks
        reach = np.zeros(n, dtype=bool)
        reach[pair_state[ok & terminal]] = True
        while True:
            hits = np.bincount(t_pair, weights=reach[t_next], minlength=n_pairs) > 0
            grown = reach.copy()
            grown[pair_state[ok & hits]] = True
            if (grown == reach).all():
                break
            reach = grown
        if (reach == alive).all():
            return alive, ok
        alive = reach
