"""The exact semi-MDP of a scenario against a stationary partner, built breadth-first on arrays.

States are packed into int64 keys (:class:`~hg_marl.agents.models.packing.StatePacker`).
A level of the breadth-first search is a batch of robot-turn states: the robot's
options are read from :meth:`BatchedRules.masks` (every feasible action, in index order,
then the first infeasible one standing for them all, as the oracle models them), stepped
with :meth:`BatchedRules.step`; the distinct mid-cycle keys (``np.unique``) get the
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
from dataclasses import dataclass

import numpy as np
from scipy import sparse
from tqdm import tqdm

from hg_marl.agents.models.answers import AnswerTable
from hg_marl.agents.models.budget import Budget
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
class Model:
    """A semi-MDP on packed robot-turn states (ids are positions in ``keys``)."""

    packer: StatePacker
    keys: np.ndarray
    """(n,) the packed state of each id."""
    pair_start: np.ndarray
    """(n + 1,) pairs of state ``s`` are ``pair_start[s]:pair_start[s + 1]``."""
    pair_action: np.ndarray
    pair_terminal: np.ndarray
    """Whether the pair is the completing ``wait`` (worth 1, followed by the re-draw)."""
    t_start: np.ndarray
    """(pairs + 1,) transitions of pair ``p`` are ``t_start[p]:t_start[p + 1]``."""
    t_next: np.ndarray
    t_prob: np.ndarray
    t_tau: np.ndarray
    regen_next: np.ndarray
    regen_prob: np.ndarray
    regen_tau: np.ndarray
    n_layouts: int

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
        """The pair of each transition."""
        return np.repeat(np.arange(self.n_pairs), np.diff(self.t_start))

    def states(self) -> list[State]:
        """The states as :class:`State` tuples, by id (for tests and small models)."""
        b, _ = self.packer.unpack(self.keys)
        return [b.state(i) for i in range(len(b))]


def _rows(b: BatchState, rows: np.ndarray) -> BatchState:
    return BatchState(b.where[rows], b.robot_at[rows], b.offer_by[rows], b.offer_obj[rows])


class _Index:
    """Known state keys, sorted, with their ids; ids in order of discovery."""

    def __init__(self) -> None:
        self.sorted = np.zeros(0, dtype=np.int64)
        self.ids = np.zeros(0, dtype=np.int64)
        self.by_id: list[np.ndarray] = []
        self.n = 0

    def add(self, keys: np.ndarray) -> None:
        """Give ids to the keys not known yet (``keys`` distinct, in the order ids are wanted)."""
        pos = np.searchsorted(self.sorted, keys)
        hit = pos < len(self.sorted)
        hit[hit] = self.sorted[pos[hit]] == keys[hit]
        new = keys[~hit]
        if not len(new):
            return
        ids = np.arange(self.n, self.n + len(new), dtype=np.int64)
        order = np.argsort(new, kind="stable")
        self.sorted = np.insert(self.sorted, pos[~hit][order], new[order])
        self.ids = np.insert(self.ids, pos[~hit][order], ids[order])
        self.by_id.append(new)
        self.n += len(new)

    def id_of(self, keys: np.ndarray) -> np.ndarray:
        """Ids of known keys."""
        return self.ids[np.searchsorted(self.sorted, keys)]

    def keys(self) -> np.ndarray:
        return np.concatenate(self.by_id) if self.by_id else np.zeros(0, dtype=np.int64)


def _first_unique(keys: np.ndarray) -> np.ndarray:
    """The distinct keys in order of first occurrence."""
    _, first = np.unique(keys, return_index=True)
    return keys[np.sort(first)]


class _Answered:
    """Answers of distinct mid-cycle keys: per key a block of (next key, probability, seconds)."""

    def __init__(self, table: AnswerTable, mids: np.ndarray, canonical: bool) -> None:
        table.ensure(mids)
        start, size = table.lookup(mids)
        self.block = np.concatenate([[0], np.cumsum(size)]).astype(np.int64)
        entry = np.repeat(start - self.block[:-1], size) + np.arange(self.block[-1])
        e = table.entries
        self.next = e["canonical" if canonical else "next"][entry]
        self.prob = e["probs"][entry]
        self.d_human = e["d_human"][entry]
        self.size = size


def build_model(
    world: World,
    answers: AnswerTable,
    layouts: list[tuple[State, float]],
    *,
    failed_actions: bool = True,
    canonical: bool = False,
    budget: Budget | None = None,
    progress: bool = False,
    label: str = "model",
) -> Model:
    """The model reachable from ``layouts`` (already canonical when ``canonical``) against ``answers``.

    ``canonical``: keep one state per relabelling class (an equivariant partner, as the
    oracle's symmetry reduction). The budget is read per batch of states (phase
    ``"explore"``) and between the partner's live answers; its states budget counts the
    states known.
    """
    budget = budget or Budget(None, None, None)
    rules = BatchedRules(world)
    packer = answers.packer
    wait = rules.wait[Agent.ROBOT]
    n_robot = rules.n_actions[Agent.ROBOT]
    uses = answers.uses_robot_action
    # the regeneration: the re-drawn tables and the partner's first answer on them
    answers.phase = "first answers"
    lay = BatchState.of([s for s, _ in layouts])
    lay_p = np.array([p for _, p in layouts], dtype=np.float64)
    lay_mid = packer.pack(lay, np.full(len(lay), wait if uses else -1, dtype=np.int64))
    u, inv = np.unique(lay_mid, return_inverse=True)
    first = _Answered(answers, u, canonical)
    count = first.size[inv]
    rows = np.repeat(np.arange(len(lay)), count)
    entry = np.repeat(first.block[inv] - np.concatenate([[0], np.cumsum(count)[:-1]]), count) + np.arange(len(rows))
    regen_keys = first.next[entry]
    regen_prob = lay_p[rows] * first.prob[entry]
    regen_tau = np.maximum(world.durations.wait, first.d_human[entry])
    index = _Index()
    index.add(_first_unique(np.concatenate([packer.pack(lay), regen_keys])))
    budget.check("explore", 0, unit=f"states explored ({index.n:,} known)", states=index.n)
    answers.phase = "explore: partner answers"
    parts: dict[str, list[np.ndarray]] = {
        k: [] for k in ("size", "action", "terminal", "tcount", "next", "prob", "tau")
    }
    bar = tqdm(
        desc=f"{label}: states", unit=" states", disable=not progress, file=sys.stderr, dynamic_ncols=True, leave=False
    )
    lo, size = 0, FIRST_CHUNK
    try:
        while lo < index.n:
            hi = min(lo + size, index.n)
            size = min(2 * size, CHUNK)
            budget.check("explore", lo, unit=f"states explored ({index.n:,} known)", states=index.n)
            b, _ = packer.unpack(index.keys()[lo:hi] if len(index.by_id) > 1 else index.by_id[0][lo:hi])
            mask = rules.masks(b, Agent.ROBOT)
            ps, pa = np.nonzero(mask)
            order_key = ps * (n_robot + 1) + pa
            if failed_actions:
                fails = np.flatnonzero(~mask.all(axis=1))
                ps = np.concatenate([ps, fails])
                pa = np.concatenate([pa, np.argmin(mask[fails], axis=1)])
                order_key = np.concatenate([order_key, fails * (n_robot + 1) + n_robot])
            order = np.argsort(order_key, kind="stable")
            ps, pa = ps[order], pa[order]
            clean = rules.is_clean(b)[ps]
            pb = _rows(b, ps)
            ok, d_robot, _ = rules.step(pb, Agent.ROBOT, pa, mask[ps])
            terminal = ok & (pa == wait) & clean
            live = np.flatnonzero(~terminal)
            seen = np.where(ok[live], pa[live], -1) if uses else np.full(len(live), -1, dtype=np.int64)
            mid = packer.pack(_rows(pb, live), seen)
            u, inv = np.unique(mid, return_inverse=True)
            ans = _Answered(answers, u, canonical)
            tcount = np.zeros(len(pa), dtype=np.int64)
            tcount[live] = ans.size[inv]
            pair_of = np.repeat(np.arange(len(pa)), tcount)
            starts = np.concatenate([[0], np.cumsum(tcount)[:-1]])
            block = np.zeros(len(pa), dtype=np.int64)
            block[live] = ans.block[inv]
            entry = np.repeat(block - starts, tcount) + np.arange(len(pair_of))
            uniq, inv = np.unique(ans.next[entry], return_inverse=True)
            index.add(uniq)  # sorted: new states get ids in key order
            parts["size"].append(np.bincount(ps, minlength=hi - lo))
            parts["action"].append(pa)
            parts["terminal"].append(terminal)
            parts["tcount"].append(tcount)
            parts["next"].append(index.id_of(uniq)[inv])
            parts["prob"].append(ans.prob[entry])
            parts["tau"].append(np.maximum(d_robot[pair_of], ans.d_human[entry]))
            bar.update(hi - lo)
            bar.set_postfix(known=index.n, refresh=False)
            lo = hi
        bar.set_postfix(known=index.n)  # the last frame reads the model's count
    finally:
        bar.close()
    budget.check("explore", lo, unit="states explored", states=index.n)

    def cat(name: str, dtype: type) -> np.ndarray:
        return np.concatenate(parts[name]).astype(dtype, copy=False) if parts[name] else np.zeros(0, dtype=dtype)

    sizes, tcounts = cat("size", np.int64), cat("tcount", np.int64)
    return Model(
        packer=packer,
        keys=index.keys(),
        pair_start=np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64),
        pair_action=cat("action", np.int64),
        pair_terminal=cat("terminal", bool),
        t_start=np.concatenate([[0], np.cumsum(tcounts)]).astype(np.int64),
        t_next=cat("next", np.int64),
        t_prob=cat("prob", np.float64),
        t_tau=cat("tau", np.float64),
        regen_next=index.id_of(regen_keys),
        regen_prob=regen_prob,
        regen_tau=regen_tau,
        n_layouts=len(layouts),
    )
