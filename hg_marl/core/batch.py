"""Many tables stepped at once on arrays: the rule table's tabulated rules, batched.

:class:`BatchedRules` reads :class:`~hg_marl.core.table.RuleTable`'s own tables (who
reaches which spot from where, where a throw lands, where a goto leads, each action's
kind, object, target and duration) as numpy arrays, and applies the preconditions and
effects that ``RuleTable.feasible`` and ``RuleTable.successor`` state to a whole batch of
states; nothing scenario-specific is computed here. The facts come from
``World.fact_lookup`` (one fancy index), the table draw from ``World.initial_states``.
A property test (``tests/env/test_batched.py``) steps it beside ``World.step`` on random
action sequences and requires identical trajectories.

It is the batched twin of :meth:`World.step <hg_marl.core.World.step>`, as the
``*_batch`` functions of :mod:`hg_marl.core.cycle` are the twin of the cycle's scalar
rules; :class:`hg_marl.envs.batched.BatchedTable` runs both over a seat's tables, and
the compiled partners (``agents/compiled.py``) tabulate their outcomes with it.
"""

from __future__ import annotations

import numpy as np

from hg_marl.core.types import Agent, Kind, State
from hg_marl.core.world import World


class BatchState:
    """A batch of symbolic states: ``where`` (N, objects), ``robot_at``, ``offer_by``, ``offer_obj`` (N,)."""

    __slots__ = ("offer_by", "offer_obj", "robot_at", "rows", "where")

    def __init__(
        self,
        where: np.ndarray,
        robot_at: np.ndarray,
        offer_by: np.ndarray,
        offer_obj: np.ndarray,
        rows: np.ndarray | None = None,
    ) -> None:
        self.where, self.robot_at, self.offer_by, self.offer_obj = where, robot_at, offer_by, offer_obj
        self.rows = np.arange(len(robot_at)) if rows is None else rows
        """Which tables of the env these are (partners that keep a member or an actor per table read it)."""

    @classmethod
    def of(cls, states: list[State]) -> BatchState:
        """A batch from a list of states."""
        return cls(
            np.array([s.where for s in states], dtype=np.int64),
            np.array([s.robot_at for s in states], dtype=np.int64),
            np.array([s.offer_by for s in states], dtype=np.int64),
            np.array([s.offer_obj for s in states], dtype=np.int64),
        )

    def state(self, i: int) -> State:
        """Table ``i`` as a :class:`State`."""
        return State(
            tuple(int(x) for x in self.where[i]),
            int(self.robot_at[i]),
            int(self.offer_by[i]),
            int(self.offer_obj[i]),
        )

    def __len__(self) -> int:
        return len(self.robot_at)

    def take(self, rows: np.ndarray) -> BatchState:
        """A new batch of tables ``rows`` (copies; a row may repeat), each still naming its env table.

        ``np.take`` along the rows: numpy's fancy indexing of a 2-D array by one index
        array takes about twice as long for the same copy.
        """
        return BatchState(
            np.take(self.where, rows, axis=0),
            self.robot_at[rows],
            self.offer_by[rows],
            self.offer_obj[rows],
            self.rows[rows],
        )

    def put(self, rows: np.ndarray, other: BatchState) -> None:
        """Overwrite tables ``rows`` with ``other``'s (same length; nothing to do when ``other`` is self's view)."""
        if other.where is self.where:
            return
        self.where[rows] = other.where
        self.robot_at[rows] = other.robot_at
        self.offer_by[rows] = other.offer_by
        self.offer_obj[rows] = other.offer_obj


class BatchedRules:
    """``RuleTable``'s tables as arrays and its rules applied to a :class:`BatchState`."""

    def __init__(self, world: World) -> None:
        t = world.table
        self.world = world
        n, m, p = t.n_objects, t.n_spots, t.n_places
        self.n_objects, self.n_spots, self.n_places = n, m, p
        self.hand = t.hand
        # reach over every place code (non-spots are never reached for a pick)
        reach = np.zeros((2, t.n_locations, p), dtype=bool)
        reach[:, :, :m] = np.array(t.reach, dtype=bool)
        self.reach = reach
        self.throw_to = np.array(t.throw_to, dtype=np.int64)  # (agent, at, object)
        self.give_ok = np.array(t.give_ok, dtype=bool)  # (at,)
        self.goto_obj = np.array(t.goto_obj, dtype=np.int64)  # (at, place)
        self.goto_static = np.array(t.goto_static, dtype=np.int64)  # (at, bins + human)
        self.spot_human = np.array(t.spot_human, dtype=bool)
        self.done = np.array([[q in t.done[o] for q in range(p)] for o in range(n)], dtype=bool)
        self.kind = tuple(np.array([s.kind for s in specs], dtype=np.int64) for specs in t.specs)
        self.obj = tuple(np.array([s.obj for s in specs], dtype=np.int64) for specs in t.specs)
        self.target = tuple(np.array([s.target for s in specs], dtype=np.int64) for specs in t.specs)
        self.duration = tuple(np.array([s.duration for s in specs], dtype=np.float64) for specs in t.specs)
        # per action, which part of a step it takes: one byte gathered per table instead of its kind compared
        self.moves = tuple(np.isin(k, (Kind.PICK, Kind.TAKE, Kind.THROW, Kind.PLACE)) for k in self.kind)
        self.gives, self.goes, self.waits = (
            tuple(k == kind for k in self.kind) for kind in (Kind.GIVE, Kind.GOTO, Kind.WAIT)
        )
        self.failed = float(t.durations.failed)
        self.n_actions = (len(t.specs[0]), len(t.specs[1]))
        self.first = tuple(
            {k: t.action_index(a, k, 0, 0) for k in Kind if any(s.kind is k for s in t.specs[a])} for a in Agent
        )
        self.wait = t.wait

    # ---- questions ------------------------------------------------------------------
    def is_clean(self, b: BatchState) -> np.ndarray:
        """Per table, whether every object is in a bin that accepts it."""
        out = np.zeros(len(b), dtype=bool)
        out[self._clean(b.where, np.arange(len(b)))] = True
        return out

    def _clean(self, where: np.ndarray, rows: np.ndarray) -> np.ndarray:
        """The ``rows`` of ``where`` whose every object is in a bin that accepts it.

        An object at a time, over the rows still clean: most tables of a batch fail on
        the first objects, so the later ones are read on a few rows.
        """
        for o in range(self.n_objects):
            rows = rows[self.done[o][where[rows, o]]]
        return rows

    def masks(self, b: BatchState, agent: int) -> np.ndarray:
        """(N, n_actions) booleans: ``RuleTable.feasible`` for every table and action."""
        n, m = self.n_objects, self.n_spots
        size = len(b)
        rows = np.arange(size)
        where, at = b.where, b.robot_at
        held = where == self.hand[agent]
        free = ~held.any(axis=1)
        out = np.zeros((size, self.n_actions[agent]), dtype=bool)
        first = self.first[agent]
        pick, throw, give, take = (first[k] for k in (Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE))
        out[:, pick : pick + n] = (where < m) & self.reach[agent][at[:, None], where] & free[:, None]
        out[:, throw : throw + n] = held & (self.throw_to[agent][at] >= 0)
        out[:, give : give + n] = held & self.give_ok[at][:, None]
        offered = free & (b.offer_by == 1 - agent)
        out[rows[offered], take + b.offer_obj[offered]] = True
        if Kind.PLACE in first:
            occupied = np.zeros((size, self.n_places), dtype=bool)
            occupied[rows[:, None], where] = True
            open_spot = self.spot_human[None, :] & ~occupied[:, :m]
            place = first[Kind.PLACE]
            out[:, place : place + n * m] = (held[:, :, None] & open_spot[:, None, :]).reshape(size, n * m)
        if Kind.GOTO in first:
            goto = first[Kind.GOTO]
            out[:, goto : goto + n] = self.goto_obj[at[:, None], where] >= 0
            statics = self.goto_static.shape[1]
            out[:, goto + n : goto + n + statics] = self.goto_static[at] >= 0
        out[:, self.wait[agent]] = True
        return out

    def step(
        self,
        b: BatchState,
        agent: int,
        actions: np.ndarray,
        mask: np.ndarray | None = None,
        ok: np.ndarray | None = None,
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Apply ``RuleTable.successor`` in place: returns (ok, duration, reward) per table.

        ``mask`` may pass the masks of ``b`` for ``agent`` if already computed (those of the
        state before the step: the partner's offer, which a take needs, is still pending).
        ``ok`` may pass each action's feasibility instead, where the caller read it from
        those masks (the model builder: the actions are the masks' own options), so that a
        row of masks is not gathered per action.
        """
        rows, actions = np.arange(len(b)), np.asarray(actions)
        # a partner's pending offer ends with this step: taken (a take is feasible only for the
        # offered object, and only while the partner offers it) or lapsed, a failed take included.
        # The masks before and after it ends agree on every action but that take.
        if ok is None:
            ok = (self.masks(b, agent) if mask is None else mask)[rows, actions]
        ended = b.offer_by == 1 - agent
        reward = np.zeros(len(b))
        if agent == Agent.ROBOT:  # a successful wait on a clean table (only the waits need the check)
            waits = np.flatnonzero(ok & self.waits[agent][actions])
            if len(waits):
                reward[self._clean(b.where, waits)] = 1.0
        b.offer_by[ended] = -1
        b.offer_obj[ended] = -1
        where, at = b.where, b.robot_at
        r = np.flatnonzero(ok & self.moves[agent][actions])
        a = actions[r]
        ob, k = self.obj[agent][a], self.kind[agent][a]
        dest = np.where(
            k == Kind.THROW,
            self.throw_to[agent][at[r], ob],
            np.where(k == Kind.PLACE, self.target[agent][a], self.hand[agent]),
        )
        where[r, ob] = dest
        gave = np.flatnonzero(ok & self.gives[agent][actions])
        b.offer_by[gave] = agent
        b.offer_obj[gave] = self.obj[agent][actions[gave]]
        g = np.flatnonzero(ok & self.goes[agent][actions])
        if len(g):
            t = self.target[agent][actions[g]]
            n = self.n_objects
            obj_t = np.minimum(t, n - 1)
            to_obj = self.goto_obj[at[g], where[g, obj_t]]
            to_static = self.goto_static[at[g], np.maximum(t - n, 0)]
            at[g] = np.where(t < n, to_obj, to_static)
        duration = np.where(ok, self.duration[agent][actions], self.failed)
        return ok, duration, reward

    def facts(self, b: BatchState) -> np.ndarray:
        """(N, F) int8: ``World.compute_facts`` for every table (one fancy index)."""
        lookup, rows, objects, n_fixed = self.world.fact_lookup
        size = len(b)
        out = np.zeros((size, n_fixed + 2 * self.n_objects), dtype=np.int8)
        out[:, :n_fixed] = lookup[b.robot_at[:, None], rows[None, :], b.where[:, objects]]
        offering = np.flatnonzero(b.offer_by >= 0)
        out[offering, n_fixed + b.offer_by[offering] * self.n_objects + b.offer_obj[offering]] = 1
        return out

    def initial(self, rng: np.random.Generator, count: int) -> BatchState:
        """``count`` fresh tables (``World.initial_states``)."""
        where, at = self.world.initial_states(rng, count)
        return BatchState(where, at, np.full(count, -1, dtype=np.int64), np.full(count, -1, dtype=np.int64))
