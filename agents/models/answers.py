"""The partner's answers as arrays: a distribution per (mid-cycle state, robot action seen).

The model builder asks for the answers of a whole batch of distinct mid-cycle keys at
once. :class:`AnswerTable` keeps them as a compiled partner does (``agents/compiled.py``):
sorted packed keys, segment starts, actions and probabilities, looked up with one
``searchsorted``. Keys it has not seen are answered by the live stationary human, one
Python call per distinct key (memoised in the table), with a budget check before each
call: a planner-driven human may spend a search on one answer, so the budget is read
between answers, never after a batch of them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.models.budget import Budget
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import World

CHECK_EVERY = 1
"""Live answers computed between two clock readings: one answer may cost a planner search, a reading 0.1 us."""


class AnswerTable:
    """A stationary human's answers by packed (state, seen) key, grown on demand.

    Args:
        world: the world.
        human: a reset stationary human with ``distribution(world, state, robot_action)``.
        packer: the builder's packer (keys include the robot action seen).
        budget: checked between live answers (phase ``phase``).
    """

    def __init__(self, world: World, human: Any, packer: StatePacker, budget: Budget | None = None) -> None:
        self.world, self.human, self.packer = world, human, packer
        self.budget = budget
        self.uses_robot_action = bool(getattr(human, "uses_robot_action", False))
        self.keys = np.zeros(0, dtype=np.int64)
        self.starts = np.zeros(1, dtype=np.int64)
        self.actions = np.zeros(0, dtype=np.int64)
        self.probs = np.zeros(0, dtype=np.float64)
        self.live_calls = 0
        """Distributions asked of the live human (the rest came from the table)."""
        self.phase = "answers"

    @classmethod
    def from_arrays(
        cls,
        world: World,
        human: Any,
        packer: StatePacker,
        keys: np.ndarray,
        starts: np.ndarray,
        actions: np.ndarray,
        probs: np.ndarray,
    ) -> AnswerTable:
        """A table filled in advance (a compiled partner's arrays; keys sorted)."""
        table = cls(world, human, packer)
        table.keys, table.starts, table.actions, table.probs = keys, starts, actions, probs
        return table

    def lookup(self, keys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(segment start, segment length) per key; every key must be known (see :meth:`ensure`)."""
        idx = np.searchsorted(self.keys, keys)
        return self.starts[idx], self.starts[idx + 1] - self.starts[idx]

    def ensure(self, keys: np.ndarray) -> None:
        """Answer the distinct sorted ``keys`` the table lacks with the live human, and store them."""
        if len(self.keys):
            idx = np.minimum(np.searchsorted(self.keys, keys), len(self.keys) - 1)
            missing = keys[self.keys[idx] != keys]
        else:
            missing = keys
        if not len(missing):
            return
        states, seen = self.packer.unpack(missing)
        acts: list[int] = []
        probs: list[float] = []
        sizes = np.zeros(len(missing), dtype=np.int64)
        world, distribution = self.world, self.human.distribution
        for i in range(len(missing)):
            if self.budget is not None and i % CHECK_EVERY == 0:
                self.budget.check(self.phase, i, len(missing), "partner answers of this step", memory=i % 1024 == 0)
            dist = [(h, p) for h, p in distribution(world, states.state(i), int(seen[i])) if p > 0.0]
            sizes[i] = len(dist)
            acts += [h for h, _ in dist]
            probs += [p for _, p in dist]
        self.live_calls += len(missing)
        self._merge(missing, sizes, np.array(acts, dtype=np.int64), np.array(probs, dtype=np.float64))

    def _merge(self, keys: np.ndarray, sizes: np.ndarray, actions: np.ndarray, probs: np.ndarray) -> None:
        old_sizes = np.diff(self.starts)
        all_keys = np.concatenate([self.keys, keys])
        all_sizes = np.concatenate([old_sizes, sizes])
        order = np.argsort(all_keys, kind="stable")
        seg_start = np.concatenate([self.starts[:-1], len(self.actions) + np.concatenate([[0], np.cumsum(sizes)[:-1]])])
        flat_a = np.concatenate([self.actions, actions])
        flat_p = np.concatenate([self.probs, probs])
        sizes_sorted = all_sizes[order]
        new_starts = np.concatenate([[0], np.cumsum(sizes_sorted)]).astype(np.int64)
        gather = np.repeat(seg_start[order] - new_starts[:-1], sizes_sorted) + np.arange(new_starts[-1])
        self.keys = all_keys[order]
        self.starts = new_starts
        self.actions = flat_a[gather]
        self.probs = flat_p[gather]
