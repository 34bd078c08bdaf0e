"""The SB3 size and argument limits, pinned for the mutation gate.

The expected ranges are the SB3 documentation's, as the module's docstring states them
(``n_steps`` >= 1, PPO's ``batch_size`` > 1, ``gamma`` in [0, 1], ...), written out here
as the table the tests read; every bound is inclusive, so the bound itself passes and one
step past it (1 for an integer, a little more for a number) is refused. The weight count
between hidden layers is the sum of ``a * b`` over consecutive sizes, worked by hand.
"""

from __future__ import annotations

from typing import Any

import pytest

from hg_marl.agents.sb3_limits import (
    MAX_BUFFER,
    MAX_LAYERS,
    MAX_LSTM_LAYERS,
    MAX_LSTM_UNITS,
    MAX_PARAMETERS,
    MAX_UNITS,
    check_kwargs,
    check_net_arch,
    check_policy_kwargs,
    check_value,
)
from hg_marl.core.errors import ConfigError, ModelFileError

# key: (kind, lowest accepted, highest accepted, a value just below, a value just above)
SPEC: dict[str, tuple[str, float, float, float, float]] = {
    "learning_rate": ("float", 1e-12, 10.0, 0.0, 10.5),
    "n_steps": ("int", 1, 1_000_000, 0, 1_000_001),
    "batch_size": ("int", 2, 1_000_000, 1, 1_000_001),
    "n_epochs": ("int", 1, 10_000, 0, 10_001),
    "gamma": ("float", 0.0, 1.0, -1e-9, 1.5),
    "gae_lambda": ("float", 0.0, 1.0, -1e-9, 1.5),
    "clip_range": ("float", 1e-12, 100.0, 0.0, 100.5),
    "clip_range_vf": ("float", 1e-12, 100.0, 0.0, 100.5),
    "ent_coef": ("float", 0.0, 1e6, -1e-9, 1e6 + 0.5),
    "vf_coef": ("float", 0.0, 1e6, -1e-9, 1e6 + 0.5),
    "max_grad_norm": ("float", 1e-12, 1e6, 0.0, 1e6 + 0.5),
    "target_kl": ("float", 1e-12, 1e6, 0.0, 1e6 + 0.5),
    "sde_sample_freq": ("int", -1, 1_000_000, -2, 1_000_001),
    "stats_window_size": ("int", 1, 1_000_000, 0, 1_000_001),
    "rms_prop_eps": ("float", 1e-12, 1.0, 0.0, 1.5),
    "buffer_size": ("int", 1, 1_000_000, 0, 1_000_001),
    "learning_starts": ("int", 0, 100_000_000, -1, 100_000_001),
    "train_freq": ("int", 1, 1_000_000, 0, 1_000_001),
    "gradient_steps": ("int", -1, 1_000_000, -2, 1_000_001),
    "target_update_interval": ("int", 1, 100_000_000, 0, 100_000_001),
    "exploration_fraction": ("float", 0.0, 1.0, -1e-9, 1.5),
    "exploration_initial_eps": ("float", 0.0, 1.0, -1e-9, 1.5),
    "exploration_final_eps": ("float", 0.0, 1.0, -1e-9, 1.5),
    "tau": ("float", 0.0, 1.0, -1e-9, 1.5),
    "verbose": ("int", 0, 2, -1, 3),
}
BOOLS = ("normalize_advantage", "use_sde", "use_rms_prop", "optimize_memory_usage")


@pytest.mark.parametrize("key", list(SPEC))
def test_each_argument_accepts_its_documented_bounds_and_refuses_one_step_past(key: str) -> None:
    _, low, high, below, above = SPEC[key]
    check_value(key, low, key, ConfigError)
    check_value(key, high, key, ConfigError)
    for bad in (below, above):
        with pytest.raises(ConfigError, match=rf"^--hp {key}: expected "):
            check_value(key, bad, f"--hp {key}", ConfigError)


def test_the_replay_buffer_limit_is_sb3s_default_million() -> None:
    assert MAX_BUFFER == 1_000_000


@pytest.mark.parametrize("key", [k for k, v in SPEC.items() if v[0] == "int"])
def test_an_integer_argument_refuses_a_float_even_a_whole_one_and_a_bool(key: str) -> None:
    for bad in (float(SPEC[key][1]), True, "1"):
        with pytest.raises(ConfigError, match=rf"^{key}: expected an integer, got "):
            check_value(key, bad, key, ConfigError)


def test_a_number_argument_takes_an_int_and_refuses_nan_and_text() -> None:
    check_value("gamma", 1, "gamma", ConfigError)
    with pytest.raises(ConfigError, match=r"^gamma: expected a number in \[0, 1\], got nan$"):
        check_value("gamma", float("nan"), "gamma", ConfigError)
    with pytest.raises(ConfigError, match=r"^gamma: expected a number, got 'abc'$"):
        check_value("gamma", "abc", "gamma", ConfigError)


def test_the_range_message_names_an_integers_bounds() -> None:
    """``{:g}`` of 1 and 1,000,000: ``[1, 1e+06]``."""
    with pytest.raises(ModelFileError, match=r"^n_steps: expected an integer in \[1, 1e\+06\], got 0$"):
        check_value("n_steps", 0, "n_steps", ModelFileError)


@pytest.mark.parametrize("key", BOOLS)
def test_a_switch_takes_only_true_or_false(key: str) -> None:
    check_value(key, True, key, ConfigError)
    check_value(key, False, key, ConfigError)
    with pytest.raises(ConfigError, match=rf"^{key}: expected true or false, got 1$"):
        check_value(key, 1, key, ConfigError)


def test_none_passes_only_where_sb3s_default_is_none() -> None:
    check_value("clip_range_vf", None, "x", ConfigError)
    check_value("target_kl", None, "x", ConfigError)
    with pytest.raises(ConfigError):
        check_value("clip_range", None, "x", ConfigError)


def test_an_unlisted_key_passes_to_sb3_unchecked() -> None:
    check_value("policy", object(), "x", ConfigError)


def test_check_kwargs_names_the_option_and_the_key() -> None:
    with pytest.raises(ConfigError, match=r"^--hp gamma: expected a number in \[0, 1\], got 2$"):
        check_kwargs({"n_steps": 8, "gamma": 2}, "--hp", ConfigError)
    with pytest.raises(ConfigError, match=r"^--hp policy_kwargs: expected a mapping, got \[1\]$"):
        check_kwargs({"policy_kwargs": [1]}, "--hp", ConfigError)
    check_kwargs({"policy_kwargs": None, "gamma": 0.5}, "--hp", ConfigError)


def test_layer_sizes_run_from_1_to_max_units() -> None:
    assert MAX_UNITS == 4096
    check_net_arch([1, MAX_UNITS], "net_arch", ConfigError)
    for bad in (0, MAX_UNITS + 1, True, 8.0):
        with pytest.raises(ConfigError, match=rf"^net_arch: layer sizes must be integers in \[1, 4096\], got {bad!r}$"):
            check_net_arch([8, bad], "net_arch", ConfigError)


def test_net_arch_must_be_a_list_of_at_most_max_layers() -> None:
    assert MAX_LAYERS == 16
    check_net_arch([], "net_arch", ConfigError)
    with pytest.raises(ConfigError, match=r"^net_arch: expected a list of at most 16 layer sizes, got \(8, 8\)$"):
        check_net_arch((8, 8), "net_arch", ConfigError)
    with pytest.raises(ConfigError, match=r"^net_arch\.vf: expected a list of at most 16 layer sizes"):
        check_net_arch({"pi": [8], "vf": [8] * 17}, "net_arch", ConfigError)


def test_a_dict_net_arch_names_its_unknown_keys_sorted() -> None:
    with pytest.raises(ConfigError, match=r"^net_arch: unknown key\(s\) q, x \(known: pi, vf, qf\)$"):
        check_net_arch({"x": [8], "pi": [8], "q": [8]}, "net_arch", ConfigError)
    check_net_arch({"qf": [8, 8]}, "net_arch", ConfigError)


def test_weights_between_hidden_layers_up_to_the_limit_pass_one_pair_more_is_refused() -> None:
    """[4000, 4000]: 16,000,000 weights, exactly the limit; [4000, 4000, 1]: 4,000 more.

    For a dict the networks add up: pi [2000, 4000] and vf [2000, 4000] are 8,000,000 each,
    and a qf of [1, 2] adds 2.
    """
    assert MAX_PARAMETERS == 16_000_000
    check_net_arch([4000, 4000], "net_arch", ConfigError)
    check_net_arch({"pi": [2000, 4000], "vf": [2000, 4000]}, "net_arch", ConfigError)
    with pytest.raises(
        ConfigError, match=r"^net_arch: 16,004,000 weights between hidden layers, over the limit 16,000,000$"
    ):
        check_net_arch([4000, 4000, 1], "net_arch", ConfigError)
    with pytest.raises(ConfigError, match=r"^net_arch: 16,000,002 weights"):
        check_net_arch({"pi": [2000, 4000], "vf": [2000, 4000], "qf": [1, 2]}, "net_arch", ConfigError)


@pytest.mark.parametrize(("key", "most"), [("lstm_hidden_size", 1024), ("n_lstm_layers", 4)])
def test_an_lstm_size_runs_from_1_to_its_limit(key: str, most: int) -> None:
    assert (MAX_LSTM_UNITS, MAX_LSTM_LAYERS) == (1024, 4)
    check_policy_kwargs({key: 1}, "policy_kwargs", ConfigError)
    check_policy_kwargs({key: most}, "policy_kwargs", ConfigError)
    check_policy_kwargs({key: None}, "policy_kwargs", ConfigError)
    bad: Any
    for bad in (0, most + 1, True, 2.0):
        with pytest.raises(ConfigError, match=rf"^policy_kwargs\.{key}: expected an integer in \[1, {most}\], got "):
            check_policy_kwargs({key: bad}, "policy_kwargs", ConfigError)


def test_policy_kwargs_net_arch_is_checked_under_its_own_name() -> None:
    with pytest.raises(ConfigError, match=r"^--hp policy_kwargs\.net_arch: expected a list"):
        check_kwargs({"policy_kwargs": {"net_arch": "big"}}, "--hp", ConfigError)
