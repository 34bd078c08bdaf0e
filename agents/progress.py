"""The one progress guard every planning robot obeys: no robot repeats a move that changes nothing.

The project's rule is that no robot may stall on a partner who leaves the task solvable.
Each robot's own expert can be wrong about its partner in a way it never notices: the
planner expects the human to take an offer, the belief robot's member accepts offers
with probability 0.4 (so every refusal stays "explained"), the oracle's policy is off its
model. What all of those stalls share is observable without any model: **the state at the
robot's turn is the state at its previous turn**. The robot's move and the partner's
answer together left the table, the robot and the pending offer exactly as they were: a
``wait`` answered by a wait, a refused ``give`` (the offer lapses), a failed action. So
the guard counts that and nothing else.

The rule (one rule, a scalar form :class:`ProgressGuard` for the live robots and an
array form :class:`ArrayProgressGuard` for the compiled robot in the human's batched
seat; ``tests/agents/test_progress.py`` checks that both choose alike; the robots that
use it: ``planner``, ``hybrid``, ``belief``, ``memory`` and the ``oracle`` off its model):

- ``unchanged`` counts the consecutive robot turns at which the state equals the state
  at the previous robot turn; any change zeroes it; a new run starts at 0.
- When ``unchanged >= K`` the robot does not play its expert's move: it takes the
  ``(m mod n)``-th feasible non-``wait`` action in index order (in the robot's own order of
  preference when it ranks its actions: the ``memory`` robot's policy), where ``n`` is the number
  of such actions and ``m`` the guard moves it took since the run started (so a stall that
  comes back tries the next move, and a guard move that itself changes nothing is followed
  by the next option at once); ``wait`` only when nothing else is feasible. A feasible
  move other than ``wait`` changes what the partner reacts to (the robot moves, picks,
  throws, offers or takes), which is what a partner who reacts to the state needs.
- So a robot repeats a move that changes nothing at most ``K`` times in a row.

Deterministic on purpose: the guard draws no random number, so a robot whose guard never
fires (the paper's planner and hybrid against the paper's cooperative human, measured in
``docs/adaptation.md``) keeps its random stream and its published trajectory.

``K`` = :data:`PROGRESS_AFTER` = 12, measured (``docs/adaptation.md``): the longest run of
unchanged robot turns in the whole paper reproduction (``hg-marl reproduce``, 10 seeds and
the adaptation experiment) is 10 turns, in the paper's random mix against the cooperative
human (the habit's infeasible proposals meet the human's waits); with K = 12 the guard never
fires there, so the reproduction's table does not move (with K = 4 it fires and the random
mix gains 0.8 tasks), and against a partner who refuses every offer a stall costs 12 cycles.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from hg_marl.core import Agent, State, World

PROGRESS_AFTER = 12
"""``K``: robot turns in a row at an unchanged state after which the guard takes a move."""


def guard_option(
    world: World, state: State, taken: int, agent: Agent = Agent.ROBOT, prefer: Sequence[float] | None = None
) -> int:
    """The guard's move at ``state``: the ``(taken mod n)``-th feasible non-wait action, ``wait`` if none.

    The options are in index order, or, when the robot ranks its actions (``prefer``,
    one score per action: a learned policy's logits), best first (ties in index order):
    the same rule, with the robot's own second choice first in line. A score of ``-inf``
    takes the action out (the move the robot keeps choosing, which changed nothing),
    unless nothing else is left.
    """
    wait = world.n_actions(agent) - 1
    options = [i for i in world.feasible_indices(state, agent) if i != wait]
    if prefer is not None:
        options = [i for i in options if float(prefer[i]) > -math.inf] or options
        options.sort(key=lambda i: (-float(prefer[i]), i))
    return options[taken % len(options)] if options else wait


class ProgressGuard:
    """The scalar form: one robot seat, one run at a time.

    Args:
        after: ``K`` (module docstring).
    """

    def __init__(self, after: int = PROGRESS_AFTER) -> None:
        if isinstance(after, bool) or not isinstance(after, int) or after < 1:
            raise ValueError(f"progress guard: K must be a positive number of turns, got {after!r}")
        self.after = after
        self.reset()

    def reset(self) -> None:
        """A new run: no previous state, no guard move taken."""
        self._last: State | None = None
        self.unchanged = 0
        self.moves = 0
        """Guard moves taken in this run."""

    def observe(self, state: State) -> bool:
        """Count the robot turn at ``state``; return whether the guard fires (``unchanged >= K``)."""
        self.unchanged = self.unchanged + 1 if state == self._last else 0
        self._last = state
        return self.stalled

    @property
    def stalled(self) -> bool:
        """Whether the state has not changed for ``K`` robot turns in a row."""
        return self.unchanged >= self.after

    def move(
        self, world: World, state: State, agent: Agent = Agent.ROBOT, prefer: Sequence[float] | None = None
    ) -> int:
        """The guard's move at ``state`` (counted when it is not ``wait``); ``prefer``: :func:`guard_option`."""
        action = guard_option(world, state, self.moves, agent, prefer)
        self.moves += int(action != world.n_actions(agent) - 1)
        return action


class ArrayProgressGuard:
    """The array form: one counter per table of a batch (the compiled robot's seat).

    Rows are table indices; :meth:`reset_rows` starts tables afresh, :meth:`apply` counts
    a batch of robot turns and replaces the proposed actions where the guard fires.

    Args:
        world: the world (its robot action count and rules).
        after: ``K`` (module docstring).
    """

    def __init__(self, world: World, after: int = PROGRESS_AFTER) -> None:
        from hg_marl.envs.batched import BatchedRules

        if isinstance(after, bool) or not isinstance(after, int) or after < 1:
            raise ValueError(f"progress guard: K must be a positive number of turns, got {after!r}")
        self.after = after
        self.rules = BatchedRules(world)
        self.wait = world.n_actions(Agent.ROBOT) - 1
        n = world.n_objects
        self._where = np.zeros((0, n), dtype=np.int64)
        self._at = np.zeros(0, dtype=np.int64)
        self._offer = np.zeros((0, 2), dtype=np.int64)
        self._known = np.zeros(0, dtype=bool)
        self.unchanged = np.zeros(0, dtype=np.int64)
        """Per table, the consecutive robot turns at which the state had not changed."""
        self.moves = np.zeros(0, dtype=np.int64)
        """Per table, the guard moves taken since its reset."""
        self.fired = np.zeros(0, dtype=bool)
        """Per table, whether its last robot move was a guard move."""
        self.moves_taken = 0
        """Guard moves over all tables."""

    def grow(self, size: int) -> None:
        """Make room for tables ``0..size-1``."""
        if len(self._at) >= size:
            return
        extra = size - len(self._at)
        self._where = np.concatenate([self._where, np.zeros((extra, self._where.shape[1]), dtype=np.int64)])
        self._at = np.concatenate([self._at, np.zeros(extra, dtype=np.int64)])
        self._offer = np.concatenate([self._offer, np.zeros((extra, 2), dtype=np.int64)])
        self._known = np.concatenate([self._known, np.zeros(extra, dtype=bool)])
        self.unchanged = np.concatenate([self.unchanged, np.zeros(extra, dtype=np.int64)])
        self.moves = np.concatenate([self.moves, np.zeros(extra, dtype=np.int64)])
        self.fired = np.concatenate([self.fired, np.zeros(extra, dtype=bool)])

    def reset_rows(self, rows: np.ndarray) -> None:
        """Tables ``rows`` start afresh: no previous state, no guard move taken."""
        self.grow(int(rows.max(initial=-1)) + 1)
        self._known[rows] = False
        self.unchanged[rows] = 0
        self.moves[rows] = 0
        self.fired[rows] = False

    def apply(self, batch: object, proposed: np.ndarray) -> np.ndarray:
        """Count this batch of robot turns; ``proposed`` with the guard's move where it fires.

        ``batch`` is a :class:`~hg_marl.envs.batched.BatchState` whose ``rows`` name the tables.
        """
        from hg_marl.envs.batched import BatchState

        assert isinstance(batch, BatchState)
        rows = np.asarray(batch.rows, dtype=np.int64)
        self.grow(int(rows.max(initial=-1)) + 1)
        out = np.array(proposed, dtype=np.int64, copy=True)
        same = (
            self._known[rows]
            & (self._where[rows] == batch.where).all(axis=1)
            & (self._at[rows] == batch.robot_at)
            & (self._offer[rows, 0] == batch.offer_by)
            & (self._offer[rows, 1] == batch.offer_obj)
        )
        self.unchanged[rows] = np.where(same, self.unchanged[rows] + 1, 0)
        fire = self.unchanged[rows] >= self.after
        self.fired[rows] = fire
        if fire.any():
            sel = np.flatnonzero(fire)
            part = BatchState(batch.where[sel], batch.robot_at[sel], batch.offer_by[sel], batch.offer_obj[sel])
            options = self.rules.masks(part, Agent.ROBOT)
            options[:, self.wait] = False
            count = options.sum(axis=1)
            has = count > 0
            k = self.moves[rows[sel]] % np.maximum(count, 1)
            pick = (options & (options.cumsum(axis=1) == (k + 1)[:, None])).argmax(axis=1)
            out[sel] = np.where(has, pick, self.wait)
            self.moves[rows[sel]] += has
            self.moves_taken += int(has.sum())
        self._where[rows], self._at[rows] = batch.where, batch.robot_at
        self._offer[rows, 0], self._offer[rows, 1] = batch.offer_by, batch.offer_obj
        self._known[rows] = True
        return out
