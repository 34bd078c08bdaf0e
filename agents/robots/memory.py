"""``memory``: a robot that plays a policy with memory trained by ``ppo_recurrent``.

The model file (kind ``memory``, :mod:`hg_marl.agents.memory_policy`) names the history
length the policy was trained with; the robot rebuilds exactly that observation at
each turn: the facts, then the interaction history of the episode so far
(:class:`~hg_marl.envs.history.HistoryTracker`, fed from each turn's last actions and
``failed`` events, :func:`~hg_marl.envs.history.cycle_from_turn`), so it sees what
it saw in training. A recurrent policy's hidden state starts at zero at ``reset`` (a
new episode) and is carried from turn to turn. The turn's mask is always applied (the
policy was trained masked), so its action is always feasible.

Stalls. A policy trained with partners who always do their share may wait for a partner
who never will (both wait forever on a table that is still solvable), or repeat an offer
such a partner refuses. The robot obeys the progress guard every robot obeys
(:mod:`hg_marl.agents.progress`) with ``K = unstall`` (default 8, the value this robot's
earlier rule was measured with, ``docs/learned-robots.md``): after ``unstall`` turns at an
unchanged state it takes the guard's move, in the policy's own order of preference (its
best feasible action other than ``wait`` and other than the move it keeps choosing
first), so it never idles forever beside an idle partner nor repeats a refused offer;
``unstall=0`` plays the policy as trained.

Decision time: the habit's deterministic constant, as for the ``sb3`` robot.
``deterministic=False`` samples the policy with the robot's own generator. The forward
pass is numpy (``agents/memory_numpy.py``): playing never imports torch.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.memory_numpy import NumpyMemoryPolicy
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.model_file import check_world, load_model_file
from hg_marl.agents.progress import ProgressGuard
from hg_marl.agents.robots.base import Robot
from hg_marl.core import Agent, World
from hg_marl.core.errors import RobotError, check_int
from hg_marl.envs.history import HistoryTracker, cycle_from_turn
from hg_marl.policy import Turn


class MemoryRobot(Robot):
    """Plays a ``memory`` model file in the robot seat (see the module docstring).

    Args:
        path: the model header (``model.json``), its weights, its stem, or its folder.
        deterministic: take the most probable feasible action (False: sample).
        cost: decision cost model (default: the habit's constant, ``CostModel.habit``).
        net: an in-memory policy instead of ``path`` (with ``history``): anything with
            ``initial(n)`` and ``step(obs, h) -> (logits, h)`` on numpy arrays.
        history: the history length of ``net``.
        unstall: the progress guard's ``K`` (after this many turns at an unchanged state,
            the policy's best feasible action other than ``wait``; 0: never).
    """

    name = "memory"

    def __init__(
        self,
        path: str | Path | None = None,
        deterministic: bool = True,
        cost: CostModel | None = None,
        net: Any = None,
        history: int = 0,
        unstall: int = 8,
    ) -> None:
        super().__init__(cost)
        if (path is None) == (net is None):
            raise RobotError("robot 'memory' needs a trained model: --model FILE (or memory:path=FILE)")
        self.deterministic = bool(deterministic)
        self.file: Any = None
        self.cap = 8
        if path is not None:
            self.file = load_model_file(path, what="--model", seat="robot")
            net = NumpyMemoryPolicy(self.file)
            history, self.cap = net.shape.history, net.shape.cap
        self.net, self.history = net, int(history)
        self.unstall = check_int(unstall, "unstall", minimum=0, error=RobotError)
        self.progress = ProgressGuard(self.unstall) if self.unstall else None
        self.tracker: HistoryTracker | None = None
        self.h: Any = None
        self.last_obs: np.ndarray | None = None
        """The observation of the last turn (facts then history), as the env's ``history`` option gives it."""

    def _reset(self, world: World) -> None:
        if self.agent is not Agent.ROBOT:
            raise RobotError("the memory robot plays the robot seat only")
        if self.file is not None:
            check_world(self.file, world, Agent.ROBOT)
        self.tracker = HistoryTracker(world, self.history, 1, self.cap)
        self.h = self.net.initial(1)
        if self.progress is not None:
            self.progress.reset()

    def act(self, turn: Turn) -> int:
        """The policy's action for the facts and the history so far (masked)."""
        t0 = time.perf_counter()
        assert self.tracker is not None, "reset() first"
        cycle = cycle_from_turn(turn)
        if cycle is not None:
            r, r_ok, hu, h_ok = cycle
            self.tracker.record(np.array([r]), np.array([r_ok]), np.array([hu]), np.array([h_ok]))
        facts = np.asarray(turn.observation["observation"])[: turn.world.n_facts]
        self.last_obs = np.concatenate([facts, self.tracker.features(Agent.ROBOT)[0]])
        logits, self.h = self.net.step(self.last_obs[None, :].astype(np.float64), self.h)
        mask = np.asarray(turn.mask).astype(bool)
        scores = np.where(mask, logits[0], -np.inf)
        if self.progress is not None and self.progress.observe(turn.state):
            # Nothing changed for K turns: the guard's move in the policy's order, without
            # the move the policy keeps choosing (it changed nothing).
            prefer = scores.copy()
            prefer[int(np.argmax(scores))] = -np.inf
            action = self.progress.move(turn.world, turn.state, self.agent, prefer=prefer)
            wall = time.perf_counter() - t0
            self._record("guard", action, reason=self.progress.reason, decision_time=self.cost.habit_cost(wall))
            return action
        if self.deterministic:
            action = int(np.argmax(scores))
        else:
            p = np.exp(scores - scores.max())
            action = int(self.rng.choice(len(p), p=p / p.sum()))
        wall = time.perf_counter() - t0
        self._record("memory", action, planning_time=wall, decision_time=self.cost.habit_cost(wall))
        return action
