"""Hyperparameters: one YAML file per algorithm (RL Zoo style), overridable from the command line.

``training/hyperparams/{algo}.yml`` maps a scenario name (or ``default``) to a flat
mapping: ``policy``, ``n_envs`` and ``n_timesteps`` are ours (which policy class, how many
environments in the ``DummyVecEnv``, the default step budget); every other key is a
constructor argument of the algorithm's class and is checked against its signature, so
a typo fails before training starts rather than as a ``TypeError`` deep inside SB3.
``policy_kwargs.activation_fn`` may name a torch activation (``"tanh"``, ``"relu"``).

Overrides are ``key=value`` strings, the value read as YAML (``0.001``, ``[32, 32]``,
``true``); a dotted key sets a nested entry (``policy_kwargs.net_arch=[32,32]``).
"""

from __future__ import annotations

import inspect
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import yaml

from hg_marl.agents.sb3_limits import check_kwargs
from hg_marl.core.errors import ConfigError, ModelFileError, NotRegularFileError, check_digits, check_int, read_limited

ALGOS: Mapping[str, str] = {
    "ppo": "PPO",
    "a2c": "A2C",
    "dqn": "DQN",
    "maskable_ppo": "MaskablePPO",
    "recurrent_ppo": "RecurrentPPO",
}
"""Command-line algorithm names and their SB3 / sb3-contrib class names."""

OWN_KEYS = ("policy", "n_envs", "n_timesteps")
"""YAML keys that are not constructor arguments."""


class HyperparamError(ConfigError):
    """An unknown algorithm, an unknown key, or a malformed override."""


@dataclass(frozen=True)
class Hyperparams:
    """The resolved hyperparameters of one training run."""

    algo: str
    """Command-line algorithm name (``ppo``, ``maskable_ppo``, ...)."""
    policy: str = "MlpPolicy"
    """SB3 policy class name."""
    n_envs: int = 1
    """Environments stepped together (``DummyVecEnv``)."""
    n_timesteps: int = 100_000
    """Default step budget when the caller gives none."""
    kwargs: Mapping[str, Any] = field(default_factory=dict)
    """Constructor arguments of the algorithm (plain YAML values)."""

    @property
    def class_name(self) -> str:
        """The SB3 / sb3-contrib class name."""
        return ALGOS[self.algo]

    def as_dict(self) -> dict[str, Any]:
        """Everything, as plain data (for the sidecar and logs)."""
        return {
            "algo": self.algo,
            "policy": self.policy,
            "n_envs": self.n_envs,
            "n_timesteps": self.n_timesteps,
            **dict(self.kwargs),
        }


def check_algo(algo: str) -> str:
    """Return ``algo`` if known, else raise :class:`HyperparamError` listing the known ones."""
    if algo not in ALGOS:
        raise HyperparamError(f"unknown algorithm {algo!r}; available: {', '.join(ALGOS)}")
    return algo


def hyperparams_path(algo: str) -> Path:
    """The packaged YAML file of ``algo``."""
    return Path(str(resources.files("hg_marl.training").joinpath("hyperparams", f"{check_algo(algo)}.yml")))


def parse_override(item: str) -> tuple[list[str], Any]:
    """Split ``"a.b=value"`` into the key path and the YAML-parsed value."""
    key, sep, value = item.partition("=")
    if not sep or not key.strip():
        raise HyperparamError(f"hyperparameter override {item!r}: expected key=value")
    check_digits(value, f"hyperparameter override {key.strip()}", HyperparamError)
    try:
        parsed = yaml.safe_load(value) if value.strip() else None
    except yaml.YAMLError as exc:
        raise HyperparamError(f"hyperparameter override {item!r}: value is not valid YAML: {exc}") from None
    return [k.strip() for k in key.split(".")], parsed


def accepted_keys(algo: str) -> tuple[str, ...]:
    """Constructor arguments the algorithm's class accepts (imports SB3)."""
    from hg_marl.agents.model_file import algo_class

    params = inspect.signature(algo_class(ALGOS[check_algo(algo)]).__init__).parameters
    return tuple(p for p in params if p not in ("self", "policy", "env", "seed", "device", "_init_setup_model"))


def load_hyperparams(
    algo: str, scenario: str = "default", overrides: Iterable[str] = (), path: str | Path | None = None
) -> Hyperparams:
    """Resolve the hyperparameters of ``algo`` for ``scenario``, with overrides.

    Args:
        algo: a key of :data:`ALGOS` (``ppo``, ``a2c``, ``dqn``, ``maskable_ppo`` or ``recurrent_ppo``).
        scenario: an entry of the YAML file; falls back to ``default``. A ``generated:...``
            spec looks up ``generated``.
        overrides: ``key=value`` strings (see the module docstring).
        path: another YAML file instead of the packaged one.

    Raises:
        HyperparamError: unknown algorithm, missing entry, unknown key or bad override.
    """
    source = Path(path) if path is not None else hyperparams_path(algo)
    data = _read_yaml(source)
    if not isinstance(data, dict):
        raise HyperparamError(f"{source}: expected a mapping of scenario names to hyperparameters")
    name = scenario.partition(":")[0]
    entry = data.get(name, data.get("default"))
    if not isinstance(entry, dict):
        raise HyperparamError(f"{source}: no entry for scenario {name!r} and no 'default' entry")
    merged: dict[str, Any] = {k: (dict(v) if isinstance(v, dict) else v) for k, v in entry.items()}
    for item in overrides:
        keys, value = parse_override(item)
        target = merged
        for k in keys[:-1]:
            nested = target.setdefault(k, {})
            if not isinstance(nested, dict):
                raise HyperparamError(f"override {item!r}: {k!r} is not a mapping")
            target = nested
        target[keys[-1]] = value
    n_envs = check_int(merged.pop("n_envs", 1), f"{algo}: n_envs", minimum=1, maximum=MAX_ENVS, error=HyperparamError)
    n_timesteps = check_int(
        merged.pop("n_timesteps", 100_000),
        f"{algo}: n_timesteps",
        minimum=1,
        maximum=MAX_TIMESTEPS,
        error=HyperparamError,
    )
    policy = merged.pop("policy", "MlpPolicy")
    if not isinstance(policy, str):
        raise HyperparamError(f"{algo}: policy: expected a policy class name, got {policy!r}")
    check_kwargs(merged, f"{algo} hyperparameter", HyperparamError)
    known = set(accepted_keys(algo))
    unknown = sorted(k for k in merged if k not in known and k not in OWN_KEYS)
    if unknown:
        raise HyperparamError(
            f"{algo}: unknown hyperparameter(s) {', '.join(unknown)}; accepted: "
            f"{', '.join(OWN_KEYS)}, {', '.join(sorted(known))}"
        )
    n_steps = merged.get("n_steps")
    if algo in ("ppo", "maskable_ppo", "recurrent_ppo") and isinstance(n_steps, int) and n_steps * n_envs < 2:
        raise HyperparamError(f"{algo}: n_steps x n_envs must be at least 2 (a rollout of one step has no advantage)")
    return Hyperparams(algo, policy, n_envs, n_timesteps, merged)


MAX_ENVS = 256
"""Most environments stepped together (``n_envs``)."""
MAX_TIMESTEPS = 10**10
"""Largest default step budget (``n_timesteps``)."""
MAX_YAML_BYTES = 1 << 20
"""A hyperparameter file may be at most 1 MiB."""


def _read_yaml(source: Path) -> Any:
    """A hyperparameter YAML file, any problem reported as one line with ``path:line``."""
    try:
        raw = read_limited(source, MAX_YAML_BYTES)
        if raw is None:
            raise HyperparamError(f"{source}: larger than {MAX_YAML_BYTES} bytes")
        text = raw.decode("utf-8")
    except NotRegularFileError:
        raise HyperparamError(f"--hyperparams {source}: not a regular file (a FIFO or a device)") from None
    except FileNotFoundError:
        raise HyperparamError(f"--hyperparams {source}: no such file") from None
    except IsADirectoryError:
        raise HyperparamError(f"--hyperparams {source}: is a folder, not a YAML file") from None
    except UnicodeDecodeError:
        raise HyperparamError(f"{source}: not UTF-8 text") from None
    except OSError as exc:
        raise HyperparamError(f"{source}: cannot read ({exc.strerror})") from None
    check_digits(text, str(source), HyperparamError, lines=True)
    try:
        return yaml.safe_load(text) or {}
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        at = f"{source}:{mark.line + 1}" if mark is not None else str(source)
        problem = getattr(exc, "problem", None) or "malformed"
        raise HyperparamError(f"{at}: not valid YAML ({problem})") from None
    except RecursionError:
        raise HyperparamError(f"{source}: YAML nested too deeply") from None


def model_kwargs(hp: Hyperparams) -> dict[str, Any]:
    """Constructor arguments ready for SB3: activation names become torch classes."""
    kwargs = {k: (dict(v) if isinstance(v, dict) else v) for k, v in hp.kwargs.items()}
    policy_kwargs = kwargs.get("policy_kwargs")
    if isinstance(policy_kwargs, dict) and isinstance(policy_kwargs.get("activation_fn"), str):
        from hg_marl.agents.model_file import activation

        try:
            policy_kwargs["activation_fn"] = activation(policy_kwargs["activation_fn"])
        except ModelFileError as exc:
            raise HyperparamError(str(exc)) from None
    return kwargs
