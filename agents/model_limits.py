"""How large a model file's arrays may be, worked out from its header before any array is read.

A ``.npz`` states each array's dtype and shape in a few bytes at the start of each
member (the npy header), so a small compressed file can claim gigabytes. The loader
(:func:`hg_marl.agents.model_file.read_arrays`) reads those headers first and holds them
to what the model header implies:

- ``linear_softmax``: exactly ``W (actions, facts)`` and ``b (actions,)``;
- ``table``: ``facts (rows, facts)`` and ``actions (rows,)`` with at most
  :data:`MAX_TABLE_ROWS` rows;
- ``sb3``: at most :func:`sb3_budget` bytes in all: the weights the header's network
  (``policy_kwargs.net_arch`` between its observation and action spaces) can have,
  counted for a policy, a value and a Q network, doubled for target networks, tripled
  for Adam's two moments, at 8 bytes each, plus :data:`SB3_SLACK_BYTES`; a network this
  estimate does not describe (an unknown algorithm, an LSTM) is held to
  :data:`~hg_marl.agents.model_file.MAX_ARRAY_BYTES`.

The arrays are then read only if they fit. docs/inputs.md lists these limits.
"""

from __future__ import annotations

import itertools
import math
import zipfile
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.core.errors import ModelFileError

MAX_TABLE_ROWS = 1_000_000
"""Most rows of a ``table`` policy (one per distinct observation seen in the traces)."""

SB3_SLACK_BYTES = 1 << 20
"""Bytes allowed beyond the estimate of an SB3 model's weights (counters, ``log_std``, step counts)."""

SB3_ALGOS = ("PPO", "MaskablePPO", "A2C", "DQN")
"""Algorithms whose networks :func:`sb3_budget` describes (MLP policy and value/Q networks)."""

_DEFAULT_LAYERS = [64, 64]
"""SB3's default hidden layers for an MLP policy."""

Shape = tuple[int | None, ...]
"""An expected array shape; ``None`` stands for a dimension the header does not fix."""


def _width(space: Any) -> int | None:
    """Inputs a space gives an MLP once flattened (one-hot for Discrete), or None if unknown."""
    if not isinstance(space, Mapping):
        return None
    kind = space.get("type")
    if kind == "Discrete" and isinstance(space.get("n"), int):
        return int(space["n"])
    if kind == "MultiBinary" and isinstance(space.get("n"), int):
        return int(space["n"])
    if kind == "Box" and isinstance(space.get("shape"), list) and all(isinstance(n, int) for n in space["shape"]):
        return math.prod(space["shape"])
    if kind == "Dict" and isinstance(space.get("spaces"), Mapping):
        widths = [_width(v) for v in space["spaces"].values()]
        return None if any(w is None for w in widths) else sum(w for w in widths if w is not None)
    return None


def _networks(policy_kwargs: Any) -> list[list[int]] | None:
    """The hidden layers of the policy, value and Q networks (defaults where unsaid), or None if unknown."""
    if policy_kwargs is None:
        policy_kwargs = {}
    if not isinstance(policy_kwargs, Mapping) or set(policy_kwargs) - {"net_arch", "activation_fn", "ortho_init"}:
        return None
    arch = policy_kwargs.get("net_arch", _DEFAULT_LAYERS)
    if isinstance(arch, Mapping):
        nets = [arch.get(k, _DEFAULT_LAYERS) for k in ("pi", "vf", "qf")]
    else:
        nets = [arch, arch, arch]
    if not all(isinstance(n, list) and all(isinstance(u, int) and u > 0 for u in n) for n in nets):
        return None
    return nets


def sb3_budget(header: Mapping[str, Any]) -> int | None:
    """Most bytes of arrays an SB3 model file with this header can need, or None if not estimated."""
    if header.get("algo") not in SB3_ALGOS:
        return None
    inputs, outputs = _width(header.get("observation_space")), _width(header.get("action_space"))
    nets = _networks(header.get("policy_kwargs"))
    if inputs is None or outputs is None or nets is None:
        return None
    weights = sum((a + 1) * b for net in nets for a, b in itertools.pairwise([inputs, *net, outputs]))
    return weights * 8 * 3 * 2 + SB3_SLACK_BYTES


def expected_shapes(header: Mapping[str, Any]) -> dict[str, Shape] | None:
    """The arrays a numpy kind (``linear_softmax``, ``table``) must hold, by name; None for other kinds."""
    n_a, n_f = len(header.get("action_names") or ()), len(header.get("fact_names") or ())
    if header.get("kind") == "linear_softmax":
        return {"W": (n_a, n_f), "b": (n_a,)}
    if header.get("kind") == "table":
        return {"facts": (None, n_f), "actions": (None,)}
    return None


def check_shape(name: str, shape: tuple[int, ...], expected: Mapping[str, Shape]) -> str | None:
    """Why an array's declared shape does not fit ``expected`` (None: it fits)."""
    if name not in expected:
        return f"array {name!r} is not one of {', '.join(sorted(expected))}"
    want = expected[name]
    if len(shape) != len(want) or any(w is not None and w != s for w, s in zip(want, shape, strict=False)):
        shown = "(" + ", ".join("rows" if w is None else str(w) for w in want) + ("," if len(want) == 1 else "") + ")"
        return f"array {name!r} declares shape {shape}, the header implies {shown}"
    if None in want and shape and shape[0] > MAX_TABLE_ROWS:
        return f"array {name!r} declares {shape[0]:,} rows, over the limit of {MAX_TABLE_ROWS:,}"
    return None


def check_npz_headers(path: Path, shapes: Mapping[str, Shape] | None, limit: int) -> None:
    """Read every array's header (dtype, shape) from the archive before any data is loaded.

    Refuses object arrays (a pickle inside), a shape ``shapes`` does not allow and more
    than ``limit`` bytes in all, so a small compressed file cannot make the loader
    allocate gigabytes.
    """
    total = 0
    with zipfile.ZipFile(path) as archive:
        for name in archive.namelist():
            if not name.endswith(".npy"):
                raise ModelFileError(f"{path}: member {name!r} is not an array")
            with archive.open(name) as member:
                version = np.lib.format.read_magic(member)
                if version == (1, 0):
                    shape, _, dtype = np.lib.format.read_array_header_1_0(member)
                else:
                    shape, _, dtype = np.lib.format.read_array_header_2_0(member)
            if dtype.kind not in "biuf" or dtype.hasobject:
                raise ModelFileError(f"{path}: array {name[:-4]!r} has dtype {dtype}; only numbers are allowed")
            misfit = check_shape(name[:-4], shape, shapes) if shapes is not None else None
            if misfit is not None:
                raise ModelFileError(f"{path}: {misfit} (checked before reading)")
            total += int(np.prod(shape, dtype=np.float64)) * dtype.itemsize
            if total > limit:
                raise ModelFileError(
                    f"{path}: more than {limit:,} bytes of arrays declared, over the limit for its header "
                    "(checked before reading)"
                )
