"""The oracle as it was before the array builder: one Python state at a time (the tests' reference).

The model is enumerated by ``agents/oracle.py``'s ``PythonModel`` (the Python enumeration kept
as the reference) and solved by the same value iteration written with ``np.bincount``
over flat transition lists. The array builder and the sparse solver must agree with it:
same states, same transitions, rates to 1e-9.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.layouts import canonical_layouts, layout_distribution
from hg_marl.agents.models.python_model import PythonModel, certain_states
from hg_marl.agents.oracle import HOUR
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, State, World


@dataclass
class Reference:
    """The reference model's rate, policy and transitions (keyed by states)."""

    rate_per_hour: float
    n_states: int
    n_transitions: int
    policy: dict[State, int]
    values: dict[State, float]
    states: list[State]
    """The states by id (canonical when the symmetry reduction is on)."""
    pair_state: np.ndarray
    """Per (state, robot action) pair: its state's id, and (below) the action; pairs contiguous per state."""
    pair_action: np.ndarray
    t_pair: np.ndarray
    """Per transition: its pair, next state's id, seconds and probability (terminal pairs have none)."""
    t_next: np.ndarray
    t_tau: np.ndarray
    t_prob: np.ndarray
    regen: dict[State, float]
    """Re-drawn states (canonical) with their summed probability."""


def reference_oracle(
    world: World, human: Any, *, failed_actions: bool = True, symmetry: bool | None = None, max_states: int = 400_000
) -> Reference:
    """The pre-array oracle on ``world`` against ``human`` (a spec or a stationary instance)."""
    policy_human = stationary_human(human, world)
    relabel: Relabel | None = Relabel(world)
    if symmetry is None:
        symmetry = bool(getattr(policy_human, "equivariant", False))
    if not (symmetry and relabel is not None and relabel.active):
        relabel = None
    layouts = layout_distribution(world) if relabel is None else canonical_layouts(world)
    model = PythonModel(world, policy_human, failed_actions, max_states, False, relabel)
    wait = world.durations.wait
    wait_index = world.n_actions(Agent.ROBOT) - 1
    regen: list[tuple[State, float, float]] = []
    for table, q in layouts:
        regen += [(nxt, q * p, tau) for nxt, p, tau in model.replies(table, wait, wait_index)]
    model.build([s for s, _ in layouts] + [s for s, _, _ in regen])
    n = len(model.states)
    pair_state = np.repeat(np.arange(n), np.diff([*model.pair_start, len(model.pair_action)]))
    terminal = np.array(model.pair_terminal, dtype=bool)
    t_pair, t_next = np.array(model.t_pair, dtype=np.int64), np.array(model.t_next, dtype=np.int64)
    t_prob, t_tau = np.array(model.t_prob), np.array(model.t_tau)
    n_pairs = len(terminal)
    cost = np.bincount(t_pair, weights=t_prob * t_tau, minlength=n_pairs)
    alive, ok = certain_states(n, pair_state, terminal, t_pair, t_next)
    starts = np.array(model.pair_start, dtype=np.int64)
    values = np.zeros(n)
    if alive.any():
        for _ in range(200_000):
            q = cost + np.bincount(
                t_pair, weights=t_prob * np.where(alive[t_next], values[t_next], 0.0), minlength=n_pairs
            )
            q = np.where(ok, np.where(terminal, 0.0, q), np.inf)
            new = np.where(alive, np.minimum.reduceat(q, starts), 0.0)
            delta = float(np.max(np.abs(new - values)))
            values = new
            if delta < 1e-9:
                break
    values = np.where(alive, values, np.inf)
    q = cost + np.bincount(t_pair, weights=t_prob * np.where(alive[t_next], values[t_next], 0.0), minlength=n_pairs)
    q = np.where(ok, np.where(terminal, 0.0, q), np.inf)
    ends = [*model.pair_start[1:], n_pairs]
    best = []  # the first action in option order within 1e-6 s of the state's lowest (equal ones are ties)
    for s in range(n):
        row = q[starts[s] : ends[s]]
        best.append(int(model.pair_action[starts[s] + next(i for i, x in enumerate(row) if x <= min(row) + 1e-6)]))
    expected = sum(p * (tau + values[model.index[model.canonical(s)]]) for s, p, tau in regen)
    regen_p: dict[State, float] = {}
    for s, p, _ in regen:
        c = model.canonical(s)
        regen_p[c] = regen_p.get(c, 0.0) + p
    return Reference(
        rate_per_hour=0.0 if math.isinf(expected) else HOUR / expected,
        n_states=n,
        n_transitions=len(t_pair),
        policy=dict(zip(model.states, best, strict=True)),
        values=dict(zip(model.states, values.tolist(), strict=True)),
        states=list(model.states),
        pair_state=pair_state,
        pair_action=np.array(model.pair_action, dtype=np.int64),
        t_pair=t_pair,
        t_next=t_next,
        t_tau=t_tau,
        t_prob=t_prob,
        regen=regen_p,
    )
