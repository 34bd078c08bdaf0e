"""Ragged batched answers (sizes, then the actions and probabilities of every state end to end) as lists."""

from __future__ import annotations

import numpy as np


def per_state(sizes: np.ndarray, actions: np.ndarray, probs: np.ndarray) -> list[list[tuple[int, float]]]:
    """One list of (action, probability) per state."""
    out, at = [], 0
    for size in sizes.tolist():
        out.append(list(zip(actions[at : at + size].tolist(), probs[at : at + size].tolist(), strict=True)))
        at += size
    return out
