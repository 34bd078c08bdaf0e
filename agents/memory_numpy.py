"""A ``memory`` model file checked and played in numpy: what the ``memory`` robot runs.

Playing one table means one tiny forward pass per turn; in torch that costs more in
call overhead (and, on a loaded machine, in its thread pool) than the arithmetic, and
it would import torch into every run. The arithmetic is written out here instead, the
same as torch's ``nn.Linear``, ``nn.Tanh`` and ``nn.GRUCell`` (gates ordered reset,
update, new, as torch stores them); ``tests/training/test_ppo_recurrent.py`` checks it
against :class:`~hg_marl.agents.memory_policy.MemoryNet` on random inputs.

:func:`check_memory_file` is the one check of a ``memory`` header and its arrays (both
players use it): bounded sizes, the observation size the history implies, and exactly
the arrays the architecture has, with their shapes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hg_marl.agents.model_file import ModelFile
from hg_marl.core.errors import ModelFileError
from hg_marl.envs.history import MAX_HISTORY, history_size

MAX_HIDDEN = 1024
"""Widest layer a file may ask for (a bound on what loading allocates)."""


@dataclass(frozen=True)
class MemoryShape:
    """The architecture a ``memory`` header names."""

    obs_size: int
    n_actions: int
    hidden: int
    recurrent: bool
    history: int
    cap: int

    def arrays(self) -> dict[str, tuple[int, ...]]:
        """Name and shape of every weight (torch's state-dict names)."""
        h, o, a = self.hidden, self.obs_size, self.n_actions
        shapes: dict[str, tuple[int, ...]] = {
            "encoder.0.weight": (h, o),
            "encoder.0.bias": (h,),
            "encoder.2.weight": (h, h),
            "encoder.2.bias": (h,),
        }
        if self.recurrent:
            shapes |= {
                "gru.weight_ih": (3 * h, h),
                "gru.weight_hh": (3 * h, h),
                "gru.bias_ih": (3 * h,),
                "gru.bias_hh": (3 * h,),
            }
        return shapes | {"actor.weight": (a, h), "actor.bias": (a,), "critic.weight": (1, h), "critic.bias": (1,)}


def _int_field(mf: ModelFile, key: str, low: int, high: int) -> int:
    value = mf.header.get(key)
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise ModelFileError(f"{mf.path}: field {key!r}: expected an integer in [{low}, {high}], got {value!r}")
    return value


def check_memory_file(mf: ModelFile) -> MemoryShape:
    """The architecture of a ``memory`` model file, its arrays checked against it."""
    if mf.header.get("kind") != "memory":
        raise ModelFileError(f"{mf.path}: a {mf.header.get('kind')} policy, not a memory policy")
    history = _int_field(mf, "history", 0, MAX_HISTORY)
    cap = _int_field(mf, "history_cap", 1, 1000)
    hidden = _int_field(mf, "hidden", 1, MAX_HIDDEN)
    obs_size = _int_field(mf, "obs_size", 1, 1 << 20)
    if obs_size != len(mf.header["fact_names"]) + history_size(history, cap):
        raise ModelFileError(f"{mf.path}: field 'obs_size' {obs_size} is not the facts plus the history features")
    recurrent = mf.header.get("recurrent")
    if not isinstance(recurrent, bool):
        raise ModelFileError(f"{mf.path}: field 'recurrent': expected true or false, got {recurrent!r}")
    shape = MemoryShape(obs_size, len(mf.header["action_names"]), hidden, recurrent, history, cap)
    got = {k: tuple(np.shape(v)) for k, v in mf.arrays.items()}
    if got != shape.arrays():
        raise ModelFileError(f"{mf.path}: weights do not match the architecture the header names")
    return shape


def _sigmoid(x: np.ndarray) -> np.ndarray:
    return 0.5 * (1.0 + np.tanh(0.5 * x))


class NumpyMemoryPolicy:
    """The forward pass of a ``memory`` policy in numpy (float64), one or many rows at a time."""

    def __init__(self, mf: ModelFile) -> None:
        self.shape = check_memory_file(mf)
        self.w = {k: np.asarray(v, dtype=np.float64) for k, v in mf.arrays.items()}

    def initial(self, n: int = 1) -> np.ndarray:
        """The hidden state at an episode's start (zeros; width 0 without a GRU)."""
        return np.zeros((n, self.shape.hidden if self.shape.recurrent else 0))

    def step(self, obs: np.ndarray, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(logits, next hidden) for a batch of observations."""
        w = self.w
        x = np.tanh(obs @ w["encoder.0.weight"].T + w["encoder.0.bias"])
        x = np.tanh(x @ w["encoder.2.weight"].T + w["encoder.2.bias"])
        if self.shape.recurrent:
            gi = x @ w["gru.weight_ih"].T + w["gru.bias_ih"]
            gh = h @ w["gru.weight_hh"].T + w["gru.bias_hh"]
            hid = self.shape.hidden
            r = _sigmoid(gi[:, :hid] + gh[:, :hid])
            z = _sigmoid(gi[:, hid : 2 * hid] + gh[:, hid : 2 * hid])
            n = np.tanh(gi[:, 2 * hid :] + r * gh[:, 2 * hid :])
            h = (1.0 - z) * n + z * h
            x = h
        return x @ w["actor.weight"].T + w["actor.bias"], h
