"""Interaction history features: what a person uses to read a partner, as binary facts.

The paper's observation is the facts of the current state. Two partners that differ
only in what they *do* (one hands objects over, one never does) reach the same states,
so a memoryless policy on facts cannot tell them apart. The ``history`` observation
option appends, for the observing agent, ``history_size(k, cap)`` more 0/1 entries
computed from the completed cycles of the episode:

- the partner's action KIND (pick, throw, give, take, place, goto, wait; one-hot) in each
  of its last ``k`` cycles, most recent first (all zero before a cycle happened);
- whether each of those ``k`` partner actions failed;
- the same ``k`` kinds and failures for the observer's own actions;
- cycles since the partner last made progress, one-hot over ``0 .. cap`` (``cap`` meaning
  "cap or more"); progress is a successful pick, throw, take or place (an object moved;
  an offer that lapses or a goto is not progress). It starts at 0 with the episode.

Kinds rather than indices keep the features layout-free: "the partner offered" means the
same on every scenario. Everything is binary so the observation stays ``Box(0, 1,
int8)``. The features restart with each episode (``reset``); a continuing table's
re-draw after a success keeps them, since the partner is the same.

One computation, :class:`HistoryTracker`, holds ``(N, ...)`` arrays for ``N`` tables and
is used by the AEC env (``N = 1``), hence the single-agent views, and by
:class:`HistoryVectorEnv` around the batched table (whole arrays, no Python per table),
so the three agree by construction; ``tests/env/test_history.py`` checks them on random
action sequences. Robots rebuild it from their turns (:func:`cycle_from_turn`).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, VectorWrapper

from hg_marl.core import Agent, Kind, World
from hg_marl.core.errors import ConfigError, check_int

N_KINDS = len(Kind)
PROGRESS_KINDS = (Kind.PICK, Kind.THROW, Kind.TAKE, Kind.PLACE)
DEFAULT_CAP = 8
"""Cycles since the partner's progress are counted up to this (then "this or more")."""
MAX_HISTORY = 64
"""Largest ``k`` accepted (the features grow linearly with it)."""


def check_history(history: Any, what: str = "history") -> int:
    """``history`` (k) validated: an int in ``[0, MAX_HISTORY]`` (0: no history features)."""
    return check_int(history, what, minimum=0, maximum=MAX_HISTORY)


def history_size(k: int, cap: int = DEFAULT_CAP) -> int:
    """Number of feature entries for ``k`` cycles of history (0 when ``k == 0``)."""
    if k == 0:
        return 0
    return 2 * k * (N_KINDS + 1) + cap + 1


def history_names(k: int, cap: int = DEFAULT_CAP) -> tuple[str, ...]:
    """A name per feature entry, in order (for headers and docs)."""
    if k == 0:
        return ()
    names: list[str] = []
    for who in ("partner", "own"):
        names += [f"{who}_kind[-{j + 1}]={kind.name.lower()}" for j in range(k) for kind in Kind]
        names += [f"{who}_failed[-{j + 1}]" for j in range(k)]
    names += [f"partner_since_progress={c}" + ("+" if c == cap else "") for c in range(cap + 1)]
    return tuple(names)


class HistoryTracker:
    """The history of ``n`` tables as arrays; see the module docstring.

    Args:
        world: gives each action's kind, per seat.
        k: cycles of history kept.
        n: tables.
        cap: the "cycles since progress" counter's ceiling.
    """

    def __init__(self, world: World, k: int, n: int = 1, cap: int = DEFAULT_CAP) -> None:
        self.k, self.n = check_history(k), int(n)
        self.cap = check_int(cap, "history cap", minimum=1, maximum=1000)
        self.size = history_size(self.k, self.cap)
        table = world.table
        self.kind_of = tuple(np.array([int(s.kind) for s in table.specs[a]], dtype=np.int64) for a in Agent)
        progress = [int(k) for k in PROGRESS_KINDS]
        self.moves = tuple(np.isin(kinds, progress) for kinds in self.kind_of)
        self.kinds = np.full((self.n, 2, max(self.k, 1)), -1, dtype=np.int64)
        """Per table and agent, the kind of its last ``k`` actions (most recent first; -1: none)."""
        self.failed = np.zeros((self.n, 2, max(self.k, 1)), dtype=bool)
        self.since = np.zeros((self.n, 2), dtype=np.int64)
        """Per table and agent, cycles since that agent last made progress (clipped at ``cap``)."""
        self._eye = np.vstack([np.eye(N_KINDS, dtype=np.int8), np.zeros((1, N_KINDS), dtype=np.int8)])

    def reset(self, rows: np.ndarray | None = None) -> None:
        """Forget the history of ``rows`` (default: every table): a new episode."""
        sel = slice(None) if rows is None else rows
        self.kinds[sel] = -1
        self.failed[sel] = False
        self.since[sel] = 0

    def record(self, robot: np.ndarray, robot_ok: np.ndarray, human: np.ndarray, human_ok: np.ndarray) -> None:
        """One completed cycle per table: each agent's action index and whether it succeeded."""
        for a, act, ok in ((0, robot, robot_ok), (1, human, human_ok)):
            act = np.asarray(act, dtype=np.int64).reshape(self.n)
            ok = np.asarray(ok, dtype=bool).reshape(self.n)
            self.kinds[:, a, 1:] = self.kinds[:, a, :-1]
            self.failed[:, a, 1:] = self.failed[:, a, :-1]
            self.kinds[:, a, 0] = self.kind_of[a][act]
            self.failed[:, a, 0] = ~ok
            moved = ok & self.moves[a][act]
            self.since[:, a] = np.where(moved, 0, np.minimum(self.since[:, a] + 1, self.cap))

    def features(self, observer: Agent | int = Agent.ROBOT) -> np.ndarray:
        """(n, size) int8: the observer's features (partner's first, then its own; see the module docstring)."""
        if self.k == 0:
            return np.zeros((self.n, 0), dtype=np.int8)
        me = int(observer)
        parts = []
        for a in (1 - me, me):
            parts.append(self._eye[self.kinds[:, a]].reshape(self.n, self.k * N_KINDS))
            parts.append(self.failed[:, a].astype(np.int8))
        since = np.zeros((self.n, self.cap + 1), dtype=np.int8)
        since[np.arange(self.n), self.since[:, 1 - me]] = 1
        parts.append(since)
        return np.concatenate(parts, axis=1)


def cycle_from_turn(turn: Any) -> tuple[int, bool, int, bool] | None:
    """(robot action, robot ok, human action, human ok) of the cycle before ``turn``, from its events.

    None before the first cycle. A robot reads its history this way: ``turn.last_actions``
    gives the indices, a ``failed`` event of an agent says its action failed.
    """
    robot, human = turn.last_actions
    if robot < 0 or human < 0:
        return None
    failed = {e.agent for e in turn.events if e.kind == "failed"}
    return int(robot), "robot" not in failed, int(human), "human" not in failed


class HistoryVectorEnv(VectorWrapper):
    """The robot's batched seat (``BatchedTable``) with history features appended to the facts.

    The features are recorded from each step's actions and ``info`` (``human_action``,
    ``failed``, ``human_failed``) for every table at once and forgotten for the tables
    that start a new episode (both autoreset modes; in ``same_step`` mode
    ``info["final_obs"]`` carries the features of the episode's last cycle). Everything
    else (``action_masks``, ``clock``, ``tasks_solved``, ``world``...) is the table's.
    """

    def __init__(self, env: Any, k: int, cap: int = DEFAULT_CAP) -> None:
        super().__init__(env)
        self.inner: Any = env
        if env.seat is not Agent.ROBOT:
            raise ConfigError("history: the batched human seat has no history option (use the robot's)")
        self.tracker = HistoryTracker(env.world, k, env.num_envs, cap)
        extra = self.tracker.size
        n_f = env.single_observation_space.shape[0]
        self.single_observation_space = spaces.Box(0, 1, (n_f + extra,), np.int8)
        self.observation_space = spaces.Box(0, 1, (env.num_envs, n_f + extra), np.int8)
        self._ended = np.zeros(env.num_envs, dtype=bool)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self.env, name)

    def _with(self, obs: Any) -> Any:
        feats = self.tracker.features(Agent.ROBOT)
        if isinstance(obs, np.ndarray):
            return np.concatenate([obs, feats], axis=1)
        import torch

        return torch.cat([obs, torch.as_tensor(feats, device=obs.device)], dim=1)

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
        obs, info = self.env.reset(seed=seed, options=options)
        self.tracker.reset()
        self._ended[:] = False
        return self._with(obs), info

    def step(self, actions: Any) -> tuple[Any, Any, Any, Any, dict[str, Any]]:
        acts = np.asarray(actions.cpu() if hasattr(actions, "cpu") else actions).astype(np.int64).reshape(-1)
        obs, reward, terminated, truncated, info = self.env.step(actions)
        self.tracker.record(acts, ~np.asarray(info["failed"]), info["human_action"], ~np.asarray(info["human_failed"]))
        ended = np.asarray(terminated.cpu() if hasattr(terminated, "cpu") else terminated, dtype=bool) | np.asarray(
            truncated.cpu() if hasattr(truncated, "cpu") else truncated, dtype=bool
        )
        if self.inner.autoreset_mode is AutoresetMode.NEXT_STEP:
            if self._ended.any():  # these tables were re-drawn by this step: a new episode
                self.tracker.reset(np.flatnonzero(self._ended))
            self._ended = ended
        elif ended.any():
            info["final_obs"] = self._with(info["final_obs"])
            self.tracker.reset(np.flatnonzero(ended))
        return self._with(obs), reward, terminated, truncated, info
