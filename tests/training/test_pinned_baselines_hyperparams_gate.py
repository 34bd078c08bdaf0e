"""The hyperparameter files' resolution, overrides and refusals, pinned for the mutation gate.

Expected values are worked by hand from the rules the module's docstring states: a
scenario falls back to ``default``; ``key=value`` overrides are YAML, dotted keys nest;
``n_envs`` lies in [1, 256] and ``n_timesteps`` in [1, 10**10]; a file is at most 1 MiB;
PPO-like rollouts need ``n_steps x n_envs >= 2``; activation names become torch classes.
The YAML files here are written by the tests, so every value is known in advance.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from hg_marl.training.baselines.hyperparams import (
    ALGOS,
    MAX_ENVS,
    MAX_TIMESTEPS,
    MAX_YAML_BYTES,
    HyperparamError,
    Hyperparams,
    accepted_keys,
    hyperparams_path,
    load_hyperparams,
    model_kwargs,
    parse_override,
)


def _yaml(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "hp.yml"
    path.write_text(text, encoding="utf-8")
    return path


def test_the_limits_are_the_documented_ones() -> None:
    """256 environments, 10**10 steps and 1 MiB, as the module and the docs state."""
    assert (MAX_ENVS, MAX_TIMESTEPS, MAX_YAML_BYTES) == (256, 10**10, 2**20)


def test_class_names_and_plain_data() -> None:
    """Each command-line name maps to its SB3 class; ``as_dict`` lists ours before the kwargs."""
    assert Hyperparams("maskable_ppo").class_name == "MaskablePPO"
    assert Hyperparams("recurrent_ppo").class_name == "RecurrentPPO"
    hp = Hyperparams("dqn", "MlpPolicy", 3, 500, {"gamma": 0.5})
    assert hp.as_dict() == {"algo": "dqn", "policy": "MlpPolicy", "n_envs": 3, "n_timesteps": 500, "gamma": 0.5}
    assert list(hp.as_dict()) == ["algo", "policy", "n_envs", "n_timesteps", "gamma"]
    assert (Hyperparams("ppo").policy, Hyperparams("ppo").n_envs, Hyperparams("ppo").n_timesteps) == (
        "MlpPolicy",
        1,
        100_000,
    )


def test_the_packaged_file_is_named_after_the_algorithm() -> None:
    """``training/hyperparams/{algo}.yml``, one per algorithm of :data:`ALGOS`."""
    for algo in ALGOS:
        path = hyperparams_path(algo)
        assert path.name == f"{algo}.yml" and path.parent.name == "hyperparams" and path.is_file()
    with pytest.raises(HyperparamError, match=r"^unknown algorithm 'sac'; available: ppo, a2c, dqn, maskable_ppo"):
        hyperparams_path("sac")


def test_an_override_splits_on_the_first_equals_and_strips_the_key_parts() -> None:
    """``" a . b =x=1"``: keys ``a``, ``b``; the value is the YAML after the first ``=``."""
    assert parse_override(" a . b =x=1") == (["a", "b"], "x=1")
    assert parse_override("lr=0.001") == (["lr"], 0.001)
    assert parse_override("flag=true") == (["flag"], True)
    assert parse_override("k=") == (["k"], None)  # an empty value is YAML null
    assert parse_override("k=   ") == (["k"], None)
    for bad in ("k", "=1", "  =1"):
        with pytest.raises(HyperparamError, match="expected key=value"):
            parse_override(bad)
    with pytest.raises(HyperparamError, match=r"^hyperparameter override 'k=\[1': value is not valid YAML"):
        parse_override("k=[1")
    with pytest.raises(HyperparamError, match=r"^hyperparameter override k: a number of"):
        parse_override(" k =" + "9" * 5000)


def test_accepted_keys_leave_out_what_the_trainer_supplies() -> None:
    """``self``, ``policy``, ``env``, ``seed``, ``device`` and ``_init_setup_model`` are not options."""
    keys = accepted_keys("ppo")
    assert "learning_rate" in keys and "n_steps" in keys
    for own in ("self", "policy", "env", "seed", "device", "_init_setup_model"):
        assert own not in keys


def test_a_scenario_reads_its_own_entry_else_default(tmp_path: Path) -> None:
    """``paper2015`` has its entry; ``other:params`` falls back to ``default``."""
    path = _yaml(
        tmp_path,
        "default:\n  n_steps: 16\n  n_envs: 2\n  n_timesteps: 300\n"
        "paper2015:\n  n_steps: 32\n  policy: MultiInputPolicy\n",
    )
    own = load_hyperparams("ppo", "paper2015", path=path)
    assert (own.policy, own.n_envs, own.n_timesteps, dict(own.kwargs)) == (
        "MultiInputPolicy",
        1,
        100_000,
        {"n_steps": 32},
    )
    other = load_hyperparams("ppo", "other:objects=3", path=path)
    assert (other.policy, other.n_envs, other.n_timesteps, dict(other.kwargs)) == ("MlpPolicy", 2, 300, {"n_steps": 16})


def test_a_file_without_the_entry_or_not_a_mapping_is_refused(tmp_path: Path) -> None:
    """No entry and no ``default``; a list at the top; an empty file (nothing in it)."""
    with pytest.raises(HyperparamError, match="no entry for scenario 'x' and no 'default' entry"):
        load_hyperparams("ppo", "x:a=1", path=_yaml(tmp_path, "paper2015:\n  n_steps: 8\n"))
    with pytest.raises(HyperparamError, match="expected a mapping of scenario names"):
        load_hyperparams("ppo", path=_yaml(tmp_path, "- 1\n- 2\n"))
    with pytest.raises(HyperparamError, match="no entry for scenario 'default'"):
        load_hyperparams("ppo", path=_yaml(tmp_path, ""))
    with pytest.raises(HyperparamError, match="no entry for scenario 'default'"):
        load_hyperparams("ppo", path=_yaml(tmp_path, "default: 3\n"))


def test_overrides_nest_and_refuse_a_scalar_in_the_path(tmp_path: Path) -> None:
    """``policy_kwargs.net_arch`` sets a new nested entry; ``gamma.x`` under a number is refused."""
    path = _yaml(tmp_path, "default:\n  gamma: 0.9\n  policy_kwargs:\n    net_arch: [4]\n")
    hp = load_hyperparams("a2c", path=path, overrides=["policy_kwargs.activation_fn=relu", "gamma=0.5"])
    assert hp.kwargs == {"gamma": 0.5, "policy_kwargs": {"net_arch": [4], "activation_fn": "relu"}}
    fresh = load_hyperparams("a2c", path=path, overrides=["policy_kwargs.ortho_init=false"])
    assert fresh.kwargs["policy_kwargs"] == {"net_arch": [4], "ortho_init": False}
    with pytest.raises(HyperparamError, match=r"override 'gamma.x=1': 'gamma' is not a mapping"):
        load_hyperparams("a2c", path=path, overrides=["gamma.x=1"])


def test_an_override_dict_from_the_file_is_not_shared_between_overrides(tmp_path: Path) -> None:
    """Two overrides of one nested mapping both land: the second sees the first."""
    path = _yaml(tmp_path, "default:\n  policy_kwargs:\n    net_arch: [4]\n")
    hp = load_hyperparams("ppo", path=path, overrides=["policy_kwargs.net_arch=[2]", "policy_kwargs.ortho_init=true"])
    assert hp.kwargs["policy_kwargs"] == {"net_arch": [2], "ortho_init": True}


@pytest.mark.parametrize(
    ("line", "expected"),
    [("n_envs: 1", 1), ("n_envs: 256", 256), ("n_envs: 4.0", 4)],
)
def test_n_envs_within_its_bounds_is_kept(tmp_path: Path, line: str, expected: int) -> None:
    assert load_hyperparams("a2c", path=_yaml(tmp_path, f"default:\n  {line}\n")).n_envs == expected


@pytest.mark.parametrize(
    ("line", "match"),
    [
        ("n_envs: 0", r"a2c: n_envs: expected an integer >= 1"),
        ("n_envs: 257", r"a2c: n_envs: expected an integer <= 256"),
        ("n_timesteps: 0", r"a2c: n_timesteps: expected an integer >= 1"),
        ("n_timesteps: 10000000001", r"a2c: n_timesteps: expected an integer <= 10000000000"),
        ("policy: 3", r"a2c: policy: expected a policy class name, got 3"),
    ],
)
def test_own_keys_out_of_bounds_are_refused(tmp_path: Path, line: str, match: str) -> None:
    with pytest.raises(HyperparamError, match=match):
        load_hyperparams("a2c", path=_yaml(tmp_path, f"default:\n  {line}\n"))


def test_the_step_budget_at_its_bounds_is_kept(tmp_path: Path) -> None:
    assert load_hyperparams("a2c", path=_yaml(tmp_path, "default:\n  n_timesteps: 1\n")).n_timesteps == 1
    top = load_hyperparams("a2c", path=_yaml(tmp_path, "default:\n  n_timesteps: 10000000000\n"))
    assert top.n_timesteps == 10**10


def test_unknown_keys_are_listed_sorted_with_what_is_accepted(tmp_path: Path) -> None:
    """Two typos, named in sorted order, then the trainer's own keys and the accepted ones."""
    path = _yaml(tmp_path, "default:\n  zeta: 1\n  alpha: 2\n  gamma: 0.9\n")
    with pytest.raises(HyperparamError) as info:
        load_hyperparams("a2c", path=path)
    message = str(info.value)
    assert message.startswith("a2c: unknown hyperparameter(s) alpha, zeta; accepted: policy, n_envs, n_timesteps, ")
    assert ", ".join(sorted(accepted_keys("a2c"))) in message


@pytest.mark.parametrize("algo", ["ppo", "maskable_ppo"])
def test_a_rollout_of_one_step_is_refused_for_ppo_like_algorithms(tmp_path: Path, algo: str) -> None:
    """``n_steps x n_envs``: 1 x 1 refused; 1 x 2 and 2 x 1 kept."""
    with pytest.raises(HyperparamError, match=rf"{algo}: n_steps x n_envs must be at least 2"):
        load_hyperparams(algo, path=_yaml(tmp_path, "default:\n  n_steps: 1\n  n_envs: 1\n"))
    assert load_hyperparams(algo, path=_yaml(tmp_path, "default:\n  n_steps: 1\n  n_envs: 2\n")).n_envs == 2
    assert load_hyperparams(algo, path=_yaml(tmp_path, "default:\n  n_steps: 2\n")).kwargs["n_steps"] == 2


def test_a2c_may_roll_out_one_step(tmp_path: Path) -> None:
    """A2C has no minibatch advantage normalisation: ``n_steps: 1`` with one environment is allowed."""
    assert load_hyperparams("a2c", path=_yaml(tmp_path, "default:\n  n_steps: 1\n")).kwargs["n_steps"] == 1


def test_a_file_of_exactly_one_mebibyte_is_read_and_one_byte_more_refused(tmp_path: Path) -> None:
    """The size check is ``> 1 MiB``: a comment pads the file to the byte."""
    head = "default:\n  n_envs: 3\n#"
    path = tmp_path / "big.yml"
    path.write_text(head + "x" * (MAX_YAML_BYTES - len(head)), encoding="utf-8")
    assert path.stat().st_size == MAX_YAML_BYTES
    assert load_hyperparams("a2c", path=path).n_envs == 3
    path.write_text(head + "x" * (MAX_YAML_BYTES - len(head) + 1), encoding="utf-8")
    with pytest.raises(HyperparamError, match=rf"big.yml: larger than {MAX_YAML_BYTES} bytes"):
        load_hyperparams("a2c", path=path)


def test_unreadable_files_are_one_line_each(tmp_path: Path) -> None:
    """Missing, a folder, not UTF-8, a long number, malformed YAML (its line), deep nesting."""
    with pytest.raises(HyperparamError, match=r"^--hyperparams .*no\.yml: no such file$"):
        load_hyperparams("a2c", path=tmp_path / "no.yml")
    with pytest.raises(HyperparamError, match=r"^--hyperparams .*: is a folder, not a YAML file$"):
        load_hyperparams("a2c", path=tmp_path)
    bad = tmp_path / "bad.yml"
    bad.write_bytes(b"default:\n  gamma: \xff\n")
    with pytest.raises(HyperparamError, match=r"bad\.yml: not UTF-8 text$"):
        load_hyperparams("a2c", path=bad)
    bad.write_text("default:\n  gamma: 0.9\n  n_steps: " + "9" * 5000 + "\n", encoding="utf-8")
    with pytest.raises(HyperparamError, match=r"bad\.yml:3: a number of 5,000 digits"):
        load_hyperparams("a2c", path=bad)
    bad.write_text("default:\n  gamma: 0.9\n  x: [1, 2\n", encoding="utf-8")
    with pytest.raises(HyperparamError) as info:
        load_hyperparams("a2c", path=bad)
    assert str(info.value).startswith(f"{bad}:4: not valid YAML (")  # the scanner stops at the end, line 4
    bad.write_text("default: " + "[" * 20000 + "]" * 20000 + "\n", encoding="utf-8")
    with pytest.raises(HyperparamError, match=r"bad\.yml: YAML nested too deeply$"):
        load_hyperparams("a2c", path=bad)
    with pytest.raises(HyperparamError, match=r"bad\.yml/x\.yml: cannot read \(Not a directory\)$"):
        load_hyperparams("a2c", path=bad / "x.yml")  # a path through a file: another OSError


def test_resolved_hyperparams_are_frozen() -> None:
    """The sidecar and the model are built from one resolved value: it cannot be changed after."""
    import dataclasses

    hp = Hyperparams("ppo")
    with pytest.raises(dataclasses.FrozenInstanceError):
        hp.n_envs = 2


def test_model_kwargs_turn_activation_names_into_torch_classes_without_touching_the_hyperparams() -> None:
    """``tanh`` becomes ``torch.nn.Tanh``; the resolved hyperparameters keep the name."""
    import torch

    hp = Hyperparams("ppo", kwargs={"policy_kwargs": {"activation_fn": "tanh", "net_arch": [2]}, "gamma": 0.5})
    kwargs = model_kwargs(hp)
    assert kwargs == {"policy_kwargs": {"activation_fn": torch.nn.Tanh, "net_arch": [2]}, "gamma": 0.5}
    assert hp.kwargs["policy_kwargs"]["activation_fn"] == "tanh"
    assert model_kwargs(Hyperparams("ppo", kwargs={"policy_kwargs": {"net_arch": [2]}})) == {
        "policy_kwargs": {"net_arch": [2]}
    }
    with pytest.raises(HyperparamError, match="swish"):
        model_kwargs(Hyperparams("ppo", kwargs={"policy_kwargs": {"activation_fn": "swish"}}))


def test_a_fifo_or_a_device_is_refused_unread(tmp_path: Path) -> None:
    """A FIFO would block the open and ``/dev/zero`` (whose size reads 0) never end."""
    fifo = tmp_path / "pipe.yml"
    os.mkfifo(fifo)
    for path in (fifo, Path("/dev/zero")):
        with pytest.raises(HyperparamError, match=r"^--hyperparams .*: not a regular file \(a FIFO or a device\)$"):
            load_hyperparams("a2c", path=path)
