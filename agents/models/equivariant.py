"""An equivariant partner's answers asked once per canonical state and mapped back on arrays.

A partner is *equivariant* when relabelling interchangeable objects in the state relabels
its answer (``equivariant = True``: the planner-driven ``cooperative`` and ``noisy``), and
some read the robot's action seen only through a class of actions answered alike
(``seen_representatives``: the cooperative human's planner reads its duration and
whether it is a wait or a give). Its answer at a mid-cycle state is then its answer at
the canonical state (:meth:`~hg_marl.agents.models.packing.StatePacker.canonical`), seen
the class's representative, with each action's object mapped back through the
relabelling. :class:`CanonicalAnswers` asks the live partner once per such canonical key
(its own rule, unchanged: nothing is restated here) and answers every other key of a
batch with array look-ups: on ``roboergosum``'s headroom model the cooperative human's
2.5 million (state, robot action seen) keys are 57 thousand canonical ones.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.models.keyed import SegmentTable, known, ranges, unique_first_inverse
from hg_marl.agents.models.live import Asked, Check, LiveAnswers, Row, questions
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import Agent, Kind, World
from hg_marl.core.relabel import Relabel
from hg_marl.envs.batched import BatchState

KEPT = 4
"""Prefetched batches whose canonical keys are kept for their call at most (the builder has two)."""


def canonical_answers(
    world: World, human: Any, packer: StatePacker, live: LiveAnswers | None = None
) -> CanonicalAnswers | None:
    """The canonical-key answers of ``human`` (asked through ``live``), or None if it is not equivariant so."""
    if not getattr(human, "equivariant", False):
        return None
    uses = bool(getattr(human, "uses_robot_action", False))
    if uses and not callable(getattr(human, "seen_representatives", None)):
        return None
    return CanonicalAnswers(world, human, packer, live)


def object_slots(world: World, agent: Agent) -> tuple[np.ndarray, np.ndarray]:
    """(slot, remap): the object each action names (-1: none) and ``remap[a, o]``, action ``a`` on object ``o``.

    Built with :meth:`Relabel.action_back` itself (the relabelling's one definition): an
    ``orig`` with ``o`` at the action's object is all it reads.
    """
    table, relabel = world.table, Relabel(world)
    n = table.n_objects
    specs = table.specs[agent]
    slot = np.full(len(specs), -1, dtype=np.int64)
    remap = np.repeat(np.arange(len(specs), dtype=np.int64)[:, None], n, axis=1)
    for a, (kind, obj, target, _) in enumerate(specs):
        j = obj if obj >= 0 else (target if kind is Kind.GOTO and target < n else -1)
        if j < 0:
            continue
        slot[a] = j
        for o in range(n):
            orig = list(range(n))
            orig[j] = o
            remap[a, o] = relabel.action_back(int(agent), a, tuple(orig))
    return slot, remap


def canonical_copy(packer: StatePacker, states: BatchState) -> tuple[BatchState, np.ndarray]:
    """A copy of ``states`` relabelled into canonical form, and ``orig`` (:meth:`StatePacker.canonical`)."""
    canon = BatchState(states.where.copy(), states.robot_at.copy(), states.offer_by.copy(), states.offer_obj.copy())
    return canon, packer.canonical(canon)


def actions_back(
    slot: np.ndarray, remap: np.ndarray, actions: np.ndarray, orig: np.ndarray, rows: np.ndarray
) -> np.ndarray:
    """Each action of the canonical labelling, answered for row ``rows[i]``, on that row's own objects.

    ``slot`` and ``remap`` are :func:`object_slots`' for the acting agent; an action that
    names no object is its own.
    """
    named = slot[actions]
    return np.where(named >= 0, remap[actions, orig[rows, np.maximum(named, 0)]], actions)


class CanonicalAnswers:
    """Answers by canonical (state, representative seen) key; the live partner asked once per key."""

    def __init__(self, world: World, human: Any, packer: StatePacker, live: LiveAnswers | None = None) -> None:
        self.world, self.human, self.packer = world, human, packer
        self.live = live or LiveAnswers(world, human)
        """Asks the live partner (in forked workers where it was given jobs)."""
        self.uses_robot_action = bool(getattr(human, "uses_robot_action", False))
        reps = human.seen_representatives(world) if self.uses_robot_action else []
        self.rep = np.array([*reps, -1], dtype=np.int64)
        """``rep[seen]``: the representative of the robot action seen (``seen = -1``: -1)."""
        self.slot, self.remap = object_slots(world, Agent.HUMAN)
        self.table = SegmentTable({"actions": np.int64, "probs": np.float64})
        """The partner's answers by canonical key (actions in canonical labelling)."""
        self.live_calls = 0
        """Distributions asked of the live partner (one per canonical key)."""
        self._pending: list[tuple[np.ndarray, Asked]] = []
        """Keys handed to the live partner by :meth:`prefetch`, and their answers to come, oldest first."""
        self._kept: list[tuple[BatchState, np.ndarray, Any]] = []
        """The prefetched batches not answered yet (states and seen, by identity) and their canonical keys."""

    def __call__(self, states: BatchState, seen: np.ndarray, check: Check) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(entries per state, actions, probabilities) of a batch, entries in index order per state."""
        at = next((i for i, (b, s, _) in enumerate(self._kept) if b is states and s is seen), None)
        if at is not None:  # a prefetched batch (those prefetched before it are not asked any more)
            canon, orig, rep, keys, uniq, first, inv = self._kept[at][2]
            del self._kept[: at + 1]
        else:
            canon, orig, rep, keys, uniq, first, inv = self._keys(states, seen)
        self._ask(uniq, first, canon, rep, check)
        start, size = self.table.lookup(uniq)
        start, size = start[inv], size[inv]
        rows = np.repeat(np.arange(len(keys)), size)
        entry = ranges(start, size)
        entries = self.table.entries
        back = actions_back(self.slot, self.remap, entries["actions"][entry], orig, rows)
        order = np.lexsort((back, rows))  # the live partner lists a distribution in index order
        return size, back[order], entries["probs"][entry][order]

    def prefetch(self, states: BatchState, seen: np.ndarray) -> None:
        """Start asking the live partner for the canonical keys of a batch that neither the table nor an
        earlier prefetch holds (the batch's keys are kept for its call)."""
        computed = self._keys(states, seen)
        canon, _, rep, _, uniq, first, _ = computed
        new = ~known(self.table.keys, uniq)
        for asked, _ in self._pending:
            new &= ~known(asked, uniq)
        at = np.flatnonzero(new)
        if len(at):
            self._pending.append((uniq[at], self.live.submit(self._questions(first[at], canon, rep))))
        self._kept = [*self._kept[1 - KEPT :], (states, seen, computed)]  # the same batch's call reads them back

    def drop_pending(self) -> None:
        """Forget every prefetch whose workers were stopped (their keys are asked again when needed)."""
        self._pending, self._kept = [], []

    def _keys(
        self, states: BatchState, seen: np.ndarray
    ) -> tuple[BatchState, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The canonical batch, ``orig``, the representatives seen, the keys, and their distinct ones."""
        canon, orig = canonical_copy(self.packer, states)
        rep = self.rep[seen] if self.uses_robot_action else np.full(len(seen), -1, dtype=np.int64)
        keys = self.packer.pack(canon, rep)
        uniq, first, inv = unique_first_inverse(keys)
        return canon, orig, rep, keys, uniq, first, inv

    @staticmethod
    def _questions(rows: np.ndarray, canon: BatchState, rep: np.ndarray) -> list[Row]:
        at = rows.tolist()
        return questions(canon.where[at], canon.robot_at[at], canon.offer_by[at], canon.offer_obj[at], rep[at])

    def _ask(self, uniq: np.ndarray, first: np.ndarray, canon: BatchState, rep: np.ndarray, check: Check) -> None:
        """Ask the live partner for the canonical keys of ``uniq`` not known yet, and store them.

        The prefetches are collected in the order they were made while this batch lacks keys
        (their answers are the partner's whichever batch asks for them), so a batch that was
        prefetched asks nothing more, and a later batch's prefetch is left in its workers.
        """
        lacking = ~known(self.table.keys, uniq)
        while self._pending and lacking.any():
            keys, asked = self._pending.pop(0)
            sizes, acts, probs = asked.collect(check)
            self.live_calls += len(keys)
            self.table.add(keys, sizes, {"actions": acts, "probs": probs})
            lacking &= ~known(keys, uniq)
        new = np.flatnonzero(lacking)
        if not len(new):
            return
        sizes, acts, probs = self.live(self._questions(first[new], canon, rep), check)
        self.live_calls += len(new)
        self.table.add(uniq[new], sizes, {"actions": acts, "probs": probs})
