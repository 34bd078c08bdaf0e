"""The average reward rate of a model: its stochastic shortest path to the next success, on CSR.

Choice. Every success is worth exactly 1 and is followed by a table drawn from a fixed
distribution (a regeneration point), so by the renewal-reward theorem a stationary
policy's rate is ``1 / E[T]`` with ``T`` the time between successes, and the policy
minimising the expected time to the next success from every state maximises the rate.
The semi-MDP's average-reward problem is thus a stochastic shortest-path problem solved
in one pass (the Dinkelbach fixed point ``max E[r - rho tau] = 0`` without a search on
``rho``): value iteration ``V(s) = min_a E[tau + V(s')]``, ``V = 0`` after the completing
``wait``. Relative value iteration on the semi-MDP would need a data transformation for
the unequal durations and a reference state, and converges no faster; policy iteration
needs a proper first policy, which the certain-completion fixpoint does not hand over for
free. Value iteration from ``V = 0`` increases monotonically to the optimum, so the same
stopping rule as the Python oracle's (``max |delta| < tolerance``) gives the same rates.

Each sweep is one CSR matrix-vector product ``P @ V`` over (pair, next state) and one
``np.minimum.reduceat`` over each state's pairs. States from which no policy completes
with probability 1 are found first (almost-sure reachability fixpoint) and get ``V = inf``.

Self-loops solved in closed form. A pair that returns to its own state with probability
``p`` (an offer refused, both agents waiting) makes plain sweeps approach its value one
factor ``p`` at a time: a partner who refuses 4 times in 5 needs about a hundred sweeps
for 1e-9. The sweeps therefore use the equivalent operator ``min_a (c_a + sum_{s' != s}
p_a(s') V(s')) / (1 - p_a(s))`` (:func:`without_self_loops`; Bertsekas' transformation
of a stochastic shortest path): at the fixed point ``V(s) = q_a`` for the chosen pair
under both operators, and ``q_a > V(s)`` under one exactly when under the other, so the
values and the policy are the same; a pair that only returns is never optimal where
completion is certain. The reported ``q`` is computed with the plain operator from the
converged values: the expected seconds after each pair, which the belief robot mixes.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

import numpy as np
from scipy import sparse

from hg_marl.agents.models.budget import Budget
from hg_marl.agents.models.builder import Model

BLOCK = 1 << 22
"""Transitions per block of the solver's per-transition temporaries: a model of tens of
millions of transitions is read a block at a time, so a temporary costs a block's bytes,
not the model's (:func:`pair_blocks`)."""

TIE = 1e-6
"""Pairs whose expected seconds are within this of a state's best are tied; the first in option
order wins. Why a tolerance: actions that are equally good reach their values by different
sums of floats, and which of them came out a few ulps lower would otherwise pick the policy."""


@dataclass(frozen=True)
class Solution:
    """Optimal expected seconds to the next success per state, and the chosen pair per state."""

    values: np.ndarray
    """(n,) seconds (inf: success is not certain from there)."""
    q: np.ndarray
    """(pairs,) seconds after each (state, action) (inf: not certain)."""
    best_pair: np.ndarray
    """(n,) the first pair within :data:`TIE` of the state's minimum."""
    iterations: int
    converged: bool
    seconds_per_task: float
    """Expected seconds between successes (inf: never)."""


def pair_blocks(t_start: np.ndarray, block: int | None = None) -> list[tuple[int, int]]:
    """Ranges ``[p0, p1)`` of pairs cutting the transitions into blocks of about ``block`` (:data:`BLOCK`).

    A pair is never cut: a per-pair sum (``np.bincount``) over a block adds each pair's
    transitions in the same order as one pass over them all, so the result is the same
    to the bit.
    """
    n_pairs, block = len(t_start) - 1, block or BLOCK
    cuts = np.searchsorted(t_start, np.arange(block, int(t_start[-1]), block), side="left")
    bounds = np.unique(np.concatenate([[0], np.minimum(cuts, n_pairs), [n_pairs]]))
    return list(zip(bounds[:-1].tolist(), bounds[1:].tolist(), strict=True))


def transition_blocks(t_start: np.ndarray, block: int | None = None) -> Iterator[tuple[int, int, slice]]:
    """Each of :func:`pair_blocks`' ranges with the slice of the transitions it holds."""
    for p0, p1 in pair_blocks(t_start, block):
        yield p0, p1, slice(int(t_start[p0]), int(t_start[p1]))


def pair_sums(
    t_start: np.ndarray, t_pair: np.ndarray, weights: Callable[[slice], np.ndarray], block: int | None = None
) -> np.ndarray:
    """Per pair, the sum of ``weights(transitions)`` over its transitions, a block at a time."""
    out = np.zeros(len(t_start) - 1)
    for p0, p1, at in transition_blocks(t_start, block):
        out[p0:p1] = np.bincount(t_pair[at] - p0, weights=weights(at), minlength=p1 - p0)
    return out


def certain_states(model: Model, transitions: sparse.csr_matrix) -> tuple[np.ndarray, np.ndarray]:
    """States from which some policy completes with probability 1, and the pairs it may use."""
    n, pair_state, terminal = model.n, model.pair_state(), model.pair_terminal
    alive = np.ones(n, dtype=bool)
    while True:  # every stored probability is positive: a product is > 0 exactly where an edge is
        leaks = (transitions @ (~alive).astype(np.float64)) > 0
        ok = terminal | ~leaks
        reach = np.zeros(n, dtype=bool)
        reach[pair_state[ok & terminal]] = True
        while True:
            hits = (transitions @ reach.astype(np.float64)) > 0
            grown = reach.copy()
            grown[pair_state[ok & hits]] = True
            if (grown == reach).all():
                break
            reach = grown
        if (reach == alive).all():
            return alive, ok
        alive = reach


def without_self_loops(
    pair_state: np.ndarray,
    t_start: np.ndarray,
    t_next: np.ndarray,
    t_prob: np.ndarray,
    cost: np.ndarray,
    n: int,
    t_pair: np.ndarray | None = None,
) -> tuple[sparse.csr_matrix, np.ndarray, np.ndarray]:
    """The sweeps' operator with self-loops solved (module docstring): (pairs, states) CSR, cost, looping pairs.

    Row ``a`` holds ``a``'s transitions to other states divided by their total probability
    ``1 - p_a(s)`` (summed from those transitions, not as one minus the loop's: no
    cancellation), the cost is ``cost / (1 - p_a(s))``; ``looping`` marks the pairs with
    transitions that all return to their state (their value is infinite). ``t_pair``: the
    pair of each transition, where the caller has it.
    """
    n_pairs = len(t_start) - 1
    counts = np.diff(t_start)
    if t_pair is None:
        t_pair = np.repeat(np.arange(n_pairs), counts)
    # a self-loop keeps its place in the rows with probability 0: the products add exact
    # zeros in the same order, and the transitions' index arrays are shared, not copied
    leaving = np.empty(len(t_prob))

    def leaving_of(at: slice) -> np.ndarray:
        leaving[at] = np.where(t_next[at] == pair_state[t_pair[at]], 0.0, t_prob[at])
        return leaving[at]

    out = pair_sums(t_start, t_pair, leaving_of)
    looping = (out == 0) & (counts > 0)
    scale = 1.0 / np.where(out > 0, out, 1.0)
    if (scale != 1.0).any():  # (times 1 is the identity: most partners' pairs leave with probability 1)
        for _, _, at in transition_blocks(t_start):
            leaving[at] *= scale[t_pair[at]]
        cost = cost * scale
    matrix = sparse.csr_matrix((leaving, t_next, t_start), shape=(n_pairs, n))
    return matrix, cost, looping


def sweeps(
    pair_state: np.ndarray,
    t_start: np.ndarray,
    t_next: np.ndarray,
    t_prob: np.ndarray,
    cost: np.ndarray,
    terminal: np.ndarray,
    alive: np.ndarray,
    ok: np.ndarray,
    starts: np.ndarray,
    *,
    tolerance: float,
    max_iterations: int,
    budget: Budget,
    t_pair: np.ndarray | None = None,
) -> tuple[np.ndarray, int, bool]:
    """Value iteration from 0 with self-loops in closed form: (values, sweeps, converged).

    The one sweep loop of the oracle and the headroom's policies. ``values`` is 0 on the
    states that cannot complete (``~alive``); the pairs that may leave them (``~ok``) and
    the pairs that only return are infinite; the completing ``wait`` is 0. The budget is
    read every 64 sweeps, the memory every 4,096.
    """
    n = len(alive)
    values = np.zeros(n)
    if not alive.any():
        return values, 0, False
    fast, fast_cost, looping = without_self_loops(pair_state, t_start, t_next, t_prob, cost, n, t_pair)
    zero_at, inf_at, dead = np.flatnonzero(terminal & ok), np.flatnonzero(~ok | looping), np.flatnonzero(~alive)
    for iteration in range(1, max_iterations + 1):
        q = fast @ values
        q += fast_cost
        q[zero_at] = 0.0
        q[inf_at] = np.inf
        new = np.minimum.reduceat(q, starts)
        new[dead] = 0.0
        delta = float(np.max(np.abs(new - values)))
        values = new
        if iteration % 64 == 0:
            budget.check("solve", iteration, unit="sweeps", memory=iteration % 4096 == 0)
        if delta < tolerance:
            return values, iteration, True
    return values, max_iterations, False


def solve(
    model: Model,
    *,
    tolerance: float = 1e-9,
    max_iterations: int = 200_000,
    budget: Budget | None = None,
) -> Solution:
    """Value iteration for the expected seconds to the next success (see the module docstring)."""
    budget = budget or Budget(None, None, None)
    n, n_pairs = model.n, model.n_pairs
    # scipy keeps the indices in the narrowest type that holds them (a copy, where the model's
    # are wider): the sweeps' matrix reads the same copy, not one of its own
    transitions = model.transitions()
    t_start, t_next = transitions.indptr, transitions.indices
    t_pair = model.t_pair()
    t_prob, t_tau = model.t_prob, model.t_tau
    cost = pair_sums(t_start, t_pair, lambda at: t_prob[at] * t_tau[at])
    budget.check("solve", 0, unit="sweeps", memory=True)
    alive, ok = certain_states(model, transitions)
    starts = model.pair_start[:-1]
    terminal = model.pair_terminal
    pair_state = model.pair_state()
    zero_at, inf_at = np.flatnonzero(terminal & ok), np.flatnonzero(~ok)

    def q_of(v: np.ndarray) -> np.ndarray:
        """Seconds after each pair given ``v`` (``v`` is 0 on the states that cannot complete)."""
        q = transitions @ v
        q += cost
        q[zero_at] = 0.0
        q[inf_at] = np.inf
        return q

    values, iterations, converged = sweeps(
        pair_state,
        t_start,
        t_next,
        t_prob,
        cost,
        terminal,
        alive,
        ok,
        starts,
        tolerance=tolerance,
        max_iterations=max_iterations,
        budget=budget,
        t_pair=t_pair,
    )
    q = q_of(np.where(alive, values, 0.0))
    values = np.where(alive, values, np.inf)
    best = np.minimum.reduceat(q, starts) if n else np.zeros(0)
    first = np.full(n, n_pairs, dtype=np.int64)
    at_min = np.flatnonzero(q <= best[pair_state] + TIE)
    np.minimum.at(first, pair_state[at_min], at_min)
    inf_state = ~np.isfinite(best)
    first[inf_state] = starts[inf_state]  # argmin of all-inf picks the first pair
    regen = values[model.regen_next]
    expected = float(np.sum(model.regen_prob * (model.regen_tau + regen)))
    return Solution(values, q, first, iterations, converged, expected)
