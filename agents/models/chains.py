"""A partner's transitions on a shared model, read as CSR: certain states, the optimal policy, a policy's rate.

The headroom matrix (``agents/headroom.py``) solves one policy per assumed partner and
evaluates every policy against every true partner on one joint model of half a million
states (``roboergosum``). Each partner's transitions are CSR rows per (state, action)
pair (:class:`Chain`), so:

- the states from which some policy completes with certainty are a backward search on
  the reversed transitions (each transition read once per outer round), not one pass
  over every transition per step of depth;
- a value-iteration sweep is one CSR product, summing each pair's transitions in the
  same order as ``np.bincount`` did (so the values are the same floats);
- a fixed policy's rate needs only the states it reaches from the re-drawn tables
  against that partner (a set closed under its transitions, so the expected seconds
  there are those of the whole chain): they are found forward from the re-draw, and the
  linear system is solved on them alone.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TypeAlias

import numpy as np
from scipy import sparse
from scipy.sparse.linalg import spsolve

from hg_marl.agents.models.builder import Dynamics
from hg_marl.agents.models.keyed import ranges, starts_of, unique

HOUR = 3600.0


Chain: TypeAlias = Dynamics
"""One partner's transitions on a model (the builder's :class:`Dynamics`)."""


def _spread(frontier: np.ndarray, reverse: sparse.csr_matrix) -> np.ndarray:
    """The columns of ``reverse``'s rows ``frontier`` (the pairs with a transition into those states)."""
    starts, ends = reverse.indptr[frontier], reverse.indptr[frontier + 1]
    size = ends - starts
    at = np.repeat(starts - np.concatenate([[0], np.cumsum(size)[:-1]]), size) + np.arange(size.sum())
    return reverse.indices[at]


def certain_states(n: int, pair_state: np.ndarray, terminal: np.ndarray, chain: Chain) -> tuple[np.ndarray, np.ndarray]:
    """States from which some policy completes with probability 1, and the pairs it may use.

    The greatest set ``alive`` such that from each of its states some pair that never
    leaves ``alive`` (``ok``) leads, step by step, to a completing pair: the oracle's
    fixpoint (``python_model.certain_states``), its inner growth done as a backward search.
    """
    n_pairs = len(terminal)
    t_pair = chain.t_pair
    reverse = sparse.csr_matrix(
        (np.ones(len(t_pair), dtype=np.int8), (chain.t_next, t_pair)), shape=(n, n_pairs)
    )  # state -> the pairs with a transition into it
    alive = np.ones(n, dtype=bool)
    while True:
        if alive.all():  # the first round: no pair can leave
            ok = np.ones(n_pairs, dtype=bool)
        else:
            ok = terminal | ~(np.bincount(t_pair, weights=~alive[chain.t_next], minlength=n_pairs) > 0)
        reach = np.zeros(n, dtype=bool)
        reach[pair_state[ok & terminal]] = True
        frontier = np.flatnonzero(reach)
        while len(frontier):
            pairs = _spread(frontier, reverse)
            states = pair_state[pairs[ok[pairs]]]
            frontier = unique(states[~reach[states]])
            reach[frontier] = True
        if (reach == alive).all():
            return alive, ok
        alive = reach


def transitions(chain: Chain, n: int, weights: np.ndarray | None = None) -> sparse.csr_matrix:
    """(pairs, states) CSR of ``weights`` per transition (the probabilities by default)."""
    data = chain.t_prob if weights is None else weights
    return sparse.csr_matrix((data, chain.t_next, chain.t_start), shape=(len(chain.t_start) - 1, n))


def forward(graph: sparse.csr_matrix, seeds: np.ndarray) -> np.ndarray:
    """States reachable from the ``seeds`` indices along ``graph``'s edges (the seeds included)."""
    found = np.zeros(graph.shape[0], dtype=bool)
    frontier = unique(seeds)
    found[frontier] = True
    while len(frontier):
        hit = _spread(frontier, graph)
        frontier = unique(hit[~found[hit]])
        found[frontier] = True
    return found


def backward(graph: sparse.csr_matrix, seeds: np.ndarray) -> np.ndarray:
    """States from which some path of ``graph`` reaches a ``seeds`` state (a boolean mask)."""
    return forward(graph.T.tocsr(), np.flatnonzero(seeds))


Transitions: TypeAlias = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]
"""States (ids, in a given order) -> a policy's transitions from each: (starts, next state, probability,
seconds), CSR over those states in that order."""


def policy_rate(chain: Chain, done: np.ndarray, policy: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]) -> float:
    """Exact tasks per hour of a policy given as its transitions at every state (:func:`reached_rate`).

    ``policy``: the transitions of the policy's pair at each state, CSR over the states
    (starts, next state, probability, seconds).
    """
    t_start, cols, probs, taus = policy

    def transitions_of(states: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        size = t_start[states + 1] - t_start[states]
        at = ranges(t_start[states], size)
        return starts_of(size), cols[at], probs[at], taus[at]

    return reached_rate(chain, done, transitions_of)


def reached_rate(chain: Chain, done: np.ndarray, transitions_of: Transitions) -> float:
    """Exact tasks per hour of a policy against ``chain``'s partner (only its re-draw is read from ``chain``).

    ``transitions_of``: the policy's transitions from given states; ``done``: the states
    whose pair completes the task. The chain of the policy is restricted to the states it
    reaches from the re-drawn tables, found forward and asked for their transitions alone
    (a tenth of a headroom model's states or less; asking every state's would cost more
    than the rest); there, the states that may reach one that cannot complete get
    infinite seconds (graph search), and the others' expected seconds to the next
    success solve ``(I - P) V = c`` (``spsolve``). Where a re-drawn table has such a
    state, the rate is 0 whatever the others' seconds, and no system is solved (most of
    a headroom matrix's entries are 0).
    """
    n = len(done)
    seen = np.zeros(n, dtype=bool)
    frontier = unique(chain.regen_next)
    seen[frontier] = True
    while len(frontier):
        hit = transitions_of(frontier)[1]
        frontier = unique(hit[~seen[hit]])
        seen[frontier] = True
    sub = np.flatnonzero(seen)  # in id order: the transitions below are those of the whole chain's rows
    pos = np.full(n, -1, dtype=np.int64)
    pos[sub] = np.arange(len(sub))
    t_start, cols, probs, taus = transitions_of(sub)
    rows = np.repeat(np.arange(len(sub)), np.diff(t_start))
    cols = pos[cols]
    m = len(sub)
    done = done[sub]
    small = sparse.csr_matrix((np.ones(len(rows), dtype=np.int8), (rows, cols)), shape=(m, m))
    reach = backward(small, done)
    certain = ~backward(small, ~reach)
    if not certain[pos[chain.regen_next]].all():  # (the builder keeps no re-draw of probability 0)
        return 0.0  # a re-drawn table may lead where completion is not certain: infinite seconds, rate 0
    values = np.full(m, math.inf)
    idx = np.flatnonzero(certain)
    if len(idx):
        inner_pos = np.full(m, -1, dtype=np.int64)
        inner_pos[idx] = np.arange(len(idx))
        from_ok = certain[rows] & ~done[rows]
        inner = from_ok & certain[cols]
        k = len(idx)
        p = sparse.csr_matrix((probs[inner], (inner_pos[rows[inner]], inner_pos[cols[inner]])), shape=(k, k))
        c = np.bincount(inner_pos[rows[from_ok]], weights=(probs * taus)[from_ok], minlength=k)
        values[idx] = np.atleast_1d(spsolve((sparse.identity(k, format="csr") - p).tocsc(), c))
    regen = values[pos[chain.regen_next]]
    terms = zip(chain.regen_prob.tolist(), chain.regen_tau.tolist(), regen.tolist(), strict=True)
    expected = math.fsum(p * (tau + v) for p, tau, v in terms)
    return 0.0 if math.isinf(expected) else HOUR / expected
