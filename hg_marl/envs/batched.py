"""Many tables stepped at once on arrays: the rule table's tabulated rules, batched.

:class:`BatchedRules` reads :class:`~hg_marl.core.table.RuleTable`'s own tables (who
reaches which spot from where, where a throw lands, where a goto leads, each action's
kind, object, target and duration) as numpy arrays, and applies the preconditions and
effects that ``RuleTable.feasible`` and ``RuleTable.successor`` state to a whole batch of
states; nothing scenario-specific is computed here. The facts come from
``World.fact_lookup`` (one fancy index), the table draw from ``World.initial_states``.
A property test (``tests/env/test_batched.py``) steps it beside ``World.step`` on random
action sequences and requires identical trajectories.

:class:`BatchedTable` is one seat's Gymnasium ``VectorEnv``: the learning seat's action
per table, then the partner's, which reaches it as arrays through :class:`ArrayPartner`
(``agents/compiled.py`` compiles scripted partners into one, ``agents/batched_learned.py``
runs a learned SB3 human as one forward pass per step; a partner that also has
``answer`` and ``outcome`` tables, as a compiled human does, hands the next state, its
facts and its robot mask, which ``BatchedRules`` computed for every entry at compile
time, so the human's half of a cycle is a few gathers). Observations, rewards,
clock, durations, effort, idle time, termination and truncation are those of the
single-table views (``agents/views.py``). Autoreset follows Gymnasium 1.x: ``NEXT_STEP``
by default (the step after an episode's last returns the reset observation with reward
0, the action ignored), or ``SAME_STEP`` (``autoreset_mode="same_step"``: the last
observation and info go to ``info["final_obs"]``/``info["final_info"]``, the reset
observation is returned), which SB3's VecEnv adapter (``hg_marl.wrappers.sb3_vec``) uses.

Backends: ``device=None`` runs on numpy (CPU); ``device="cpu"`` or ``"cuda"`` keeps the
same code path and returns observations, rewards and flags as torch tensors (actions may
be tensors), converted at the boundary only. ``benchmarks/batched_throughput.py``
measures it at 0.75-1.3x numpy on CPU (no gain: the per-table work is a few integer
gathers), so numpy is the default; no GPU was available to measure ``"cuda"``.
"""

from __future__ import annotations

from typing import Any, Protocol, cast, runtime_checkable

import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, VectorEnv

from hg_marl.core import Agent, Kind, State, World, cycle
from hg_marl.core.errors import ConfigError, check_int

MEMORY_LIMIT = 2 * 2**30
"""Bytes a batch may allocate (state, facts and masks); checked before allocating."""


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
        self.failed = float(t.durations.failed)
        self.n_actions = (len(t.specs[0]), len(t.specs[1]))
        self.first = tuple(
            {k: t.action_index(a, k, 0, 0) for k in Kind if any(s.kind is k for s in t.specs[a])} for a in Agent
        )
        self.wait = t.wait

    # ---- questions ------------------------------------------------------------------
    def is_clean(self, b: BatchState) -> np.ndarray:
        """Per table, whether every object is in a bin that accepts it."""
        return self.done[np.arange(self.n_objects), b.where].all(axis=1)

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
        self, b: BatchState, agent: int, actions: np.ndarray, mask: np.ndarray | None = None
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Apply ``RuleTable.successor`` in place: returns (ok, duration, reward) per table.

        ``mask`` may pass the masks of ``b`` for ``agent`` if already computed (they must be
        those of the state before the offer lapses; see below, they agree on every action).
        """
        rows = np.arange(len(b))
        kind, o, target = self.kind[agent][actions], self.obj[agent][actions], self.target[agent][actions]
        # a partner's pending offer lapses unless this is its take; a failed take lets it lapse too.
        # The masks before and after the lapse agree: only TAKE depends on the offer, and a take of
        # the offered object keeps it.
        if mask is None:
            mask = self.masks(b, agent)
        ok = mask[rows, actions]
        take_reply = (kind == Kind.TAKE) & (o == b.offer_obj)
        lapse = (b.offer_by == 1 - agent) & ~(take_reply & ok)
        reward = np.zeros(len(b))
        if agent == Agent.ROBOT:  # a successful wait on a clean table (only the waits need the check)
            waits = np.flatnonzero(ok & (kind == Kind.WAIT))
            if len(waits):
                reward[waits] = self.is_clean(BatchState(b.where[waits], b.robot_at, b.offer_by, b.offer_obj))
        b.offer_by[lapse] = -1
        b.offer_obj[lapse] = -1
        where, at = b.where, b.robot_at
        moves = ok & ((kind == Kind.PICK) | (kind == Kind.TAKE) | (kind == Kind.THROW) | (kind == Kind.PLACE))
        r, ob = rows[moves], o[moves]
        k = kind[moves]
        dest = np.where(
            k == Kind.THROW,
            self.throw_to[agent][at[r], ob],
            np.where(k == Kind.PLACE, target[moves], self.hand[agent]),
        )
        where[r, ob] = dest
        took = ok & (kind == Kind.TAKE)
        b.offer_by[took] = -1
        b.offer_obj[took] = -1
        gave = ok & (kind == Kind.GIVE)
        b.offer_by[gave] = agent
        b.offer_obj[gave] = o[gave]
        went = ok & (kind == Kind.GOTO)
        if went.any():
            g, t = rows[went], target[went]
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


class ArrayPartner(Protocol):
    """The partner of a batched seat: one action per table from arrays.

    ``seen`` is, per table, the learning robot's successful action of this cycle (-1 if it
    failed), for partners whose choice depends on it; a robot partner gets -1.

    Optional capabilities, each declared by its own protocol below and detected once when
    the table is built (never looked up on the hot path): :class:`FollowsClock`
    (``follow``), :class:`ResetsRows` (``reset_rows``) and :class:`TabledHuman`
    (``actions``, ``outcome``, ``answer``, ``fall_back``).
    """

    name: str

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """The partner's action index per table."""


@runtime_checkable
class FollowsClock(Protocol):
    """A partner whose behaviour depends on each table's clock (a schedule of humans)."""

    def follow(self, clock: np.ndarray, tasks_solved: np.ndarray) -> None:
        """Called before each of its moves with every table's clock and tasks solved."""


@runtime_checkable
class ResetsRows(Protocol):
    """A partner that keeps something per table (an actor, a member) to start afresh."""

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Tables ``rows`` start a new episode."""


@runtime_checkable
class TabledHuman(Protocol):
    """A compiled human: its answers' outcomes tabulated (``agents/compiled.py``).

    ``outcome`` holds, per table entry, the next state's fields (``where``, ``robot_at``,
    ``offer_by``, ``offer_obj``), its ``facts`` and robot ``mask``, and the action's
    ``ok`` and ``duration``, all computed by :class:`BatchedRules` at compile time.
    """

    actions: np.ndarray
    outcome: dict[str, np.ndarray]

    def answer(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(table entry, found) per table."""

    def fall_back(
        self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator, out: np.ndarray, found: np.ndarray
    ) -> np.ndarray:
        """``out`` with the live partner's answers where ``found`` is False."""


def check_batch(world: World, num_envs: Any, memory_limit: int = MEMORY_LIMIT) -> int:
    """``num_envs`` validated: a positive int whose arrays fit ``memory_limit`` bytes."""
    count = check_int(num_envs, "num_envs", minimum=1)
    per_table = 8 * (world.n_objects + 16) + world.n_facts * 2 + 2 * (world.n_actions(Agent.HUMAN) + 1) + 128
    if count * per_table > memory_limit:
        raise ConfigError(
            f"num_envs: {count} tables need about {count * per_table / 2**20:.0f} MB, over the "
            f"{memory_limit / 2**20:.0f} MB limit (memory_limit); use fewer tables"
        )
    return count


class BatchedTable(VectorEnv):
    """One seat of ``num_envs`` tables with its partner inside; see the module docstring.

    Args:
        partner: the partner as arrays (an :class:`ArrayPartner`).
        num_envs: tables stepped at once.
        scenario: scenario name, TOML path, Scenario or a World.
        seat: ``Agent.ROBOT`` (default) or ``Agent.HUMAN``.
        continuing: re-draw a table after each success instead of ending its episode.
        max_cycles: truncate after this many cycles (None: no limit).
        time_budget: truncate once the clock reaches this many simulated seconds.
        effort_weight: the human seat's reward minus this times its seconds of work.
        autoreset_mode: ``"next_step"`` (Gymnasium's default) or ``"same_step"``.
        memory_limit: bytes the batch may allocate (checked before allocating).
        device: None for numpy; a torch device to return observations, rewards and masks as tensors.
    """

    def __init__(
        self,
        partner: ArrayPartner,
        num_envs: int,
        scenario: Any = "paper2015",
        seat: Agent = Agent.ROBOT,
        continuing: bool = False,
        max_cycles: int | None = 500,
        time_budget: float | None = None,
        effort_weight: float = 0.0,
        autoreset_mode: str = "next_step",
        memory_limit: int = MEMORY_LIMIT,
        device: Any = None,
    ) -> None:
        self.world = scenario if isinstance(scenario, World) else World(scenario)
        self.num_envs = check_batch(self.world, num_envs, memory_limit)
        if max_cycles is not None:
            max_cycles = check_int(max_cycles, "max_cycles", minimum=1)
        if time_budget is not None and not (np.isfinite(time_budget) and time_budget > 0):
            raise ConfigError(f"time_budget: expected a positive finite number of seconds, got {time_budget!r}")
        if not (np.isfinite(effort_weight) and effort_weight >= 0):
            raise ConfigError(f"effort_weight: expected a non-negative finite number, got {effort_weight!r}")
        modes = {"next_step": AutoresetMode.NEXT_STEP, "same_step": AutoresetMode.SAME_STEP}
        if autoreset_mode not in modes:
            raise ConfigError(f"autoreset_mode: expected one of {sorted(modes)}, got {autoreset_mode!r}")
        self.autoreset_mode = modes[autoreset_mode]
        self.metadata = {"autoreset_mode": self.autoreset_mode, "render_modes": []}
        self.rules = BatchedRules(self.world)
        self.seat = Agent(seat)
        self.partner = partner
        self._follows = isinstance(partner, FollowsClock)
        self._resets = isinstance(partner, ResetsRows)
        self._tabled = isinstance(partner, TabledHuman) and partner.outcome is not None
        self.continuing, self.max_cycles, self.time_budget = bool(continuing), max_cycles, time_budget
        self.effort_weight = float(effort_weight)
        self.device = device
        n_f, n_a = self.world.n_facts, self.world.n_actions(self.seat)
        self.single_observation_space = spaces.Box(0, 1, (n_f,), np.int8)
        self.single_action_space = spaces.Discrete(n_a)
        self.observation_space = spaces.Box(0, 1, (self.num_envs, n_f), np.int8)
        self.action_space = spaces.MultiDiscrete(np.full(self.num_envs, n_a))
        self._rng = np.random.default_rng()
        self._partner_rng = np.random.default_rng()
        self.state = self.rules.initial(self._rng, self.num_envs)
        self._zero_counters(np.arange(self.num_envs))
        self._autoreset = np.zeros(self.num_envs, dtype=bool)
        self._obs = np.zeros((self.num_envs, n_f), dtype=np.int8)
        self._masks = np.zeros((self.num_envs, n_a), dtype=bool)
        self._stale = np.ones(self.num_envs, dtype=bool)
        """Tables whose cached facts and mask must be recomputed (their state changed by the rules)."""
        n = self.num_envs
        self._robot_act, self._robot_ok = np.full(n, -1, dtype=np.int64), np.zeros(n, dtype=bool)
        self._robot_dur, self._robot_won = np.zeros(n), np.zeros(n, dtype=bool)

    # ---- counters -------------------------------------------------------------------
    def _zero_counters(self, rows: np.ndarray) -> None:
        if not hasattr(self, "clock"):
            n = self.num_envs
            self.clock, self.cycles, self.tasks_solved = np.zeros(n), np.zeros(n, np.int64), np.zeros(n, np.int64)
            self.effort, self.idle = np.zeros((n, 2)), np.zeros((n, 2))
        self.clock[rows] = 0.0
        self.cycles[rows] = 0
        self.tasks_solved[rows] = 0
        self.effort[rows] = 0.0
        self.idle[rows] = 0.0

    # ---- gymnasium API ----------------------------------------------------------------
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
        """New tables (``options={"states": [State, ...]}`` to start from given states)."""
        if seed is not None:
            self._rng, self._partner_rng = (np.random.default_rng(s) for s in np.random.SeedSequence(seed).spawn(2))
        options = options or {}
        rows = np.arange(self.num_envs)
        if "states" in options:
            states = list(options["states"])
            if len(states) != self.num_envs:
                raise ConfigError(f"options['states']: expected {self.num_envs} states, got {len(states)}")
            self.state = BatchState.of(states)
        else:
            self.state = self.rules.initial(self._rng, self.num_envs)
        self._zero_counters(rows)
        self._autoreset[:] = False
        self._reset_partner(rows)
        partner = np.full(self.num_envs, -1, dtype=np.int64)
        if self.seat is Agent.HUMAN:
            partner = self._partner_move(rows, np.full(self.num_envs, -1, dtype=np.int64))[0]
        self._stale[:] = True
        info = {"clock": self.clock.copy(), "tasks_solved": self.tasks_solved.copy()}
        if self.seat is Agent.HUMAN:
            info["robot_action"] = partner
        return self._out(self._view()[0].copy()), info

    def _view(self) -> tuple[np.ndarray, np.ndarray]:
        """The current facts and seat masks, recomputing the stale tables only."""
        if self._stale.any():
            rows = np.flatnonzero(self._stale)
            sub = self._sub(rows)
            self._obs[rows] = self.rules.facts(sub)
            self._masks[rows] = self.rules.masks(sub, self.seat)
            self._stale[:] = False
        return self._obs, self._masks

    def action_masks(self) -> np.ndarray:
        """(num_envs, n_actions) booleans: the learning seat's feasible actions (sb3-contrib's hook)."""
        return self._view()[1].copy()

    def step(self, actions: Any) -> tuple[Any, Any, Any, Any, dict[str, Any]]:
        """One cycle per table (see the module docstring); ``actions`` has one index per table."""
        actions = np.asarray(actions.cpu() if hasattr(actions, "cpu") else actions).astype(np.int64).reshape(-1)
        n_a = self.rules.n_actions[self.seat]
        if actions.shape != (self.num_envs,) or (actions < 0).any() or (actions >= n_a).any():
            raise ValueError(f"actions: expected {self.num_envs} indices in [0, {n_a}), got {actions!r}")
        resetting = self._autoreset.copy() if self.autoreset_mode is AutoresetMode.NEXT_STEP else None
        # Every table steps (whole arrays, no copies); the tables being autoreset are then
        # re-drawn and their step's results discarded: the action is ignored, as Gymnasium says.
        every = np.arange(self.num_envs)
        if self.seat is Agent.ROBOT:
            rewards, terminated, truncated, info = self._robot_cycle(every, actions)
        else:
            rewards, terminated, truncated, info = self._human_cycle(every, actions)
        if resetting is not None and resetting.any():
            rewards[resetting], terminated[resetting], truncated[resetting] = 0.0, False, False
            for key, value in info.items():
                value[resetting] = False if key.startswith("_") else 0
        ended = terminated | truncated
        if resetting is not None:
            if resetting.any():
                self._reset_rows(np.flatnonzero(resetting))
            self._autoreset = ended
            obs = self._view()[0].copy()
        else:
            obs = self._view()[0].copy()
            if ended.any():
                info["final_obs"] = obs
                info["final_info"] = {k: v.copy() for k, v in info.items() if k != "final_obs"}
                info["_final_obs"] = ended
                self._reset_rows(np.flatnonzero(ended))
                obs = self._view()[0].copy()
        return self._out(obs), self._out(rewards), self._out(terminated), self._out(truncated), info

    # ---- cycles -----------------------------------------------------------------------
    def _sub(self, rows: np.ndarray) -> BatchState:
        """Tables ``rows`` (the state itself, not a copy, when they are all of them in order)."""
        s = self.state
        if len(rows) == self.num_envs:
            return BatchState(s.where, s.robot_at, s.offer_by, s.offer_obj, rows)
        return BatchState(s.where[rows], s.robot_at[rows], s.offer_by[rows], s.offer_obj[rows], rows)

    def _partner_move(self, rows: np.ndarray, seen: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The partner's move on tables ``rows``: (actions, ok, duration)."""
        if self._follows:
            cast(FollowsClock, self.partner).follow(self.clock, self.tasks_solved)
        sub = self._sub(rows)
        other = self.seat.other
        if other is Agent.HUMAN and self._tabled:
            return self._compiled_move(rows, sub, seen)
        acts = np.asarray(self.partner.act(sub, seen, self._partner_rng), dtype=np.int64)
        ok, duration, reward = self.rules.step(sub, other, acts)
        self.state.put(rows, sub)
        self._stale[rows] = True
        if other is Agent.ROBOT:
            self._robot_won[rows] = self._rewarded(rows, reward)
            self._robot_act[rows], self._robot_ok[rows], self._robot_dur[rows] = acts, ok, duration
        return acts, ok, duration

    def _compiled_move(
        self, rows: np.ndarray, sub: BatchState, seen: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """A compiled human's move: its answers' outcomes gathered from its table (``CompiledHuman.outcome``).

        Tables outside the table are answered by the live human and stepped by the rules.
        """
        partner = cast(TabledHuman, self.partner)
        pos, found = partner.answer(sub, seen, self._partner_rng)
        acts = partner.actions[pos]
        if found.all():
            hit, p = rows, pos
        else:
            acts = partner.fall_back(sub, seen, self._partner_rng, acts, found)
            hit, p = rows[found], pos[found]
        out = partner.outcome
        st = self.state
        if len(hit) == self.num_envs:  # every table found: gather straight into the state
            for name, target in (
                ("where", st.where),
                ("robot_at", st.robot_at),
                ("offer_by", st.offer_by),
                ("offer_obj", st.offer_obj),
                ("facts", self._obs),
                ("mask", self._masks),
            ):
                np.take(out[name], p, axis=0, out=target)
        else:
            st.where[hit], st.robot_at[hit] = out["where"][p], out["robot_at"][p]
            st.offer_by[hit], st.offer_obj[hit] = out["offer_by"][p], out["offer_obj"][p]
            self._obs[hit], self._masks[hit] = out["facts"][p], out["mask"][p]
        self._stale[hit] = False
        ok, duration = out["ok"][pos], out["duration"][pos]
        if not found.all():
            miss = np.flatnonzero(~found)
            slow = BatchState(sub.where[miss], sub.robot_at[miss], sub.offer_by[miss], sub.offer_obj[miss])
            ok[miss], duration[miss], _ = self.rules.step(slow, Agent.HUMAN, acts[miss])
            st.put(rows[miss], slow)
            self._stale[rows[miss]] = True
        return acts, ok, duration

    def _rewarded(self, rows: np.ndarray, reward: np.ndarray) -> np.ndarray:
        """Count successes; in continuing mode re-draw the solved tables (before the human's move)."""
        won = reward > 0
        self.tasks_solved[rows[won]] += 1
        if self.continuing and won.any():
            self.state.put(rows[won], self.rules.initial(self._rng, int(won.sum())))
            self._stale[rows[won]] = True
        return won

    def _end_cycle(
        self,
        rows: np.ndarray,
        acts: tuple[np.ndarray, np.ndarray],
        ok: tuple[np.ndarray, np.ndarray],
        dur: tuple[np.ndarray, np.ndarray],
        won: np.ndarray,
    ) -> tuple[np.ndarray, np.ndarray]:
        """Clock, effort, idle and cycle counters of a finished cycle; (terminated, truncated)."""
        waited = (
            cycle.waited_batch(self.world, Agent.ROBOT, acts[0]),
            cycle.waited_batch(self.world, Agent.HUMAN, acts[1]),
        )
        length, idle = cycle.close_batch(dur, waited)
        for a in (0, 1):
            self.effort[rows, a] += cycle.effort_batch(ok[a], waited[a], dur[a])
            self.idle[rows, a] += idle[a]
        self.clock[rows] += length
        self.cycles[rows] += 1
        truncate = cycle.truncated_batch(self.cycles[rows], self.clock[rows], self.max_cycles, self.time_budget)
        done = cycle.ends_episode(won, self.continuing)
        return done, truncate & ~done

    def _robot_cycle(self, rows: np.ndarray, actions: np.ndarray) -> tuple[Any, Any, Any, dict[str, Any]]:
        sub = self._sub(rows)
        ok_r, d_r, reward = self.rules.step(sub, Agent.ROBOT, actions, self._view()[1][rows])
        self.state.put(rows, sub)
        self._stale[rows] = True
        won = self._rewarded(rows, reward)
        h_act, ok_h, d_h = self._partner_move(rows, cycle.seen_batch(actions, ok_r))
        done, trunc = self._end_cycle(rows, (actions, h_act), (ok_r, ok_h), (d_r, d_h), won)
        info = self._info(rows, actions, ok_r, "human", h_act, ok_h)
        return reward, done, trunc, info

    def _human_cycle(self, rows: np.ndarray, actions: np.ndarray) -> tuple[Any, Any, Any, dict[str, Any]]:
        r_act, ok_r, d_r = self._robot_act[rows], self._robot_ok[rows], self._robot_dur[rows]
        won = np.zeros(len(rows), dtype=bool)  # an episodic win ended the human's episode already
        sub = self._sub(rows)
        effort_before = self.effort[rows, 1].copy()
        ok_h, d_h, _ = self.rules.step(sub, Agent.HUMAN, actions, self._view()[1][rows])
        self.state.put(rows, sub)
        self._stale[rows] = True
        done, trunc = self._end_cycle(rows, (r_act, actions), (ok_r, ok_h), (d_r, d_h), won)
        work = self.effort[rows, 1] - effort_before
        go_on = ~(done | trunc)
        task_reward = np.zeros(len(rows))
        robot_action = np.full(len(rows), -1, dtype=np.int64)
        if go_on.any():
            g = rows[go_on]
            acts, _, _ = self._partner_move(g, np.full(len(g), -1, dtype=np.int64))
            robot_action[go_on] = acts
            task_reward[go_on] = self._robot_won[g]
            done = done | (go_on & cycle.ends_episode(task_reward, self.continuing))
        reward = cycle.seat_reward(task_reward, work, self.effort_weight)
        info = self._info(rows, actions, ok_h, "robot", robot_action, np.ones(len(rows), bool))
        info["work"], info["task_reward"] = work, task_reward
        return reward, done, trunc, info

    def _info(
        self,
        rows: np.ndarray,
        own: np.ndarray,
        own_ok: np.ndarray,
        other: str,
        other_act: np.ndarray,
        other_ok: np.ndarray,
    ) -> dict[str, Any]:
        """Per-table arrays (full length; tables autoreset this step hold zeros), with ``_key`` masks."""
        me = int(self.seat)
        n = self.num_envs
        values = {
            f"{other}_action": other_act,
            "failed": ~own_ok,
            f"{other}_failed": ~other_ok,
            "clock": self.clock[rows],
            "cycle": self.cycles[rows],
            "tasks_solved": self.tasks_solved[rows],
            "effort": self.effort[rows, me],
            "idle": self.idle[rows, me],
            "partner_effort": self.effort[rows, 1 - me],
        }
        info: dict[str, Any] = {}
        present = np.zeros(n, dtype=bool)
        present[rows] = True
        for key, value in values.items():
            if len(rows) == n:  # fancy-indexed above, so already a fresh array
                info[key] = np.asarray(value)
            else:
                info[key] = np.zeros(n, dtype=np.asarray(value).dtype)
                info[key][rows] = value
            info[f"_{key}"] = present
        return info

    def _reset_partner(self, rows: np.ndarray) -> None:
        if self._resets:
            cast(ResetsRows, self.partner).reset_rows(rows, self._partner_rng)

    def _reset_rows(self, rows: np.ndarray) -> None:
        self.state.put(rows, self.rules.initial(self._rng, len(rows)))
        self._stale[rows] = True
        self._zero_counters(rows)
        self._reset_partner(rows)
        if self.seat is Agent.HUMAN:
            self._partner_move(rows, np.full(len(rows), -1, dtype=np.int64))

    def _out(self, array: np.ndarray) -> Any:
        if self.device is None:
            return array
        import torch

        return torch.as_tensor(array, device=self.device)
