"""Behaviour cloning from trace files into a ``learned`` human (or robot) policy.

Input: the replay JSONL format of :mod:`hg_marl.agents.humans.trace` (one seat's facts,
mask and action per turn). Output: a policy directory that
``make_human("learned", path=OUT)`` loads (:mod:`hg_marl.agents.humans.learned`).

Two fits, both pure numpy (no torch needed to clone a person):

- ``table`` (default): for every distinct fact vector, the action recorded most often
  there (ties: the smallest index). It reproduces a deterministic recorded policy
  exactly on the recorded states, which is what a replayed participant is; unseen
  observations fall back to ``wait`` (the loader's ``fallback``).
- ``linear_softmax``: multinomial logistic regression of the action on the facts,
  restricted to the recorded mask (the loader applies the same mask), by full-batch
  gradient descent with a small L2 penalty. It generalises to unseen tables and is
  stationary, so the oracle can plan against it; it may not fit every recorded action.

Why not an SB3 policy: a table or a linear map already reproduces recorded actions on
recorded states, loads without torch, and the oracle can read its distribution.
"""

from __future__ import annotations

import logging
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hg_marl.agents.humans.learned import save_learned_policy
from hg_marl.agents.humans.trace import read_trace, trace_paths
from hg_marl.core import Agent, World

log = logging.getLogger(__name__)

KINDS = ("table", "linear_softmax")


@dataclass(frozen=True)
class Dataset:
    """Recorded (facts, mask, action) triples of one seat in one scenario."""

    facts: np.ndarray
    """``(n, F)`` int8."""
    masks: np.ndarray
    """``(n, A)`` bool."""
    actions: np.ndarray
    """``(n,)`` int64."""
    scenario: str
    """Scenario name from the headers."""
    seat: Agent
    """The recorded seat."""


def load_traces(paths: Sequence[str | Path]) -> Dataset:
    """Read trace files into one dataset, checking they share scenario, seat and names.

    Raises:
        ValueError: no steps, or files from different scenarios, seats or name lists.
    """
    facts: list[list[int]] = []
    masks: list[list[int]] = []
    actions: list[int] = []
    first: dict[str, object] | None = None
    for path in [file for given in paths for file in trace_paths(given)]:
        for episode in read_trace(path):
            h = episode.header
            key = {k: h.get(k) for k in ("scenario", "seat", "fact_names", "action_names")}
            if first is None:
                first = key
            elif key != first:
                raise ValueError(
                    f"{path}: episode {h.get('episode')} is from {h.get('scenario')!r} "
                    f"({h.get('seat')}), not {first['scenario']!r} ({first['seat']}) like the first"
                )
            for step in episode.steps:
                facts.append(step["facts"])
                masks.append(step["mask"])
                actions.append(int(step["action"]))
    if first is None or not actions:
        raise ValueError(f"no recorded steps in {', '.join(map(str, paths))}")
    return Dataset(
        np.array(facts, dtype=np.int8),
        np.array(masks, dtype=bool),
        np.array(actions, dtype=np.int64),
        str(first["scenario"]),
        Agent.HUMAN if first["seat"] == "human" else Agent.ROBOT,
    )


def fit_table(data: Dataset) -> dict[bytes, int]:
    """Majority action per distinct fact vector (ties: the smallest action index)."""
    counts: dict[bytes, Counter[int]] = {}
    for row, action in zip(data.facts, data.actions, strict=True):
        counts.setdefault(row.tobytes(), Counter())[int(action)] += 1
    return {key: min(c, key=lambda a: (-c[a], a)) for key, c in counts.items()}


def fit_linear(
    data: Dataset, n_actions: int, iterations: int = 2000, learning_rate: float = 0.5, l2: float = 1e-4
) -> tuple[np.ndarray, np.ndarray]:
    """Masked multinomial logistic regression by full-batch gradient descent.

    Returns:
        ``(W, b)`` with shapes ``(n_actions, n_facts)`` and ``(n_actions,)``.
    """
    x = data.facts.astype(np.float64)
    n, f = x.shape
    y = np.zeros((n, n_actions))
    y[np.arange(n), data.actions] = 1.0
    w, b = np.zeros((n_actions, f)), np.zeros(n_actions)
    for _ in range(iterations):
        logits = np.where(data.masks, x @ w.T + b, -np.inf)
        p = np.exp(logits - logits.max(axis=1, keepdims=True))
        p /= p.sum(axis=1, keepdims=True)
        grad = (p - y) / n
        w -= learning_rate * (grad.T @ x + l2 * w)
        b -= learning_rate * grad.sum(axis=0)
    return w, b


def behaviour_clone(
    traces: Sequence[str | Path], out: str | Path, kind: str = "table", scenario: str | None = None
) -> tuple[Path, float]:
    """Fit a policy to recorded play and write it as a ``learned`` policy directory.

    Args:
        traces: trace files (JSON lines, see :mod:`hg_marl.agents.humans.trace`) or
            directories of them (every ``*.jsonl`` below, e.g. what ``hg-marl play`` recorded).
        out: the directory to write.
        kind: ``table`` or ``linear_softmax`` (see the module docstring).
        scenario: the scenario spec to build the World from (default: the traces' scenario
            name, which must then be a built-in or a path).

    Returns:
        The directory and the fraction of recorded actions the fitted policy's most
        probable action reproduces on the recorded observations.

    Raises:
        ValueError: unknown kind, empty or inconsistent traces, names that differ from
            the scenario's.
    """
    if kind not in KINDS:
        raise ValueError(f"unknown behaviour-cloning kind {kind!r}; use one of {KINDS}")
    data = load_traces(traces)
    world = World(scenario or data.scenario)
    n_actions = world.n_actions(data.seat)
    if data.facts.shape[1] != world.n_facts or data.masks.shape[1] != n_actions:
        raise ValueError(
            f"traces do not match scenario {world.scenario.name!r}: {data.facts.shape[1]} facts and "
            f"{data.masks.shape[1]} actions recorded, {world.n_facts} and {n_actions} expected"
        )
    if kind == "table":
        table = fit_table(data)
        path = save_learned_policy(out, world, table=table, seat=data.seat)
        predicted = np.array([table[row.tobytes()] for row in data.facts])
    else:
        w, b = fit_linear(data, n_actions)
        path = save_learned_policy(out, world, weights=w, bias=b, seat=data.seat)
        predicted = np.argmax(np.where(data.masks, data.facts @ w.T + b, -np.inf), axis=1)
    accuracy = float(np.mean(predicted == data.actions))
    log.info(
        "behaviour cloning (%s): %d steps, %d distinct observations, accuracy %.3f",
        kind,
        len(data.actions),
        len(np.unique(data.facts, axis=0)),
        accuracy,
    )
    return path, accuracy
