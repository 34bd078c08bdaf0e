"""Model-file array limits worked by hand from the header (``agents/model_limits.py``).

The SB3 budget is the weights of the policy, value and Q networks (each layer
``(inputs + 1) x outputs``), times 8 bytes, times 3 (Adam's two moments) and 2 (target
networks), plus 1 MiB of slack; the sums below are done by hand. Array shapes are held to
what the header implies, and an archive's declared bytes to the limit, read from each
member's npy header (both npy header versions).
"""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.model_limits import (
    MAX_TABLE_ROWS,
    SB3_SLACK_BYTES,
    check_npz_headers,
    check_shape,
    expected_shapes,
    sb3_budget,
)
from hg_marl.core.errors import ModelFileError

MIB = 1 << 20


def test_the_slack_is_one_mebibyte_and_the_table_limit_a_million_rows() -> None:
    assert SB3_SLACK_BYTES == MIB and MAX_TABLE_ROWS == 1_000_000


def test_ppo_with_default_layers_on_a_box_and_a_discrete_space() -> None:
    # 12 inputs (Box 3 x 4), 5 actions, [64, 64] for each of the three networks:
    # (12+1)*64 + (64+1)*64 + (64+1)*5 = 832 + 4160 + 325 = 5317 weights, 15951 for three
    header = {
        "algo": "PPO",
        "observation_space": {"type": "Box", "shape": [3, 4]},
        "action_space": {"type": "Discrete", "n": 5},
    }
    assert sb3_budget(header) == 15951 * 8 * 3 * 2 + MIB
    assert sb3_budget({**header, "policy_kwargs": None}) == 15951 * 8 * 3 * 2 + MIB


def test_a_dict_net_arch_names_each_network_and_the_unnamed_one_takes_the_default() -> None:
    # 3 inputs (Discrete 3, one-hot), 2 outputs (MultiBinary 2)
    # pi [8]: 4*8 + 9*2 = 50; vf [4]: 4*4 + 5*2 = 26; qf [64, 64]: 4*64 + 65*64 + 65*2 = 4546
    header = {
        "algo": "MaskablePPO",
        "observation_space": {"type": "Discrete", "n": 3},
        "action_space": {"type": "MultiBinary", "n": 2},
        "policy_kwargs": {"net_arch": {"pi": [8], "vf": [4]}, "activation_fn": "Tanh"},
    }
    assert sb3_budget(header) == (50 + 26 + 4546) * 48 + MIB


def test_a_dict_observation_adds_its_parts() -> None:
    # Box 2 + Discrete 3 = 5 inputs, 2 actions, one layer of 1 unit for each network:
    # (5+1)*1 + (1+1)*2 = 10 weights per network, 30 for three
    header = {
        "algo": "DQN",
        "observation_space": {
            "type": "Dict",
            "spaces": {"a": {"type": "Box", "shape": [2]}, "b": {"type": "Discrete", "n": 3}},
        },
        "action_space": {"type": "Discrete", "n": 2},
        "policy_kwargs": {"net_arch": [1]},
    }
    assert sb3_budget(header) == 30 * 48 + MIB


@pytest.mark.parametrize(
    "change",
    [
        {"algo": "SAC"},
        {"policy_kwargs": {"net_arch": [64], "lstm_hidden_size": 256}},
        {"policy_kwargs": {"net_arch": [64, 0]}},
        {"policy_kwargs": {"net_arch": {"pi": [64], "vf": "big"}}},
        {"policy_kwargs": "net_arch=[64]"},
        {"observation_space": {"type": "Graph"}},
        {"observation_space": {"type": "Box", "shape": [2, "x"]}},
        {"observation_space": {"type": "Discrete", "n": 2.5}},
        {"observation_space": {"type": "MultiBinary", "n": None}},
        {"observation_space": {"type": "Dict", "spaces": {"a": {"type": "Graph"}}}},
        {"observation_space": {"type": "Dict", "spaces": [1, 2]}},
        {"observation_space": "Box(3,)"},
        {"action_space": None},
    ],
)
def test_a_network_the_estimate_does_not_describe_has_no_budget(change: dict[str, object]) -> None:
    header = {
        "algo": "A2C",
        "observation_space": {"type": "Box", "shape": [4]},
        "action_space": {"type": "Discrete", "n": 2},
        "policy_kwargs": {"net_arch": [64]},
    }
    assert sb3_budget(header) is not None
    assert sb3_budget({**header, **change}) is None


def test_the_numpy_kinds_expected_shapes() -> None:
    header = {"action_names": ["a", "b", "c"], "fact_names": ["f", "g", "h", "i"]}
    assert expected_shapes({**header, "kind": "linear_softmax"}) == {"W": (3, 4), "b": (3,)}
    assert expected_shapes({**header, "kind": "table"}) == {"facts": (None, 4), "actions": (None,)}
    assert expected_shapes({**header, "kind": "sb3"}) is None
    assert expected_shapes({"kind": "linear_softmax"}) == {"W": (0, 0), "b": (0,)}


def test_shapes_are_held_to_the_header_with_the_reason() -> None:
    linear = {"W": (3, 4), "b": (3,)}
    table = {"facts": (None, 4), "actions": (None,)}
    assert check_shape("W", (3, 4), linear) is None
    assert check_shape("x", (3,), linear) == "array 'x' is not one of W, b"
    assert check_shape("W", (3, 5), linear) == "array 'W' declares shape (3, 5), the header implies (3, 4)"
    assert check_shape("W", (3, 4, 1), linear) == "array 'W' declares shape (3, 4, 1), the header implies (3, 4)"
    assert check_shape("b", (4,), linear) == "array 'b' declares shape (4,), the header implies (3,)"
    assert check_shape("facts", (10, 4), table) is None
    assert check_shape("facts", (10, 5), table) == "array 'facts' declares shape (10, 5), the header implies (rows, 4)"
    assert check_shape("actions", (MAX_TABLE_ROWS,), table) is None
    assert check_shape("actions", (MAX_TABLE_ROWS + 1,), table) == (
        "array 'actions' declares 1,000,001 rows, over the limit of 1,000,000"
    )


def _npz(path: Path, arrays: dict[str, np.ndarray], version: tuple[int, int] | None = None) -> Path:
    with zipfile.ZipFile(path, "w") as archive:
        for name, arr in arrays.items():
            buf = io.BytesIO()
            np.lib.format.write_array(buf, arr, version=version, allow_pickle=True)
            archive.writestr(f"{name}.npy", buf.getvalue())
    return path


@pytest.mark.parametrize("version", [(1, 0), (2, 0)])
def test_declared_bytes_are_summed_over_members_up_to_the_limit(tmp_path: Path, version: tuple[int, int]) -> None:
    # W: 3 x 4 float64 = 96 bytes, b: 3 int32 = 12 bytes: 108 in all
    path = _npz(tmp_path / "w.npz", {"W": np.zeros((3, 4)), "b": np.zeros(3, dtype=np.int32)}, version)
    shapes = {"W": (3, 4), "b": (3,)}
    check_npz_headers(path, shapes, 108)
    check_npz_headers(path, None, 108)
    with pytest.raises(ModelFileError) as info:
        check_npz_headers(path, shapes, 107)
    assert str(info.value) == (
        f"{path}: more than 107 bytes of arrays declared, over the limit for its header (checked before reading)"
    )
    with pytest.raises(ModelFileError, match=r"array 'W' declares shape \(3, 4\), the header implies \(4, 3\)"):
        check_npz_headers(path, {"W": (4, 3), "b": (3,)}, 108)


def test_objects_and_non_arrays_are_refused(tmp_path: Path) -> None:
    path = _npz(tmp_path / "o.npz", {"W": np.array([{"x": 1}], dtype=object)})
    with pytest.raises(ModelFileError, match=r"array 'W' has dtype object; only numbers are allowed"):
        check_npz_headers(path, None, MIB)
    for kind in ("b", "i", "u", "f"):
        ok = _npz(tmp_path / f"{kind}.npz", {"x": np.zeros(2, dtype=np.dtype(f"{kind}1" if kind != "f" else "f4"))})
        check_npz_headers(ok, None, MIB)
    with zipfile.ZipFile(tmp_path / "n.npz", "w") as archive:
        archive.writestr("readme.txt", "hello")
    with pytest.raises(ModelFileError, match=r"member 'readme.txt' is not an array"):
        check_npz_headers(tmp_path / "n.npz", None, MIB)
    complex_ = _npz(tmp_path / "c.npz", {"x": np.zeros(2, dtype=np.complex64)})
    with pytest.raises(ModelFileError, match=r"has dtype complex64; only numbers are allowed"):
        check_npz_headers(complex_, None, MIB)
