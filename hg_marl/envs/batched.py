"""Many tables stepped at once: one seat's Gymnasium vector env over the batched rules.

The rules over arrays (:class:`BatchState`, :class:`BatchedRules`, the twin of
``World.step``) live in :mod:`hg_marl.core.batch`, beside the cycle's batched twin in
:mod:`hg_marl.core.cycle`; both are re-exported here.

:class:`BatchedTable` is one seat's Gymnasium ``VectorEnv``: the learning seat's action
per table, then the partner's, which reaches it as arrays through an
:class:`~hg_marl.envs.array_partner.ArrayPartner`, its optional capabilities declared
there (``agents/compiled.py`` compiles scripted partners into one,
``agents/batched_learned.py`` runs a learned SB3 human as one forward pass per step; a
:class:`TabledHuman`, as a compiled human is, hands the next state, its facts and its
robot mask, computed for every entry at compile time, so the human's half of a cycle is
a few gathers). Observations, rewards, clock, durations, effort, idle time, termination and truncation are those of the
single-table views (``agents/views.py``). Autoreset follows Gymnasium 1.x: ``NEXT_STEP``
by default (the step after an episode's last returns the reset observation with reward
0, the action ignored), or ``SAME_STEP`` (``autoreset_mode="same_step"``: the last
observation and info go to ``info["final_obs"]``/``info["final_info"]``, the reset
observation is returned), which SB3's VecEnv adapter (``hg_marl.wrappers.sb3_vec``) uses.

Backends: ``device=None`` runs on numpy (CPU); ``device="cpu"`` or ``"cuda"`` keeps the
same code path and returns observations, rewards and flags as torch tensors (actions may
be tensors), converted at the boundary only. The per-table work is a few integer
gathers, so numpy is the default (``benchmarks/batched_throughput.py`` compares them).
"""

from __future__ import annotations

from typing import Any, cast

import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, VectorEnv

from hg_marl.core import Agent, World, cycle
from hg_marl.core.batch import BatchedRules, BatchState
from hg_marl.core.errors import ConfigError, check_int
from hg_marl.envs.array_partner import ArrayPartner, FollowsClock, ResetsRows, TabledHuman

__all__ = [
    "MEMORY_LIMIT",
    "ArrayPartner",
    "BatchState",
    "BatchedRules",
    "BatchedTable",
    "FollowsClock",
    "ResetsRows",
    "TabledHuman",
    "check_batch",
]

MEMORY_LIMIT = 2 * 2**30
"""Bytes a batch may allocate (state, facts and masks); checked before allocating."""


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
        effort_weight = cycle.check_effort_weight(effort_weight)
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
