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
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import sparse

from hg_marl.agents.models.budget import Budget
from hg_marl.agents.models.builder import Model


@dataclass(frozen=True)
class Solution:
    """Optimal expected seconds to the next success per state, and the chosen pair per state."""

    values: np.ndarray
    """(n,) seconds (inf: success is not certain from there)."""
    q: np.ndarray
    """(pairs,) seconds after each (state, action) (inf: not certain)."""
    best_pair: np.ndarray
    """(n,) the first pair reaching the state's minimum."""
    iterations: int
    converged: bool
    seconds_per_task: float
    """Expected seconds between successes (inf: never)."""


def certain_states(model: Model, transitions: sparse.csr_matrix) -> tuple[np.ndarray, np.ndarray]:
    """States from which some policy completes with probability 1, and the pairs it may use."""
    n, pair_state, terminal = model.n, model.pair_state(), model.pair_terminal
    structure = transitions.copy()
    structure.data = np.ones_like(structure.data)
    alive = np.ones(n, dtype=bool)
    while True:
        leaks = (structure @ (~alive).astype(np.float64)) > 0
        ok = terminal | ~leaks
        reach = np.zeros(n, dtype=bool)
        reach[pair_state[ok & terminal]] = True
        while True:
            hits = (structure @ reach.astype(np.float64)) > 0
            grown = reach.copy()
            grown[pair_state[ok & hits]] = True
            if (grown == reach).all():
                break
            reach = grown
        if (reach == alive).all():
            return alive, ok
        alive = reach


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
    transitions = model.transitions()
    cost = np.bincount(model.t_pair(), weights=model.t_prob * model.t_tau, minlength=n_pairs)
    budget.check("solve", 0, unit="sweeps", memory=True)
    alive, ok = certain_states(model, transitions)
    starts = model.pair_start[:-1]
    terminal = model.pair_terminal
    values = np.zeros(n)
    iterations, converged = 0, False

    zero_at, inf_at, dead = np.flatnonzero(terminal & ok), np.flatnonzero(~ok), np.flatnonzero(~alive)

    def q_of(v: np.ndarray) -> np.ndarray:
        """Seconds after each pair given ``v`` (``v`` is 0 on the states that cannot complete)."""
        q = transitions @ v
        q += cost
        q[zero_at] = 0.0
        q[inf_at] = np.inf
        return q

    if alive.any():
        for iterations in range(1, max_iterations + 1):
            new = np.minimum.reduceat(q_of(values), starts)
            new[dead] = 0.0
            delta = float(np.max(np.abs(new - values)))
            values = new
            if iterations % 64 == 0:
                budget.check("solve", iterations, unit="sweeps", memory=iterations % 4096 == 0)
            if delta < tolerance:
                converged = True
                break
    q = q_of(np.where(alive, values, 0.0))
    values = np.where(alive, values, np.inf)
    best = np.minimum.reduceat(q, starts) if n else np.zeros(0)
    pair_state = model.pair_state()
    first = np.full(n, n_pairs, dtype=np.int64)
    at_min = np.flatnonzero(q == best[pair_state])
    np.minimum.at(first, pair_state[at_min], at_min)
    inf_state = ~np.isfinite(best)
    first[inf_state] = starts[inf_state]  # argmin of all-inf picks the first pair
    regen = values[model.regen_next]
    expected = float(np.sum(model.regen_prob * (model.regen_tau + regen)))
    return Solution(values, q, first, iterations, converged, expected)
