"""A ``memory`` model file's weight arrays, named and shaped as ``MemoryNet``'s, for tests
that write such files without torch."""

from __future__ import annotations

import numpy as np


def memory_arrays(hidden: int, obs: int, n_actions: int, recurrent: bool, fill: float = 0.0) -> dict[str, np.ndarray]:
    """Every array of a ``hidden``-unit net over ``obs`` inputs and ``n_actions`` logits, filled with ``fill``."""
    h = hidden
    shapes = {
        "encoder.0.weight": (h, obs),
        "encoder.0.bias": (h,),
        "encoder.2.weight": (h, h),
        "encoder.2.bias": (h,),
        "actor.weight": (n_actions, h),
        "actor.bias": (n_actions,),
        "critic.weight": (1, h),
        "critic.bias": (1,),
    }
    if recurrent:
        shapes |= {
            "gru.weight_ih": (3 * h, h),
            "gru.weight_hh": (3 * h, h),
            "gru.bias_ih": (3 * h,),
            "gru.bias_hh": (3 * h,),
        }
    return {k: np.full(s, fill) for k, s in shapes.items()}


def small_memory_header(**fields: object) -> dict[str, object]:
    """A complete ``memory`` header for :func:`memory_arrays` ``(4, 3, 2, recurrent=True)``: three
    facts (a, b, c), no history (``obs_size`` 3), two actions (go, wait), 4 hidden units, a GRU;
    ``fields`` replace entries."""
    header: dict[str, object] = {
        "kind": "memory",
        "history": 0,
        "history_cap": 8,
        "hidden": 4,
        "obs_size": 3,
        "fact_names": ["a", "b", "c"],
        "action_names": ["go", "wait"],
        "recurrent": True,
    }
    return header | fields
