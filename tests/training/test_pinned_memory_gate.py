"""The ``memory`` model file's checks at their bounds and its numpy forward pass by hand.

A one-unit network makes every number of the forward pass a few scalar operations,
worked here with ``math`` (the logistic as ``1 / (1 + e^-x)``, the GRU's gates in torch's
order reset, update, new), independently of the numpy code under test.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.memory_numpy import MAX_HIDDEN, NumpyMemoryPolicy, check_memory_file
from hg_marl.agents.model_file import ModelFile
from hg_marl.core.errors import ModelFileError
from hg_marl.envs.history import history_size
from tests.memory_arrays import memory_arrays

FACTS, ACTIONS = ["f0", "f1", "f2"], ["a0", "a1"]


def _arrays(hidden: int, obs: int, recurrent: bool, fill: float = 0.0) -> dict[str, np.ndarray]:
    return memory_arrays(hidden, obs, len(ACTIONS), recurrent, fill)


def _file(**fields: Any) -> ModelFile:
    history, cap = fields.get("history", 0), fields.get("history_cap", 8)
    sane = type(history) is int and 0 <= history <= 64 and type(cap) is int and cap >= 1
    obs = len(FACTS) + history_size(history, cap) if sane else 3
    header = {
        "kind": "memory",
        "fact_names": FACTS,
        "action_names": ACTIONS,
        "history": 0,
        "history_cap": 8,
        "hidden": 4,
        "obs_size": obs,
        "recurrent": False,
    }
    header |= {k: v for k, v in fields.items() if k != "_arrays"}
    hidden = header["hidden"] if isinstance(header["hidden"], int) and 0 < header["hidden"] <= 8 else 4
    width = header["obs_size"] if 1 <= header["obs_size"] <= 5000 else 3
    arrays = fields.pop("_arrays", None) or _arrays(hidden, width, header["recurrent"] is True)
    return ModelFile(Path("memory.json"), header, arrays)


@pytest.mark.parametrize(
    "fields",
    [
        {"history": 0},
        {"history": 64},
        {"history": 2, "history_cap": 1},
        {"history": 2, "history_cap": 1000},
        {"hidden": 1},
        {"recurrent": True},
    ],
)
def test_headers_at_their_bounds_load(fields: dict[str, Any]) -> None:
    shape = check_memory_file(_file(**fields))
    assert shape.history == fields.get("history", 0) and shape.n_actions == 2


def test_the_widest_layer_is_1024_units() -> None:
    assert MAX_HIDDEN == 1024
    wide = _file(hidden=1024, _arrays=_arrays(1024, 3, False))
    assert check_memory_file(wide).hidden == 1024
    with pytest.raises(ModelFileError, match=r"field 'hidden': expected an integer in \[1, 1024\], got 1025"):
        check_memory_file(_file(hidden=1025))


@pytest.mark.parametrize(
    ("fields", "message"),
    [
        ({"kind": "table"}, "a table policy, not a memory policy"),
        ({"history": -1}, r"field 'history': expected an integer in \[0, 64\], got -1"),
        ({"history": 65}, r"field 'history': expected an integer in \[0, 64\], got 65"),
        ({"history": True}, r"field 'history': expected an integer in \[0, 64\], got True"),
        ({"history": 2, "history_cap": 0}, r"field 'history_cap': expected an integer in \[1, 1000\], got 0"),
        ({"history": 2, "history_cap": 1001}, r"field 'history_cap': expected an integer in \[1, 1000\], got 1001"),
        ({"hidden": 0}, r"field 'hidden': expected an integer in \[1, 1024\], got 0"),
        ({"hidden": 2.0}, r"field 'hidden': expected an integer in \[1, 1024\], got 2.0"),
        ({"obs_size": 0}, r"field 'obs_size': expected an integer in \[1, 1048576\], got 0"),
        ({"obs_size": (1 << 20) + 1}, r"field 'obs_size': expected an integer in \[1, 1048576\], got 1048577"),
        ({"obs_size": 4}, "field 'obs_size' 4 is not the facts plus the history features"),
        ({"recurrent": 1}, "field 'recurrent': expected true or false, got 1"),
        ({"_arrays": _arrays(4, 3, True)}, "weights do not match the architecture the header names"),
        ({"_arrays": _arrays(5, 3, False)}, "weights do not match the architecture the header names"),
    ],
)
def test_bad_headers_and_weights_are_refused_naming_the_field(fields: dict[str, Any], message: str) -> None:
    with pytest.raises(ModelFileError, match=message):
        check_memory_file(_file(**fields))


def _logistic(x: float) -> float:
    return 1.0 / (1.0 + math.exp(-x))


def _one_unit(recurrent: bool) -> NumpyMemoryPolicy:
    w = _arrays(1, 3, recurrent)
    w["encoder.0.weight"][:] = [[0.5, -1.0, 2.0]]
    w["encoder.0.bias"][:] = [0.1]
    w["encoder.2.weight"][:] = [[1.5]]
    w["encoder.2.bias"][:] = [-0.2]
    w["actor.weight"][:] = [[2.0], [-3.0]]
    w["actor.bias"][:] = [0.25, 0.5]
    if recurrent:
        w["gru.weight_ih"][:] = [[0.3], [-0.7], [1.1]]  # reset, update, new
        w["gru.weight_hh"][:] = [[0.2], [0.4], [-0.6]]
        w["gru.bias_ih"][:] = [0.05, -0.1, 0.15]
        w["gru.bias_hh"][:] = [0.0, 0.2, -0.3]
    return NumpyMemoryPolicy(_file(hidden=1, recurrent=recurrent, _arrays=w))


def test_the_forward_pass_without_memory_by_hand() -> None:
    net = _one_unit(False)
    obs = np.array([[1.0, 2.0, 0.5]])
    x = math.tanh(0.5 * 1.0 - 1.0 * 2.0 + 2.0 * 0.5 + 0.1)
    x = math.tanh(1.5 * x - 0.2)
    h0 = net.initial(2)
    assert h0.shape == (2, 0)
    logits, h = net.step(obs, net.initial(1))
    assert logits[0].tolist() == pytest.approx([2.0 * x + 0.25, -3.0 * x + 0.5], rel=1e-12)
    assert h.shape == (1, 0)


def test_the_gru_step_by_hand_gates_in_torch_order() -> None:
    net = _one_unit(True)
    assert net.initial(3).tolist() == [[0.0], [0.0], [0.0]]
    obs = np.array([[1.0, 2.0, 0.5]])
    x = math.tanh(1.5 * math.tanh(0.5 - 2.0 + 1.0 + 0.1) - 0.2)
    h = 0.4  # a hidden state carried from an earlier turn
    r = _logistic(0.3 * x + 0.05 + 0.2 * h + 0.0)
    z = _logistic(-0.7 * x - 0.1 + 0.4 * h + 0.2)
    n = math.tanh(1.1 * x + 0.15 + r * (-0.6 * h - 0.3))
    h1 = (1.0 - z) * n + z * h
    logits, out = net.step(obs, np.array([[h]]))
    assert out[0, 0] == pytest.approx(h1, rel=1e-12)
    assert logits[0].tolist() == pytest.approx([2.0 * h1 + 0.25, -3.0 * h1 + 0.5], rel=1e-12)
