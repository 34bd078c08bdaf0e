"""What an SB3 model may ask for, checked before SB3 or torch allocates anything.

One home for the limits on the two ways a network's size reaches SB3: ``--hp`` /
``--hyperparams`` (training) and a model header's ``policy_kwargs`` (loading). A layer
of 200,000 units asks torch for 200,000 squared float32 weights before any error could be raised, so sizes are
bounded here: at most :data:`MAX_LAYERS` hidden layers of at most :data:`MAX_UNITS`
units, and at most :data:`MAX_PARAMETERS` weights between hidden layers (an estimate
that leaves out the input and output layers, whose sizes come from the scenario and
are bounded by its own limits).

The constructor arguments are checked against what the algorithms accept
(:data:`RULES`, from the SB3 documentation: ``n_steps`` >= 1, ``batch_size`` > 1 for PPO,
``gamma`` in [0, 1], ...), so ``learning_rate=abc`` or ``n_steps=0`` is one line naming
the key instead of an assertion deep inside SB3.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from typing import Any

from hg_marl.core.errors import HgMarlError

MAX_UNITS = 4096
"""Widest hidden layer accepted."""
MAX_LAYERS = 16
"""Most hidden layers accepted (per network, ``pi`` and ``vf`` each)."""
MAX_PARAMETERS = 16_000_000
"""Most weights between consecutive hidden layers (4 bytes each as float32; Adam keeps two more copies)."""

MAX_LSTM_UNITS = 1024
"""Widest LSTM accepted (RecurrentPPO's ``lstm_hidden_size``: 4 x 1024 x 1024 weights per layer)."""
MAX_LSTM_LAYERS = 4
"""Most stacked LSTM layers accepted (RecurrentPPO's ``n_lstm_layers``)."""

MAX_BUFFER = 1_000_000
"""Largest DQN replay buffer (SB3's default)."""

_INT, _FLOAT, _BOOL = "int", "float", "bool"

RULES: Mapping[str, tuple[str, float | None, float | None]] = {
    "learning_rate": (_FLOAT, 1e-12, 10.0),
    "n_steps": (_INT, 1, 1_000_000),
    "batch_size": (_INT, 2, 1_000_000),
    "n_epochs": (_INT, 1, 10_000),
    "gamma": (_FLOAT, 0.0, 1.0),
    "gae_lambda": (_FLOAT, 0.0, 1.0),
    "clip_range": (_FLOAT, 1e-12, 100.0),
    "clip_range_vf": (_FLOAT, 1e-12, 100.0),
    "ent_coef": (_FLOAT, 0.0, 1e6),
    "vf_coef": (_FLOAT, 0.0, 1e6),
    "max_grad_norm": (_FLOAT, 1e-12, 1e6),
    "target_kl": (_FLOAT, 1e-12, 1e6),
    "normalize_advantage": (_BOOL, None, None),
    "use_sde": (_BOOL, None, None),
    "sde_sample_freq": (_INT, -1, 1_000_000),
    "stats_window_size": (_INT, 1, 1_000_000),
    "use_rms_prop": (_BOOL, None, None),
    "rms_prop_eps": (_FLOAT, 1e-12, 1.0),
    "buffer_size": (_INT, 1, MAX_BUFFER),
    "learning_starts": (_INT, 0, 100_000_000),
    "train_freq": (_INT, 1, 1_000_000),
    "gradient_steps": (_INT, -1, 1_000_000),
    "target_update_interval": (_INT, 1, 100_000_000),
    "exploration_fraction": (_FLOAT, 0.0, 1.0),
    "exploration_initial_eps": (_FLOAT, 0.0, 1.0),
    "exploration_final_eps": (_FLOAT, 0.0, 1.0),
    "tau": (_FLOAT, 0.0, 1.0),
    "optimize_memory_usage": (_BOOL, None, None),
    "verbose": (_INT, 0, 2),
}
"""Type and inclusive range of each constructor argument; ``None`` is accepted where SB3's default is None
(``clip_range_vf``, ``target_kl``). Keys not listed here pass through to SB3 (its own checks apply)."""

_NONE_OK = ("clip_range_vf", "target_kl")


def check_value(key: str, value: Any, what: str, error: type[HgMarlError]) -> None:
    """One constructor argument against :data:`RULES` (an unlisted key passes)."""
    rule = RULES.get(key)
    if rule is None or (value is None and key in _NONE_OK):
        return
    kind, low, high = rule
    if kind == _BOOL:
        if not isinstance(value, bool):
            raise error(f"{what}: expected true or false, got {value!r}")
        return
    if isinstance(value, bool) or not isinstance(value, int | float) or (kind == _INT and not isinstance(value, int)):
        raise error(f"{what}: expected {'an integer' if kind == _INT else 'a number'}, got {value!r}")
    if not math.isfinite(value) or (low is not None and value < low) or (high is not None and value > high):
        raise error(
            f"{what}: expected {'an integer' if kind == _INT else 'a number'} in [{low:g}, {high:g}], got {value!r}"
        )


def _layers(value: Any, what: str, error: type[HgMarlError]) -> list[int]:
    if not isinstance(value, list) or len(value) > MAX_LAYERS:
        raise error(f"{what}: expected a list of at most {MAX_LAYERS} layer sizes, got {value!r}")
    for size in value:
        if isinstance(size, bool) or not isinstance(size, int) or not 1 <= size <= MAX_UNITS:
            raise error(f"{what}: layer sizes must be integers in [1, {MAX_UNITS}], got {size!r}")
    return value


def check_net_arch(value: Any, what: str, error: type[HgMarlError]) -> None:
    """``net_arch`` as SB3 takes it: a list of sizes, or ``{pi: [...], vf: [...]}`` (``qf`` for DQN)."""
    if isinstance(value, dict):
        unknown = sorted(set(value) - {"pi", "vf", "qf"})
        if unknown:
            raise error(f"{what}: unknown key(s) {', '.join(map(str, unknown))} (known: pi, vf, qf)")
        networks = [_layers(v, f"{what}.{k}", error) for k, v in value.items()]
    else:
        networks = [_layers(value, what, error)]
    total = sum(a * b for layers in networks for a, b in itertools.pairwise(layers))
    if total > MAX_PARAMETERS:
        raise error(f"{what}: {total:,} weights between hidden layers, over the limit {MAX_PARAMETERS:,}")


def check_kwargs(kwargs: Mapping[str, Any], what: str, error: type[HgMarlError]) -> None:
    """Every constructor argument in :data:`RULES` and ``policy_kwargs.net_arch``."""
    for key, value in kwargs.items():
        check_value(key, value, f"{what} {key}", error)
    policy_kwargs = kwargs.get("policy_kwargs")
    if policy_kwargs is not None:
        check_policy_kwargs(policy_kwargs, f"{what} policy_kwargs", error)


def check_policy_kwargs(policy_kwargs: Any, what: str, error: type[HgMarlError]) -> None:
    """``policy_kwargs``: an object whose ``net_arch`` (if any) fits the limits."""
    if not isinstance(policy_kwargs, dict):
        raise error(f"{what}: expected a mapping, got {policy_kwargs!r}")
    if "net_arch" in policy_kwargs:
        check_net_arch(policy_kwargs["net_arch"], f"{what}.net_arch", error)
    for key, most in (("lstm_hidden_size", MAX_LSTM_UNITS), ("n_lstm_layers", MAX_LSTM_LAYERS)):
        value = policy_kwargs.get(key)
        if value is not None and not (isinstance(value, int) and not isinstance(value, bool) and 1 <= value <= most):
            raise error(f"{what}.{key}: expected an integer in [1, {most}], got {value!r}")
