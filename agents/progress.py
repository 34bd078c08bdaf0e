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

**Patience.** A partner may also answer only a robot that keeps still: one who helps once
the robot has waited for a while, or stayed at one place. A robot that stalls against it
changes the state at every turn (it walks between two places, or waits and then moves on
when its plan finds nothing), so the rule above never sees it. What such stalls share is
that **no object moves and no offer changes**, whatever the robot does. So the guard also
counts ``quiet``, the consecutive robot turns at which the objects' places and the pending
offer equal those at the previous robot turn (the robot's own place ignored); when
``quiet >= P`` the robot waits patiently: it plays ``wait`` until the partner has let
``W`` of its turns in a row pass without moving anything (while the partner works, the
robot keeps waiting). A spell in which the partner moved nothing doubles ``W`` for the next
one (up to :data:`PATIENCE_MAX`), so a partner who needs the robot still for any time is
met after a few spells. A spell in which it moved something shows that this partner works
when the robot keeps still: ``W`` is kept, and from then on a spell begins as soon as
nothing has moved for :data:`PATIENCE_AGAIN` turns. ``quiet`` and ``unchanged`` start again
after a spell.

Deterministic on purpose: the guard draws no random number, so a robot whose guard never
fires (the paper's planner and hybrid against the paper's cooperative human, measured in
``docs/adaptation.md``) keeps its random stream and its published trajectory.

``K`` = :data:`PROGRESS_AFTER` = 12, measured (``docs/adaptation.md``): the longest run of
unchanged robot turns in the whole paper reproduction (``hg-marl reproduce``, 10 seeds and
the adaptation experiment) is 10 turns, in the paper's random mix against the cooperative
human (the habit's infeasible proposals meet the human's waits); with K = 12 the guard never
fires there, so the reproduction's table does not move (with K = 4 it fires and the random
mix gains 0.8 tasks), and against a partner who refuses every offer a stall costs 12 cycles.

``P`` = :data:`PATIENCE_AFTER` = 200 and ``W`` = :data:`PATIENCE_WAIT` = 40 turns, measured
(``docs/adaptation.md``): the longest quiet run of the planner, hybrid and belief robots
over the four bundled scenarios, 14 partners (the family-out ones, the paper's, an idler)
and 3 seeds is 75 turns (``fo_slow_start``, who watches the robot for 120 s), and in the reproduction's
adaptation experiment 143 (the 300 s in which the adversarial human hides what it can, in
``adversarial_and_back``), so no spell begins in any measured run and each stays as it was;
``W`` = 40 turns of ``wait`` is 40 s at the bundled durations. The price of that margin: a
partner who needs the robot still waits ``P`` quiet turns for its first chance.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from hg_marl.core import Agent, State, World

PROGRESS_AFTER = 12
"""``K``: robot turns in a row at an unchanged state after which the guard takes a move."""
PATIENCE_AFTER = 200
"""``P``: robot turns in a row with no object moved and no offer changed after which the robot waits patiently."""
PATIENCE_WAIT = 40
"""``W``'s first value: the robot's turns the partner may let pass without moving anything before a spell ends."""
PATIENCE_MAX = 8 * PATIENCE_WAIT
"""The longest ``W``: spells in which the partner moved nothing double it up to here."""
PATIENCE_AGAIN = 8
"""``P`` once a spell has seen the partner move something: it works when the robot keeps still."""


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
        """A new run: no previous state, no guard move taken, no spell of patience."""
        self._last: State | None = None
        self.unchanged = 0
        self.moves = 0
        """Guard moves taken in this run."""
        self.quiet = 0
        """Consecutive robot turns with no object moved and no offer changed."""
        self.waiting = False
        """Whether the robot is in a spell of patience."""
        self.patience = PATIENCE_WAIT
        """``W``: turns the partner may let pass without moving anything before the spell ends."""
        self.spells = 0
        """Spells of patience begun in this run."""
        self.answered = False
        """Whether a spell has seen the partner move something (then spells begin after ``PATIENCE_AGAIN``)."""
        self._still = 0
        self._helped = False

    def observe(self, state: State) -> bool:
        """Count the robot turn at ``state``; return whether the guard decides it (a spell, or ``unchanged >= K``)."""
        last = self._last
        self.unchanged = self.unchanged + 1 if state == last else 0
        moved = last is None or (state.where, state.offer_by, state.offer_obj) != (
            last.where,
            last.offer_by,
            last.offer_obj,
        )
        self.quiet = 0 if moved else self.quiet + 1
        self._last = state
        if self.waiting:
            self._helped = self._helped or moved
            self._still = 0 if moved else self._still + 1
            if self._still >= self.patience:  # the partner let W turns pass: the robot acts again
                self.answered = self.answered or self._helped
                if not self._helped:
                    self.patience = min(2 * self.patience, PATIENCE_MAX)
                self.waiting = False
                self.quiet = self.unchanged = 0
        elif self.quiet >= (PATIENCE_AGAIN if self.answered else PATIENCE_AFTER):
            self.waiting, self._still, self._helped = True, 0, False
            self.spells += 1
        return self.stalled

    @property
    def stalled(self) -> bool:
        """Whether the guard decides this turn: a spell of patience, or ``K`` unchanged robot turns in a row."""
        return self.waiting or self.unchanged >= self.after

    @property
    def reason(self) -> str:
        """What a decision of the guard's is logged with: ``patience`` or ``no_progress``."""
        return "patience" if self.waiting else "no_progress"

    def move(
        self, world: World, state: State, agent: Agent = Agent.ROBOT, prefer: Sequence[float] | None = None
    ) -> int:
        """The guard's move at ``state``: ``wait`` in a spell, else the rotation move (counted).

        ``prefer``: :func:`guard_option`.
        """
        wait = world.n_actions(agent) - 1
        if self.waiting:
            return wait
        action = guard_option(world, state, self.moves, agent, prefer)
        self.moves += int(action != wait)
        return action


_PER_TABLE: dict[str, int | bool] = {
    "_where": 0,
    "_at": 0,
    "_offer": 0,
    "_known": False,
    "unchanged": 0,
    "moves": 0,
    "fired": False,
    "quiet": 0,
    "waiting": False,
    "patience": PATIENCE_WAIT,
    "spells": 0,
    "answered": False,
    "_still": 0,
    "_helped": False,
}
"""The array guard's per-table arrays and a fresh table's value in each."""
_RESET = tuple(name for name in _PER_TABLE if name not in ("_where", "_at", "_offer"))
"""What :meth:`ArrayProgressGuard.reset_rows` sets afresh (the last state is unknown, so it is not read)."""


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
        """Per table, whether its last robot move was the guard's (a rotation move or a patient wait)."""
        self.moves_taken = 0
        """Guard rotation moves over all tables."""
        self.quiet = np.zeros(0, dtype=np.int64)
        """Per table, the consecutive robot turns with no object moved and no offer changed."""
        self.waiting = np.zeros(0, dtype=bool)
        """Per table, whether its robot is in a spell of patience."""
        self.patience = np.zeros(0, dtype=np.int64)
        """Per table, ``W``."""
        self.spells = np.zeros(0, dtype=np.int64)
        """Per table, the spells of patience begun since its reset."""
        self.answered = np.zeros(0, dtype=bool)
        """Per table, whether a spell has seen the partner move something."""
        self._still = np.zeros(0, dtype=np.int64)
        self._helped = np.zeros(0, dtype=bool)

    def grow(self, size: int) -> None:
        """Make room for tables ``0..size-1``, each as :meth:`reset_rows` leaves it."""
        extra = size - len(self._at)
        if extra <= 0:
            return
        for name, fresh in _PER_TABLE.items():
            have = getattr(self, name)
            setattr(self, name, np.concatenate([have, np.full((extra, *have.shape[1:]), fresh, dtype=have.dtype)]))

    def reset_rows(self, rows: np.ndarray) -> None:
        """Tables ``rows`` start afresh: no previous state, no guard move taken, no spell of patience."""
        self.grow(int(rows.max(initial=-1)) + 1)
        for name in _RESET:
            getattr(self, name)[rows] = _PER_TABLE[name]

    def apply(self, batch: object, proposed: np.ndarray) -> np.ndarray:
        """Count this batch of robot turns; ``proposed`` with the guard's move where it fires.

        ``batch`` is a :class:`~hg_marl.envs.batched.BatchState` whose ``rows`` name the tables.
        """
        from hg_marl.envs.batched import BatchState

        assert isinstance(batch, BatchState)
        rows = np.asarray(batch.rows, dtype=np.int64)
        self.grow(int(rows.max(initial=-1)) + 1)
        out = np.array(proposed, dtype=np.int64, copy=True)
        still = (
            self._known[rows]
            & (self._where[rows] == batch.where).all(axis=1)
            & (self._offer[rows, 0] == batch.offer_by)
            & (self._offer[rows, 1] == batch.offer_obj)
        )
        same = still & (self._at[rows] == batch.robot_at)
        self.unchanged[rows] = np.where(same, self.unchanged[rows] + 1, 0)
        self.quiet[rows] = np.where(still, self.quiet[rows] + 1, 0)
        # spells of patience, as ProgressGuard.observe: the partner's stillness ends one
        waiting = self.waiting[rows]
        self._helped[rows] |= waiting & ~still
        self._still[rows] = np.where(waiting, np.where(still, self._still[rows] + 1, 0), self._still[rows])
        end = waiting & (self._still[rows] >= self.patience[rows])
        helped = self._helped[rows]
        self.answered[rows] |= end & helped
        doubled = np.minimum(2 * self.patience[rows], PATIENCE_MAX)
        self.patience[rows] = np.where(end & ~helped, doubled, self.patience[rows])
        self.quiet[rows] = np.where(end, 0, self.quiet[rows])
        self.unchanged[rows] = np.where(end, 0, self.unchanged[rows])
        after = np.where(self.answered[rows], PATIENCE_AGAIN, PATIENCE_AFTER)
        begin = ~waiting & (self.quiet[rows] >= after)
        waiting = (waiting & ~end) | begin
        self.waiting[rows] = waiting
        self._still[rows] = np.where(begin, 0, self._still[rows])
        self._helped[rows] &= ~begin
        self.spells[rows] += begin
        out[waiting] = self.wait
        fire = ~waiting & (self.unchanged[rows] >= self.after)
        self.fired[rows] = fire | waiting
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
