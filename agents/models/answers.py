"""The partner's answers as arrays: a distribution per (mid-cycle state, robot action seen), stepped.

The model builder asks for the answers of a whole batch of distinct mid-cycle keys at
once. :class:`AnswerTable` keeps them as a compiled partner does (``agents/compiled.py``):
sorted packed keys, segment starts, actions and probabilities, looked up with one
``searchsorted``, and per entry the answer's outcome (the next robot-turn state's key,
as is and in canonical labelling, and the answer's duration), stepped once with the
batched rules when the entry is made. Keys the table lacks are answered on arrays where
the human's rule allows (``partners.py``), by the live human once per canonical key where
it is equivariant (``equivariant.py``), else by the live human once per key; a budget is
read every :data:`CHECK_EVERY` live answers: a planner-driven human may spend a search on one.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.models.budget import Budget
from hg_marl.agents.models.equivariant import canonical_answers
from hg_marl.agents.models.keyed import Searches, SegmentTable, known
from hg_marl.agents.models.live import Asked, LiveAnswers, questions
from hg_marl.agents.models.packing import StatePacker
from hg_marl.agents.models.partners import Answers, batch_answers
from hg_marl.core import Agent, World
from hg_marl.core.errors import HumanError
from hg_marl.core.spec import AgentSpec
from hg_marl.envs.batched import BatchedRules, BatchState

CHECK_EVERY = 4
"""Live answers computed between two budget readings (one answer may cost a planner search; the
time budget's timer, ``Budget.deadline``, interrupts a long one anyway)."""

FIELDS = {"actions": np.int64, "probs": np.float64, "next": np.int64, "canonical": np.int64, "d_human": np.float64}
"""Per-entry arrays (a key's entries are contiguous, at :meth:`AnswerTable.lookup`'s positions)."""


class KeyBatch:
    """Distinct sorted mid-cycle keys, unpacked and with the human's masks, each computed once when first read.

    Why: a joint model's partners are asked the same keys at each step of the build
    (twenty on the headroom's), and unpacking them and computing the human's masks
    once, not once per partner, is about a third of the build. Readers must not change
    the arrays (:meth:`AnswerTable.ensure` steps copies).
    """

    def __init__(self, packer: StatePacker, rules: BatchedRules, keys: np.ndarray) -> None:
        self.packer, self.rules, self.keys = packer, rules, keys
        self._unpacked: tuple[BatchState, np.ndarray] | None = None
        self._mask: np.ndarray | None = None
        self._subset: tuple[np.ndarray, KeyBatch] | None = None
        self._derived: dict[str, Any] = {}
        self.searches = Searches()
        """The tables' look-ups of these keys, made once for tables holding the same keys."""

    @property
    def unpacked(self) -> tuple[BatchState, np.ndarray]:
        """The states and the robot actions seen (:meth:`StatePacker.unpack`)."""
        if self._unpacked is None:
            self._unpacked = self.packer.unpack(self.keys)
        return self._unpacked

    @property
    def mask(self) -> np.ndarray:
        """The human's masks of the states (:meth:`BatchedRules.masks`)."""
        if self._mask is None:
            self._mask = self.rules.masks(self.unpacked[0], Agent.HUMAN)
        return self._mask

    def derived(self, name: str, make: Callable[[], Any]) -> Any:
        """``make()``, computed once for every partner that asks for ``name`` (``partners.Shared``)."""
        if name not in self._derived:
            self._derived[name] = make()
        return self._derived[name]

    def rows(self, rows: np.ndarray) -> KeyBatch:
        """The keys at ``rows``, kept for the next table that lacks the same (what is computed is taken)."""
        if self._subset is not None and np.array_equal(self._subset[0], rows):
            return self._subset[1]
        out = KeyBatch(self.packer, self.rules, self.keys[rows])
        self._subset = (rows, out)
        if self._unpacked is not None:
            b, seen = self._unpacked
            out._unpacked = (b.take(rows), seen[rows])
        if self._mask is not None:
            out._mask = self._mask[rows]
        return out


class AnswerTable:
    """A stationary human's answers by packed (state, seen) key, grown on demand.

    Args:
        world: the world.
        human: a reset stationary human with ``distribution(world, state, robot_action)``.
        packer: the builder's packer (keys include the robot action seen).
        budget: read between live answers (phase :attr:`phase`).
        arrays: answer on arrays where the human has an array version (False: always live).
        batch: answers on arrays to use instead of the human's (the human may then be None).
        jobs: worker processes for the live human's answers (0: one per CPU; ``live.py``): the answers
            do not depend on it; with more than one, :meth:`close` the table when the model is built.
    """

    def __init__(
        self,
        world: World,
        human: Any,
        packer: StatePacker,
        budget: Budget | None = None,
        arrays: bool = True,
        batch: Answers | None = None,
        jobs: int = 1,
    ) -> None:
        self.world, self.human, self.packer = world, human, packer
        self.live = LiveAnswers(world, human, jobs)
        """Asks the live human, in ``jobs`` forked workers (``agents/models/live.py``); close with :meth:`close`."""
        self.budget = budget
        self.rules = BatchedRules(world)
        self.uses_robot_action = bool(getattr(human, "uses_robot_action", False))
        self.table = SegmentTable(FIELDS)
        self.batch = batch or (batch_answers(world, human) if arrays else None)
        """The human's answers on arrays (``agents/models/partners.py``), None to ask it live."""
        self.canonical = canonical_answers(world, human, packer, self.live) if arrays and self.batch is None else None
        """An equivariant human asked once per canonical key (``agents/models/equivariant.py``)."""
        self.live_calls = 0
        """Distributions asked of the live human (the rest came from the table)."""
        self.relabelled: bool | None = None
        """Whether entries carry their next state's canonical key (the builder sets it on a new
        table: a model without symmetry reduction never reads it); None: computed."""
        self.phase = "answers"
        self._pending: list[tuple[np.ndarray, Asked]] = []
        """Keys handed to the live human by :meth:`prefetch`, and their answers to come, oldest first."""
        self._inflight: list[np.ndarray] = []
        """The keys of every :meth:`prefetch` not stored yet (a later prefetch leaves them out)."""

    @property
    def keys(self) -> np.ndarray:
        """The keys answered, sorted."""
        return self.table.keys

    @property
    def entries(self) -> dict[str, np.ndarray]:
        """Per-entry arrays by :data:`FIELDS` name (positions from :meth:`lookup`)."""
        return self.table.entries

    def lookup(
        self, keys: np.ndarray, at: np.ndarray | None = None, searches: Searches | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """(first entry, entry count) per key; every key must be known (see :meth:`ensure`).

        ``at``: the keys' positions among :attr:`keys` where known; ``searches``: where other
        tables are asked the same keys (:meth:`SegmentTable.lookup`).
        """
        return self.table.lookup(keys, at, searches)

    def compact(self) -> tuple[np.ndarray, np.ndarray, dict[str, np.ndarray]]:
        """(keys, starts, entries), key ``i``'s entries at ``starts[i]:starts[i + 1]``: as compiled partners store."""
        return self.table.compact()

    def ensure(self, keys: np.ndarray, batch: KeyBatch | None = None) -> None:
        """Answer the distinct sorted ``keys`` the table lacks with the live human, and store them.

        ``batch``: the same keys as a :class:`KeyBatch` shared with other tables (their
        unpacking and masks are then computed once for all).
        """
        lack = self.table.lacks(keys, None if batch is None else batch.searches)
        if not lack.any():
            return
        batch = self._rows_lacking(keys, lack, batch)
        missing = batch.keys
        states, seen = batch.unpacked
        if self.batch is not None:
            if self.budget is not None:
                self.budget.check(self.phase, 0, len(missing), "partner answers on arrays")
            size, actions, probs_arr = self.batch(states, batch)
            self._store(batch, size, actions, probs_arr)
            return
        if self.canonical is not None:
            before = self.canonical.live_calls
            size, actions, probs_arr = self.canonical(states, seen, self._check)
            self.live_calls += self.canonical.live_calls - before
            self._store(batch, size, actions, probs_arr)
            return
        answered = None
        while answered is None and self._pending:  # prefetches are collected in the order they were made
            keys_asked, asked = self._pending.pop(0)
            if np.array_equal(keys_asked, missing):
                answered = asked.collect(self._check)
            else:  # another batch's, made before this one's: dropped (the builder never does this)
                asked.collect(self._check)
                self._inflight = [k for k in self._inflight if k is not keys_asked]
        if answered is None:
            asked_now = questions(states.where, states.robot_at, states.offer_by, states.offer_obj, seen)
            answered = self.live(asked_now, self._check)
        self.live_calls += len(missing)
        self._store(batch, *answered)

    def _rows_lacking(self, keys: np.ndarray, lack: np.ndarray, batch: KeyBatch | None) -> KeyBatch:
        """The keys the table lacks as a :class:`KeyBatch` (of ``batch``'s rows where given: shared)."""
        if batch is None:
            return KeyBatch(self.packer, self.rules, keys[lack])
        return batch if lack.all() else batch.rows(np.flatnonzero(lack))

    @property
    def answers_live(self) -> bool:
        """Whether keys the table lacks are answered by the live human (not on arrays)."""
        return self.batch is None

    def prefetch(self, keys: np.ndarray, batch: KeyBatch | None = None) -> None:
        """Start the live human's answers to the distinct sorted ``keys`` the table lacks, in its workers.

        The next :meth:`ensure` of the same keys (and ``batch``) collects them instead of
        asking: the builder steps the other partners' answers meanwhile. What storing the
        answers needs of the states (their unpacking, the human's masks) is computed here,
        while the workers search. Several batches may be prefetched before the first is
        collected (the builder asks for the next batch's while this one's are searched):
        keys an earlier prefetch asked are left out, and each ensure collects the
        prefetches in the order they were made. Nothing starts without workers or for a
        human answered on arrays.
        """
        if self.batch is not None or not self.live.workers.parallel:
            return
        lack = self.table.lacks(keys)
        for earlier in self._inflight:  # asked by an earlier prefetch, stored by that batch's ensure
            lack = lack & ~known(earlier, keys)
        if not lack.any():
            return
        batch = self._rows_lacking(keys, lack, batch)
        states, seen = batch.unpacked
        if self.canonical is not None:
            self.canonical.prefetch(states, seen)
        else:
            asked = questions(states.where, states.robot_at, states.offer_by, states.offer_obj, seen)
            self._pending.append((batch.keys, self.live.submit(asked)))
        self._inflight.append(batch.keys)
        _ = batch.mask  # computed now, read by the ensure that stores the answers

    def close(self) -> None:
        """Stop the live human's worker processes, if it has any (a later :meth:`ensure` forks new ones).

        Answers prefetched and not collected are dropped with the workers (a later
        :meth:`ensure` asks for them again).
        """
        self.live.close()
        self._pending, self._inflight = [], []
        if self.canonical is not None:
            self.canonical.drop_pending()

    def _check(self, i: int, total: int) -> None:
        if self.budget is not None and i % CHECK_EVERY == 0:
            self.budget.check(self.phase, i, total, "partner answers of this step", memory=i % 4096 == 0)

    def _store(self, batch: KeyBatch, size: np.ndarray, actions: np.ndarray, probs: np.ndarray) -> None:
        """Step the answers of the keys of ``batch`` once and merge them into the table."""
        rep = np.repeat(np.arange(len(size)), size)
        b = batch.unpacked[0].take(rep)  # a copy: stepped in place
        _, d_human, _ = self.rules.step(b, Agent.HUMAN, actions, batch.mask[rep])
        nxt = self.packer.pack(b)
        if self.relabelled is not False:
            self.packer.canonical(b)
        new = {
            "actions": actions,
            "probs": probs.astype(np.float64, copy=False),
            "next": nxt,
            "canonical": nxt if self.relabelled is False else self.packer.pack(b),
            "d_human": d_human,
        }
        self.table.add(batch.keys, size, new, batch.searches)
        self._inflight = [k for k in self._inflight if self.table.lacks(k).any()]


def stationary_human(human: Any, world: World) -> Any:
    """``human`` ready to answer as a model's partner: built (from a spec's text or an
    :class:`~hg_marl.core.spec.AgentSpec`; an instance is used as it is), checked stationary
    (it has ``distribution(world, state, seen)``) and reset.

    Raises:
        HumanError: a human without a distribution (switching and replay are not stationary).
    """
    if isinstance(human, AgentSpec):
        human = make_human(human.name, **human.params)
    elif isinstance(human, str):
        human = make_human(human)
    if not callable(getattr(human, "distribution", None)):
        raise HumanError(
            f"the oracle needs a stationary human with distribution(world, state); {getattr(human, 'name', human)!r} "
            "has none (switching and replay humans are not stationary: run the oracle per phase)"
        )
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    return human
