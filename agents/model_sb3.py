"""SB3 models to and from a model file, without unpickling: rebuilt from the header, loaded from the arrays.

torch and SB3 are imported inside these functions only, so the numpy kinds of
:mod:`hg_marl.agents.model_format` never import torch.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any, TypeGuard

import gymnasium
import numpy as np

from hg_marl.agents.model_format import (
    _COUNTERS,
    ACTIVATIONS,
    OBSERVATIONS,
    ModelFile,
    read_arrays,
    save_model_file,
    weights_file,
    write_arrays,
)
from hg_marl.agents.sb3_limits import check_policy_kwargs
from hg_marl.core.errors import ModelFileError


def algo_class(algo: str) -> Any:
    """The SB3 or sb3-contrib algorithm class called ``algo`` (imports SB3)."""
    import stable_baselines3

    cls = getattr(stable_baselines3, algo, None)
    if cls is None:
        import sb3_contrib

        cls = getattr(sb3_contrib, algo, None)
    from stable_baselines3.common.base_class import BaseAlgorithm

    if not (isinstance(cls, type) and issubclass(cls, BaseAlgorithm)):
        raise ModelFileError(f"unknown SB3 algorithm class {algo!r}")
    return cls


def activation(name: str) -> Any:
    """The torch activation class for a ``policy_kwargs.activation_fn`` name."""
    import torch

    if name not in ACTIVATIONS:
        raise ModelFileError(f"unknown activation_fn {name!r}; use one of {', '.join(ACTIVATIONS)}")
    return getattr(torch.nn, ACTIVATIONS[name])


def space_to_json(space: Any) -> dict[str, Any]:
    """A Gymnasium space as plain JSON (Box, Discrete, MultiBinary, Dict)."""
    from gymnasium import spaces

    if isinstance(space, spaces.Box):
        return {
            "type": "Box",
            "low": space.low.tolist(),
            "high": space.high.tolist(),
            "shape": list(space.shape),
            "dtype": str(space.dtype),
        }
    if isinstance(space, spaces.Discrete):
        return {"type": "Discrete", "n": int(space.n), "start": int(space.start)}
    if isinstance(space, spaces.MultiBinary):
        return {"type": "MultiBinary", "n": np.asarray(space.n).tolist()}
    if isinstance(space, spaces.Dict):
        return {"type": "Dict", "spaces": {k: space_to_json(v) for k, v in space.spaces.items()}}
    raise ModelFileError(f"cannot store a {type(space).__name__} space in a model header")


MAX_SPACE_SIZE = 1_000_000
"""A space in a header may have at most this many elements (checked before any allocation)."""


def _is_int(x: object) -> TypeGuard[int]:
    """An integer in JSON: ``true`` and ``false`` are not (Python's ``bool`` is an ``int``)."""
    return isinstance(x, int) and not isinstance(x, bool)


def _is_shape(x: object, scalar: bool = False) -> TypeGuard[list[int]]:
    """A list of positive integers (``scalar``: the empty list too, a one-element space's shape)."""
    return isinstance(x, list) and (scalar or len(x) > 0) and all(_is_int(n) and n > 0 for n in x)


def space_from_json(data: Any, where: str) -> Any:
    """Rebuild a space written by :func:`space_to_json`, checking every field."""
    from gymnasium import spaces

    def fail(message: str) -> ModelFileError:
        return ModelFileError(f"{where}: {message}")

    if not isinstance(data, dict):
        raise fail("expected a space object")
    kind = data.get("type")
    try:
        if kind == "Box":
            shape = data.get("shape")
            if not _is_shape(shape, scalar=True):
                raise fail("Box shape must be a list of positive integers")
            if math.prod(shape) > MAX_SPACE_SIZE:  # Python's integers: no wrap-around past 2**63
                raise fail(f"Box of {math.prod(shape)} elements is over the limit {MAX_SPACE_SIZE}")
            dtype = np.dtype(str(data.get("dtype")))
            if dtype.kind not in "biuf":
                raise fail(f"Box dtype {dtype} is not numeric")
            low = np.asarray(data.get("low"), dtype=np.float64)
            high = np.asarray(data.get("high"), dtype=np.float64)
            return spaces.Box(low.astype(dtype), high.astype(dtype), tuple(shape), dtype)
        if kind == "Discrete":
            n, start = data.get("n"), data.get("start", 0)
            if not _is_int(n) or not 0 < n <= MAX_SPACE_SIZE:
                raise fail(f"Discrete n must be an integer in [1, {MAX_SPACE_SIZE}]")
            if not _is_int(start):
                raise fail("Discrete start must be an integer")
            return spaces.Discrete(n, start=start)
        if kind == "MultiBinary":
            n = data.get("n")  # an integer, or a shape (``MultiBinary([2, 3])``)
            shape = [n] if _is_int(n) else n
            if not _is_shape(shape) or math.prod(shape) > MAX_SPACE_SIZE:
                raise fail(f"MultiBinary n must be an integer or a shape of 1 to {MAX_SPACE_SIZE} elements")
            return spaces.MultiBinary(shape[0] if _is_int(n) else shape)
        if kind == "Dict":
            sub = data.get("spaces")
            if not isinstance(sub, dict):
                raise fail("Dict needs 'spaces'")
            return spaces.Dict({str(k): space_from_json(v, f"{where}.{k}") for k, v in sub.items()})
    except (TypeError, ValueError) as exc:
        if isinstance(exc, ModelFileError):
            raise
        raise fail(f"malformed {kind} space ({exc})") from None
    raise fail(f"unknown space type {kind!r}")


def _flatten(tree: Any, arrays: dict[str, np.ndarray], where: str) -> Any:
    """State dicts to JSON with tensors moved to ``arrays`` (``{"$array": key}`` placeholders)."""
    import torch

    if isinstance(tree, torch.Tensor):
        key = f"t{len(arrays)}"
        arrays[key] = tree.detach().cpu().numpy()
        return {"$array": key}
    if isinstance(tree, Mapping):
        return {"$dict": [[k, _flatten(v, arrays, where)] for k, v in tree.items()]}
    if isinstance(tree, list | tuple):
        return [_flatten(v, arrays, where) for v in tree]
    if tree is None or isinstance(tree, bool | int | float | str):
        return tree
    raise ModelFileError(f"{where}: cannot store a {type(tree).__name__} in a model file")


def _unflatten(tree: Any, arrays: Mapping[str, np.ndarray], where: str, depth: int = 0) -> Any:
    import torch

    if depth > 20:
        raise ModelFileError(f"{where}: state nested too deeply")
    if isinstance(tree, dict):
        if set(tree) == {"$array"}:
            key = tree["$array"]
            if not isinstance(key, str) or key not in arrays:
                raise ModelFileError(f"{where}: state names a missing array {key!r}")
            return torch.from_numpy(np.array(arrays[key]))
        pairs = tree.get("$dict")
        if set(tree) != {"$dict"} or not isinstance(pairs, list):
            raise ModelFileError(f"{where}: malformed state entry")
        out: dict[Any, Any] = {}
        for pair in pairs:
            if not (isinstance(pair, list) and len(pair) == 2 and isinstance(pair[0], str | int)):
                raise ModelFileError(f"{where}: malformed state entry")
            out[pair[0]] = _unflatten(pair[1], arrays, where, depth + 1)
        return out
    if isinstance(tree, list):
        return [_unflatten(v, arrays, where, depth + 1) for v in tree]
    if tree is None or isinstance(tree, bool | int | float | str):
        return tree
    raise ModelFileError(f"{where}: malformed state entry")


def _policy_alias(model: Any) -> str:
    for alias, cls in getattr(model, "policy_aliases", {}).items():
        if cls is type(model.policy):
            return str(alias)
    raise ModelFileError(f"cannot store policy class {type(model.policy).__name__}: not one of SB3's named policies")


OPTIMIZERS = ("Adam", "AdamW", "RMSprop", "SGD")
"""``policy_kwargs.optimizer_class`` names a file may give (torch.optim classes)."""


def _policy_kwargs_json(kwargs: Mapping[str, Any]) -> dict[str, Any]:
    """``policy_kwargs`` as JSON: the activation and optimizer classes become names."""
    out = dict(kwargs)
    fn = out.get("activation_fn")
    if fn is not None and not isinstance(fn, str):
        names = {v: k for k, v in ACTIVATIONS.items()}
        if fn.__name__ not in names:
            raise ModelFileError(f"cannot store activation_fn {fn.__name__}; use one of {', '.join(ACTIVATIONS)}")
        out["activation_fn"] = names[fn.__name__]
    optimizer = out.get("optimizer_class")
    if optimizer is not None and not isinstance(optimizer, str):
        if optimizer.__name__ not in OPTIMIZERS:
            raise ModelFileError(
                f"cannot store optimizer_class {optimizer.__name__}; use one of {', '.join(OPTIMIZERS)}"
            )
        out["optimizer_class"] = optimizer.__name__
    return out


def policy_kwargs_from_json(kwargs: Any, where: str) -> dict[str, Any]:
    """``policy_kwargs`` ready for SB3 (activation and optimizer names become torch classes)."""
    import torch

    if kwargs is None:
        return {}
    if not isinstance(kwargs, dict):
        raise ModelFileError(f"{where}: field 'policy_kwargs' must be an object")
    check_policy_kwargs(kwargs, f"{where}: field 'policy_kwargs'", ModelFileError)
    out = dict(kwargs)
    if isinstance(out.get("activation_fn"), str):
        try:
            out["activation_fn"] = activation(out["activation_fn"])
        except ModelFileError as exc:
            raise ModelFileError(f"{where}: {exc}") from None
    if "optimizer_class" in out:
        if out["optimizer_class"] not in OPTIMIZERS:
            raise ModelFileError(
                f"{where}: field 'policy_kwargs.optimizer_class' must be one of {', '.join(OPTIMIZERS)}"
            )
        out["optimizer_class"] = getattr(torch.optim, out["optimizer_class"])
    return out


def save_sb3(model: Any, path: Path, fields: Mapping[str, Any], *, observation: str) -> Path:
    """Save an SB3 model as ``<stem>.npz`` + ``<stem>.json`` (policy, optimizer, counters).

    Args:
        model: the SB3 / sb3-contrib model.
        path: the header's path (``.json``; a ``.zip`` or stem is mapped to it).
        fields: header fields (:func:`world_fields`, training configuration, ...).
        observation: the view's observation mode.
    """
    import stable_baselines3

    if observation not in OBSERVATIONS:
        raise ModelFileError(f"observation must be one of {', '.join(OBSERVATIONS)}, got {observation!r}")
    arrays: dict[str, np.ndarray] = {}
    state = _flatten(model.get_parameters(), arrays, str(path))
    counters = {k: int(getattr(model, k)) for k in _COUNTERS if hasattr(model, k)}
    header = {
        **fields,
        "kind": "sb3",
        "algo": type(model).__name__,
        "policy": _policy_alias(model),
        "policy_kwargs": _policy_kwargs_json(model.policy_kwargs),
        "observation": observation,
        "observation_space": space_to_json(model.observation_space),
        "action_space": space_to_json(model.action_space),
        "state": state,
        "counters": counters,
        "sb3_version": stable_baselines3.__version__,
    }
    return save_model_file(Path(path).with_suffix(".json"), header, arrays)


class _SpacesOnly(gymnasium.Env):
    """A Gymnasium env that only carries spaces: enough for SB3 to build a policy."""

    def __init__(self, observation_space: Any, action_space: Any) -> None:
        self.observation_space = observation_space
        self.action_space = action_space

    def reset(self, *, seed: Any = None, options: Any = None) -> Any:
        raise ModelFileError("a model rebuilt from its file cannot be trained without an environment")

    def step(self, action: Any) -> Any:
        raise ModelFileError("a model rebuilt from its file cannot be trained without an environment")


def build_sb3(mf: ModelFile, env: Any = None, *, optimizer: bool = True, **kwargs: Any) -> Any:
    """Rebuild the SB3 model a header describes and load its state (never unpickling).

    Args:
        mf: a loaded ``sb3`` model file.
        env: the environment to train on (resume); None builds one that only carries the
            header's spaces (inference).
        optimizer: also restore the optimizer state.
        **kwargs: constructor arguments (the hyperparameters when resuming).
    """
    header, where = mf.header, str(mf.path)
    if header["kind"] != "sb3":
        raise ModelFileError(f"{where}: a {header['kind']} policy, not an SB3 model")
    cls = algo_class(header["algo"])
    policy = header.get("policy")
    if policy not in getattr(cls, "policy_aliases", {}):
        raise ModelFileError(f"{where}: field 'policy': {policy!r} is not a policy of {header['algo']}")
    obs_space = space_from_json(header.get("observation_space"), f"{where}: field 'observation_space'")
    act_space = space_from_json(header.get("action_space"), f"{where}: field 'action_space'")
    if env is None:
        env = _SpacesOnly(obs_space, act_space)
        if "buffer_size" in _signature(cls):
            kwargs.setdefault("buffer_size", 1)  # inference: no replay memory
        if "n_steps" in _signature(cls):
            kwargs.setdefault("n_steps", 2)
            if "batch_size" in _signature(cls):
                kwargs.setdefault("batch_size", 2)
    policy_kwargs = policy_kwargs_from_json(header.get("policy_kwargs"), where)
    kwargs.pop("policy_kwargs", None)
    try:
        model = cls(policy, env, policy_kwargs=policy_kwargs, device="cpu", **kwargs)
    except (TypeError, ValueError, AssertionError) as exc:
        raise ModelFileError(f"{where}: cannot rebuild the {header['algo']} model ({exc})") from None
    if model.observation_space != obs_space or model.action_space != act_space:
        raise ModelFileError(f"{where}: its spaces differ from the environment's")
    restore_sb3(model, mf, optimizer=optimizer)
    return model


def _signature(cls: Any) -> tuple[str, ...]:
    import inspect

    return tuple(inspect.signature(cls.__init__).parameters)


def restore_sb3(model: Any, mf: ModelFile, *, optimizer: bool = True) -> None:
    """Load a model file's state dicts and counters into an already built SB3 model."""
    where = str(mf.path)
    state = _unflatten(mf.header.get("state"), mf.arrays, where)
    if not isinstance(state, dict) or "policy" not in state:
        raise ModelFileError(f"{where}: field 'state' has no policy")
    if not optimizer:
        state = {k: v for k, v in state.items() if k == "policy"}
    try:
        model.set_parameters(state, exact_match=optimizer, device="cpu")
    except (RuntimeError, ValueError, KeyError, TypeError, IndexError) as exc:
        message = " ".join(str(exc).split())[:300]
        raise ModelFileError(f"{where}: weights do not fit the {mf.header['algo']} policy ({message})") from None
    counters = mf.header.get("counters", {})
    if not isinstance(counters, dict):
        raise ModelFileError(f"{where}: field 'counters' must be an object")
    for key in _COUNTERS:
        if key in counters and hasattr(model, key):
            value = counters[key]
            if not isinstance(value, int) or isinstance(value, bool) or value < 0:
                raise ModelFileError(f"{where}: field 'counters.{key}' must be a non-negative integer")
            setattr(model, key, value)


# -- replay buffers ----------------------------------------------------------------------

_BUFFER_ARRAYS = ("observations", "next_observations", "actions", "rewards", "dones", "timeouts")


def _buffer_arrays(buffer: Any) -> dict[str, np.ndarray]:
    """A replay buffer's arrays by name (``observations/<key>`` for dict observations)."""
    arrays: dict[str, np.ndarray] = {}
    for name in _BUFFER_ARRAYS:
        value = getattr(buffer, name, None)
        if isinstance(value, dict):
            arrays.update({f"{name}/{k}": v for k, v in value.items()})
        elif isinstance(value, np.ndarray):
            arrays[name] = value
    return arrays


def save_replay_buffer(buffer: Any, path: Path) -> dict[str, Any]:
    """Write a replay buffer's arrays as ``.npz``; return the header entry that names it."""
    arrays = _buffer_arrays(buffer)
    sha = write_arrays(path, arrays, compress=True)
    return {"file": path.name, "sha256": sha, "pos": int(buffer.pos), "full": bool(buffer.full)}


def load_replay_buffer(buffer: Any, header_path: Path, entry: Any) -> None:
    """Fill ``buffer`` from the file a checkpoint header names, checking every array's shape and dtype."""
    if not isinstance(entry, dict):
        raise ModelFileError(f"{header_path}: field 'replay_buffer' must be an object")
    path = weights_file(header_path, entry)
    expected = _buffer_arrays(buffer)
    shapes = {key: tuple(target.shape) for key, target in expected.items()}
    arrays = read_arrays(path, entry.get("sha256") if isinstance(entry.get("sha256"), str) else None, shapes)
    if set(arrays) != set(expected):
        raise ModelFileError(f"{path}: arrays {sorted(arrays)} differ from the buffer's {sorted(expected)}")
    for key, target in expected.items():
        if arrays[key].shape != target.shape or arrays[key].dtype != target.dtype:
            raise ModelFileError(
                f"{path}: array {key!r} is {arrays[key].shape} {arrays[key].dtype}, "
                f"the buffer needs {target.shape} {target.dtype}"
            )
    pos, full = entry.get("pos"), entry.get("full")
    size = int(buffer.buffer_size)
    if not isinstance(pos, int) or isinstance(pos, bool) or not 0 <= pos < max(size, 1) or not isinstance(full, bool):
        raise ModelFileError(f"{header_path}: field 'replay_buffer.pos'/'full' out of range")
    for key, target in expected.items():
        np.copyto(target, arrays[key])
    buffer.pos, buffer.full = pos, full
