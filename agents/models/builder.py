"""The exact semi-MDP of a scenario against a stationary partner, built breadth-first on arrays.

States are packed into int64 keys (:class:`~hg_marl.agents.models.packing.StatePacker`).
A level of the breadth-first search is a batch of robot-turn states: the robot's
options are read from :meth:`BatchedRules.masks` (every feasible action, in index order,
then the first infeasible one standing for them all, as the oracle models them), stepped
with :meth:`BatchedRules.step`; the distinct mid-cycle keys (hashed: ``keyed.py``) get the
partner's answers from an :class:`~hg_marl.agents.models.answers.AnswerTable` (arrays,
grown by the live human for keys it lacks), which are stepped again; the next states'
keys are deduplicated against the sorted known keys with ``searchsorted``. Nothing here
is written per state in Python except the live partner's answers.

The result, :class:`Model`, is the oracle's model (``agents/oracle.py``): pairs (state,
robot action) contiguous per state, transitions per pair in CSR form (``t_start``) with
probabilities and cycle seconds ``max(d_robot, d_human)``, the completing ``wait``
marked terminal, and the regeneration (the re-drawn tables and the partner's first answer
on them). A test builds it beside the oracle's Python enumeration and requires the same
states, transitions and rates.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
from scipy import sparse
from tqdm import tqdm

from hg_marl.agents.models.answers import AnswerTable, KeyBatch
from hg_marl.agents.models.budget import Budget, trim_heap
from hg_marl.agents.models.keyed import (
    first_unique,
    nonzero_2d,
    positions,
    ranges,
    starts_of,
    unique,
    unique_inverse,
)
from hg_marl.agents.models.lazy import TableTransitions
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchedRules, BatchState

CHUNK = 1 << 15
"""Robot-turn states expanded per batch at most (bounds the batch's arrays; the budget is read per batch)."""
FIRST_CHUNK = 64
"""The first batch's size, doubled per batch up to :data:`CHUNK`: a states budget is then
overrun by at most one batch's discoveries while the model is small, and a large model is
still built in large batches."""


@dataclass
class Dynamics:
    """One partner's transitions on a model: CSR over pairs, and its regeneration."""

    t_start: np.ndarray
    """(pairs + 1,) transitions of pair ``p`` are ``t_start[p]:t_start[p + 1]``."""
    t_next: np.ndarray
    t_prob: np.ndarray
    t_tau: np.ndarray
    regen_next: np.ndarray
    """The re-drawn tables after the partner's first answer (state ids), with probability and seconds."""
    regen_prob: np.ndarray
    regen_tau: np.ndarray

    @cached_property
    def t_pair(self) -> np.ndarray:
        """The pair of each transition (computed once: the certain states, the costs and the sweeps read it)."""
        return np.repeat(np.arange(len(self.t_start) - 1), np.diff(self.t_start))


@dataclass
class Model:
    """A semi-MDP on packed robot-turn states (ids are positions in ``keys``), one dynamics per partner."""

    packer: StatePacker
    keys: np.ndarray
    """(n,) the packed state of each id."""
    pair_start: np.ndarray
    """(n + 1,) pairs of state ``s`` are ``pair_start[s]:pair_start[s + 1]``."""
    pair_action: np.ndarray
    pair_terminal: np.ndarray
    """Whether the pair is the completing ``wait`` (worth 1, followed by the re-draw)."""
    dynamics: list[Dynamics]
    """Per partner (the builder's ``answers`` in order); the state set is closed under all of them."""
    n_layouts: int
    partner: int = 0
    """The partner the ``t_*`` and ``regen_*`` shortcuts and the solver read."""
    lazy: TableTransitions | None = None
    """``build_model(keep=False)``: the transitions are read from the answer tables."""

    def chain(self, partner: int) -> Dynamics:
        """Partner ``partner``'s transitions (built from its answer table when not kept)."""
        if self.lazy is None:
            return self.dynamics[partner]
        t_start, t_next, t_prob, t_tau, t_pair = self.lazy.every(partner, self.pair_terminal)
        regen_next, regen_prob, regen_tau = self.lazy.regen[partner]
        chain = Dynamics(t_start, t_next, t_prob, t_tau, regen_next, regen_prob, regen_tau)
        chain.t_pair = t_pair  # known here: not computed again
        return chain

    def regen(self, partner: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Partner ``partner``'s re-draw: next states, probabilities, seconds."""
        if self.lazy is not None:
            return self.lazy.regen[partner]
        d = self.dynamics[partner]
        return d.regen_next, d.regen_prob, d.regen_tau

    def gather(self, partner: int, pairs: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The transitions of ``pairs`` only: (starts, next state, probability, seconds), CSR over ``pairs``."""
        if self.lazy is None:
            d = self.dynamics[partner]
            lo, size = d.t_start[pairs], d.t_start[pairs + 1] - d.t_start[pairs]
            at = ranges(lo, size)
            return starts_of(size), d.t_next[at], d.t_prob[at], d.t_tau[at]
        return self.lazy.gather(partner, pairs, self.pair_terminal)

    def of(self, partner: int) -> Model:
        """The same model read for another partner (arrays shared)."""
        return replace(self, partner=partner)

    @property
    def t_start(self) -> np.ndarray:
        return self.dynamics[self.partner].t_start

    @property
    def t_next(self) -> np.ndarray:
        return self.dynamics[self.partner].t_next

    @property
    def t_prob(self) -> np.ndarray:
        return self.dynamics[self.partner].t_prob

    @property
    def t_tau(self) -> np.ndarray:
        return self.dynamics[self.partner].t_tau

    @property
    def regen_next(self) -> np.ndarray:
        return self.dynamics[self.partner].regen_next

    @property
    def regen_prob(self) -> np.ndarray:
        return self.dynamics[self.partner].regen_prob

    @property
    def regen_tau(self) -> np.ndarray:
        return self.dynamics[self.partner].regen_tau

    @property
    def n(self) -> int:
        """Robot-turn states."""
        return len(self.keys)

    @property
    def n_pairs(self) -> int:
        """(state, robot action) pairs."""
        return len(self.pair_action)

    def transitions(self) -> sparse.csr_matrix:
        """(pairs, states) probabilities as CSR."""
        return sparse.csr_matrix((self.t_prob, self.t_next, self.t_start), shape=(self.n_pairs, self.n))

    def pair_state(self) -> np.ndarray:
        """The state of each pair."""
        return np.repeat(np.arange(self.n), np.diff(self.pair_start))

    def t_pair(self) -> np.ndarray:
        """The pair of each transition (int32 where the pairs fit: the largest array the solver adds)."""
        dtype = np.int32 if self.n_pairs <= np.iinfo(np.int32).max else np.int64
        return np.repeat(np.arange(self.n_pairs, dtype=dtype), np.diff(self.t_start))

    def states(self) -> list[State]:
        """The states as :class:`State` tuples, by id (for tests and small models)."""
        b, _ = self.packer.unpack(self.keys)
        return [b.state(i) for i in range(len(b))]


class _Index:
    """Known state keys, sorted, with their ids; ids in order of discovery."""

    def __init__(self) -> None:
        self.sorted = np.zeros(0, dtype=np.int64)
        self.ids = np.zeros(0, dtype=np.int64)
        self.by_id: list[np.ndarray] = []
        self.n = 0

    def add(self, keys: np.ndarray) -> np.ndarray:
        """Give ids to the keys not known yet (``keys`` distinct, in the order ids are wanted); every key's id."""
        pos = np.searchsorted(self.sorted, keys)
        if len(self.sorted):
            at = np.minimum(pos, len(self.sorted) - 1)
            hit = self.sorted[at] == keys
            out = self.ids[at]  # a key not known yet gets its new id below
        else:
            hit, out = np.zeros(len(keys), dtype=bool), np.empty(len(keys), dtype=np.int64)
        fresh = np.flatnonzero(~hit)
        new = keys[fresh]
        ids = np.arange(self.n, self.n + len(new), dtype=np.int64)
        out[fresh] = ids
        if len(new):
            where = pos[fresh]
            if np.any(new[1:] < new[:-1]):  # distinct keys given unsorted (the builder's are sorted)
                order = np.argsort(new)
                where, new_sorted, ids_sorted = where[order], new[order], ids[order]
            else:
                new_sorted, ids_sorted = new, ids
            self.sorted = np.insert(self.sorted, where, new_sorted)
            self.ids = np.insert(self.ids, where, ids_sorted)
            self.by_id.append(new)
            self.n += len(new)
        return out

    def id_of(self, keys: np.ndarray) -> np.ndarray:
        """Ids of known keys."""
        return self.ids[positions(self.sorted, keys)]

    def keys(self) -> np.ndarray:
        return np.concatenate([np.zeros(0, dtype=np.int64), *self.by_id])  # in order of their ids

    def keys_between(self, lo: int, hi: int) -> np.ndarray:
        """``keys()[lo:hi]``, copying only the batches of ids it overlaps (not every key known)."""
        parts, start = [], 0
        for block in self.by_id:
            end = start + len(block)
            if end > lo and start < hi:
                parts.append(block[max(lo - start, 0) : hi - start])
            start = end
        return parts[0] if len(parts) == 1 else np.concatenate([np.zeros(0, dtype=np.int64), *parts])


@dataclass
class _Front:
    """A batch's robot side, stepped before any partner answers it: its pairs and distinct mid-cycle keys.

    Why apart: while one batch's live answers are searched in the workers, the next
    batch's front is computed and its searches queued behind them (its boundary does not
    depend on what this batch finds once enough states are known), so the workers do
    not wait for this process between batches.
    """

    hi: int
    """The end of the states it read (``lo`` plus their number: a front asked past the known states
    ends where they end, and is not taken for the batch of a later boundary)."""
    ps: np.ndarray
    """The state of each pair, as a row of the batch."""
    pa: np.ndarray
    d_robot: np.ndarray
    terminal: np.ndarray
    live: np.ndarray
    """The pairs that are not the completing ``wait``."""
    mids: tuple[np.ndarray, np.ndarray]
    """The live pairs' mid-cycle keys, with and without the robot action seen."""
    distinct: dict[bool, tuple[np.ndarray, np.ndarray]]
    """Per kind of key (seen or not): the distinct keys sorted, and each live pair's among them."""
    shared: dict[bool, KeyBatch]

    @classmethod
    def of(
        cls,
        rules: BatchedRules,
        packer: StatePacker,
        index: _Index,
        lo: int,
        hi: int,
        tables: list[AnswerTable],
        failed_actions: bool,
    ) -> _Front:
        """The front of the known states ``lo:hi`` (those of them that are known)."""
        b, _ = packer.unpack(index.keys_between(lo, hi))
        hi = lo + len(b)
        mask = rules.masks(b, Agent.ROBOT)
        n_robot = rules.n_actions[Agent.ROBOT]
        if failed_actions:  # an extra column: the first infeasible action, after the feasible ones
            fails = np.logical_not(mask.all(axis=1)).reshape(-1, 1)
            ps, pa = nonzero_2d(np.concatenate([mask, fails], axis=1))  # row-major: in option order
            failing = pa == n_robot
            pa[failing] = np.argmin(mask[ps[failing]], axis=1)
            feasible = ~failing
        else:
            ps, pa = nonzero_2d(mask)
            feasible = np.ones(len(pa), dtype=bool)
        pb = b.take(ps)
        ok, d_robot, reward = rules.step(pb, Agent.ROBOT, pa, ok=feasible)
        terminal = reward > 0  # the rules' own reward: a wait on a clean table completes the task
        live = np.flatnonzero(~terminal)
        plain = packer.pack(pb)[live]
        mids = (packer.seen(plain, np.where(ok[live], pa[live], -1)), plain)
        distinct: dict[bool, tuple[np.ndarray, np.ndarray]] = {}
        shared: dict[bool, KeyBatch] = {}
        for uses in sorted({t.uses_robot_action for t in tables}):
            distinct[uses] = unique_inverse(mids[0 if uses else 1])
            shared[uses] = KeyBatch(packer, rules, distinct[uses][0])
        return cls(hi, ps, pa, d_robot, terminal, live, mids, distinct, shared)

    def prefetch(self, tables: list[AnswerTable]) -> None:
        """Start the live partners' searches of the batch's keys (nothing for the others, or asked already)."""
        for t in tables:
            if t.answers_live:
                t.prefetch(self.distinct[t.uses_robot_action][0], self.shared[t.uses_robot_action])


class _Answered:
    """Answers of distinct mid-cycle keys: per key a block of (next key, probability, seconds)."""

    def __init__(self, table: AnswerTable, mids: np.ndarray, canonical: bool, batch: KeyBatch | None = None) -> None:
        table.ensure(mids, batch)
        start, size = table.lookup(mids, searches=None if batch is None else batch.searches)
        self.block = np.concatenate([[0], np.cumsum(size)]).astype(np.int64)
        entry = np.repeat(start - self.block[:-1], size) + np.arange(self.block[-1])
        e = table.entries
        self.next = e["canonical" if canonical else "next"][entry]
        self.prob = e["probs"][entry]
        self.d_human = e["d_human"][entry]
        self.size = size


def _regen(
    world: World, table: AnswerTable, lay: BatchState, lay_p: np.ndarray, canonical: bool
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The partner's first answer on each re-drawn table: (next key, probability, seconds) flat."""
    wait = world.table.wait[Agent.ROBOT]
    table.phase = "first answers"
    mid = table.packer.pack(lay, np.full(len(lay), wait if table.uses_robot_action else -1, dtype=np.int64))
    u, inv = unique_inverse(mid)
    first = _Answered(table, u, canonical)
    count = first.size[inv]
    rows = np.repeat(np.arange(len(lay)), count)
    entry = np.repeat(first.block[inv] - np.concatenate([[0], np.cumsum(count)[:-1]]), count) + np.arange(len(rows))
    return first.next[entry], lay_p[rows] * first.prob[entry], np.maximum(world.durations.wait, first.d_human[entry])


def build_model(
    world: World,
    answers: AnswerTable | Sequence[AnswerTable],
    layouts: list[tuple[State, float]],
    *,
    failed_actions: bool = True,
    canonical: bool = False,
    budget: Budget | None = None,
    progress: bool = False,
    label: str = "model",
    keep: bool = True,
) -> Model:
    """The model reachable from ``layouts`` (already canonical when ``canonical``) against ``answers``.

    ``answers``: one partner, or several (the states are then closed under every
    partner's answers, each partner's transitions kept apart: the headroom's joint model).
    ``canonical``: keep one state per relabelling class (equivariant partners, as the
    oracle's symmetry reduction). The budget is read per batch of states (phase
    ``"explore"``) and between the partners' live answers; its states budget counts the
    states known. ``keep=False``: the transitions are not kept per partner but read from
    the partners' answer tables when asked (:meth:`Model.chain`, :meth:`Model.gather`):
    a pair's transitions are its mid-cycle key's answers, and the keys are fewer than
    the pairs (the headroom's joint model of 21 partners fits in its memory budget).
    """
    tables = [answers] if isinstance(answers, AnswerTable) else list(answers)
    budget = budget or Budget(None, None, None)
    rules = BatchedRules(world)
    packer = tables[0].packer
    lay = BatchState.of([s for s, _ in layouts])
    lay_p = np.array([p for _, p in layouts], dtype=np.float64)
    for t in tables:
        if not len(t.keys):
            t.relabelled = canonical  # a model without the reduction never reads them
        elif canonical and t.relabelled is False:
            raise ValueError("an answer table filled without canonical keys cannot serve a reduced model")
    regen = [_regen(world, t, lay, lay_p, canonical) for t in tables]
    index = _Index()
    index.add(first_unique(np.concatenate([packer.pack(lay), *(r[0] for r in regen)])))
    budget.check("explore", 0, unit=f"states explored ({index.n:,} known)", states=index.n)
    for t in tables:
        t.phase = "explore: partner answers"
    parts: dict[str, list[np.ndarray]] = {
        k: [] for k in ("size", "action", "terminal", "mid_seen", "mid_plain", "d_robot")
    }
    flows: list[dict[str, list[np.ndarray]]] = [{k: [] for k in ("tcount", "next", "prob", "tau")} for _ in tables]
    bar = tqdm(
        desc=f"{label}: states", unit=" states", disable=not progress, file=sys.stderr, dynamic_ncols=True, leave=False
    )
    lo, size = 0, FIRST_CHUNK
    ahead: _Front | None = None
    try:
        while lo < index.n:
            hi = min(lo + size, index.n)
            size = min(2 * size, CHUNK)
            budget.check("explore", lo, unit=f"states explored ({index.n:,} known)", states=index.n)
            front = (
                ahead
                if ahead is not None and ahead.hi == hi
                else _Front.of(rules, packer, index, lo, hi, tables, failed_actions)
            )
            ahead = None
            ps, pa, d_robot, terminal, live = front.ps, front.pa, front.d_robot, front.terminal, front.live
            distinct, shared = front.distinct, front.shared
            outcomes = []
            found: list[np.ndarray] = []
            if not keep:
                for name, mid in zip(("mid_seen", "mid_plain"), front.mids, strict=True):
                    keyed = np.full(len(pa), -1, dtype=np.int64)
                    keyed[live] = mid
                    parts[name].append(keyed)
                parts["d_robot"].append(d_robot)
            front.prefetch(tables)  # the live partners' searches start in their workers first ...
            answered: dict[int, _Answered] = {}
            for i in sorted(range(len(tables)), key=lambda i: tables[i].answers_live):
                # ... while the partners on arrays are answered here (each table's answers are its own)
                if tables[i].answers_live and ahead is None and index.n >= hi + size:
                    # the next batch is known whatever this one finds: its searches queue behind these
                    ahead = _Front.of(rules, packer, index, hi, hi + size, tables, failed_actions)
                    ahead.prefetch(tables)
                uses = tables[i].uses_robot_action
                answered[i] = _Answered(tables[i], distinct[uses][0], canonical, shared[uses])
            for i, t in enumerate(tables):
                inv = distinct[t.uses_robot_action][1]
                ans = answered[i]
                if not keep:
                    found.append(ans.next)
                    continue
                tcount = np.zeros(len(pa), dtype=np.int64)
                tcount[live] = ans.size[inv]
                pair_of = np.repeat(np.arange(len(pa)), tcount)
                block = np.zeros(len(pa), dtype=np.int64)
                block[live] = ans.block[inv]
                entry = np.repeat(block - np.concatenate([[0], np.cumsum(tcount)[:-1]]), tcount)
                entry += np.arange(len(pair_of))
                outcomes.append((tcount, pair_of, ans, entry))
            if not keep:  # the same states: every answer of a distinct key is some pair's transition
                index.add(unique(np.concatenate(found)))
                parts["size"].append(np.bincount(ps, minlength=hi - lo))
                parts["action"].append(pa)
                parts["terminal"].append(terminal)
                bar.update(hi - lo)
                lo = hi
                continue
            # the next states of the distinct keys' answers (every one is some pair's): fewer than the pairs'
            uniq, inv = unique_inverse(
                outcomes[0][2].next if len(outcomes) == 1 else np.concatenate([o[2].next for o in outcomes])
            )
            ids = index.add(uniq)[inv]  # sorted: new states get ids in key order
            at = 0
            for flow, (tcount, pair_of, ans, entry) in zip(flows, outcomes, strict=True):
                flow["tcount"].append(tcount)
                flow["next"].append(ids[at : at + len(ans.next)][entry])
                flow["prob"].append(ans.prob[entry])
                flow["tau"].append(np.maximum(d_robot[pair_of], ans.d_human[entry]))
                at += len(ans.next)
            parts["size"].append(np.bincount(ps, minlength=hi - lo))
            parts["action"].append(pa)
            parts["terminal"].append(terminal)
            bar.update(hi - lo)
            bar.set_postfix(known=index.n, refresh=False)
            lo = hi
        bar.set_postfix(known=index.n)  # the last frame reads the model's count
    finally:
        bar.close()
    budget.check("explore", lo, unit="states explored", states=index.n)

    def cat(arrays: list[np.ndarray], dtype: type) -> np.ndarray:
        return np.concatenate(arrays).astype(dtype, copy=False) if arrays else np.zeros(0, dtype=dtype)

    def starts(counts: list[np.ndarray]) -> np.ndarray:
        return np.concatenate([[0], np.cumsum(cat(counts, np.int64))]).astype(np.int64)

    if not keep:
        regen_ids = [(index.id_of(k), p, tau) for k, p, tau in regen]
        return Model(
            packer=packer,
            keys=index.keys(),
            pair_start=starts(parts["size"]),
            pair_action=cat(parts["action"], np.int64),
            pair_terminal=cat(parts["terminal"], bool),
            dynamics=[],
            n_layouts=len(layouts),
            lazy=TableTransitions(
                tables,
                index,
                canonical,
                cat(parts["mid_seen"], np.int64),
                cat(parts["mid_plain"], np.int64),
                cat(parts["d_robot"], np.float64),
                regen_ids,
            ),
        )

    def joined(flow: dict[str, list[np.ndarray]], name: str, dtype: type) -> np.ndarray:
        """A field's batches joined, then dropped and their heap pages given back (see trim_heap)."""
        pieces = flow.pop(name)
        out = cat(pieces, dtype)
        pieces.clear()
        trim_heap(out.nbytes)
        return out

    dynamics = [  # each field's batches are dropped once joined: the peak is one field's two copies, not all
        Dynamics(
            t_start=starts(flow.pop("tcount")),
            t_next=joined(flow, "next", np.int64),
            t_prob=joined(flow, "prob", np.float64),
            t_tau=joined(flow, "tau", np.float64),
            regen_next=index.id_of(keys),
            regen_prob=prob,
            regen_tau=tau,
        )
        for flow, (keys, prob, tau) in zip(flows, regen, strict=True)
    ]
    return Model(
        packer=packer,
        keys=index.keys(),
        pair_start=starts(parts["size"]),
        pair_action=cat(parts["action"], np.int64),
        pair_terminal=cat(parts["terminal"], bool),
        dynamics=dynamics,
        n_layouts=len(layouts),
    )
