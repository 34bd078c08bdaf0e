"""The one file format for learned policies, robot seat and human seat alike, and its loader.

A model file is two files side by side in one folder:

- a JSON *header* (``model.json``, ``policy.json``, ``ckpt_800_steps.json``): the format
  and version, the ``kind`` (``sb3``, ``linear_softmax``, ``table``), the seat, the
  scenario and the world's fact and action names, the package version, the name of the
  weights file and its sha256; for ``sb3`` also the algorithm class, the policy class and
  its ``policy_kwargs``, the observation and action spaces, the observation mode, the
  training counters and the optimizer's non-tensor state;
- the *weights*: a ``.npz`` of plain numeric arrays, read with ``allow_pickle=False``.

Why: an SB3 ``.zip`` (and a replay buffer ``.pkl``) is unpickled on load, so a shared
file can run any code. Nothing here unpickles: an SB3 model is rebuilt from the header
(algorithm and policy class looked up by name in SB3 / sb3-contrib, never imported from
a name the file gives) and its state dicts are loaded from the arrays. A file in SB3's
zip format is refused with a message saying how to convert it
(``hg-marl convert --trust F``, for files the user vouches for). The header may only
name a weights file in its own folder.

Every problem is a :class:`~hg_marl.core.errors.ModelFileError` naming the file (and
``path:line`` for malformed JSON). torch and SB3 are imported inside the SB3 functions
only, so the numpy kinds never import torch.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import zipfile
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import gymnasium
import numpy as np

from hg_marl.agents.model_limits import Shape, check_npz_headers, expected_shapes, sb3_budget
from hg_marl.agents.sb3_limits import check_policy_kwargs
from hg_marl.core.errors import ModelFileError, output_error

FORMAT = "hg_marl.model"
VERSION = 2
KINDS = ("sb3", "linear_softmax", "table")
OBSERVATIONS = ("facts", "flat", "dict")
HEADER_NAMES = ("model.json", "policy.json")
"""Headers looked for, in order, when a folder is given."""
ACTIVATIONS = {"tanh": "Tanh", "relu": "ReLU", "elu": "ELU", "leaky_relu": "LeakyReLU", "gelu": "GELU"}
"""``policy_kwargs.activation_fn`` names and their torch.nn classes (the only classes a file may name)."""
MAX_HEADER_BYTES = 1 << 20
"""A model header may be at most 1 MiB (its arrays live in the ``.npz``)."""

MAX_ARRAY_BYTES = 1 << 30
"""A weights file may hold at most this many bytes of arrays (1 GiB) once loaded; each kind
is held to less, worked out from its header (:mod:`hg_marl.agents.model_limits`)."""

_COUNTERS = ("num_timesteps", "_n_updates", "_episode_num", "_n_calls")


def convert_hint(path: Path | str) -> str:
    """The one-line advice for a file in SB3's pickle-based zip format."""
    return (
        f"{path}: an SB3 .zip, which runs code when loaded; refused. If you trust where it came from, "
        f"convert it once with `hg-marl convert --trust {path}` and pass the .json it writes"
    )


# -- files -------------------------------------------------------------------------------


def atomic_write_bytes(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temp file, fsync and rename (never a half file)."""
    tmp = path.with_name(f".{path.name}.tmp")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with open(tmp, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        tmp.replace(path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise (output_error(exc, path) or exc) from None


def write_arrays(path: Path, arrays: Mapping[str, np.ndarray], *, compress: bool = False) -> str:
    """Write plain numeric arrays as ``.npz`` atomically; return the file's sha256."""
    import io

    buffer = io.BytesIO()
    for key, value in arrays.items():
        if np.asarray(value).dtype.kind not in "biuf":
            raise ModelFileError(f"{path}: array {key!r} is not numeric ({np.asarray(value).dtype})")
    plain: dict[str, Any] = {k: np.asarray(v) for k, v in arrays.items()}
    if compress:
        np.savez_compressed(buffer, **plain)
    else:
        np.savez(buffer, **plain)
    data = buffer.getvalue()
    atomic_write_bytes(path, data)
    return hashlib.sha256(data).hexdigest()


def sha256_of(path: Path) -> str:
    """The sha256 of a file's bytes."""
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def read_arrays(
    path: Path, sha256: str | None = None, shapes: Mapping[str, Shape] | None = None, limit: int = MAX_ARRAY_BYTES
) -> dict[str, np.ndarray]:
    """Read a ``.npz`` of numeric arrays, never unpickling; check its hash if given.

    Args:
        path: the ``.npz``.
        sha256: the hash its header states, if any.
        shapes: the arrays it must hold, by name (:mod:`hg_marl.agents.model_limits`).
        limit: most bytes of arrays in all (at most :data:`MAX_ARRAY_BYTES`).

    Raises:
        ModelFileError: missing, not an npz, truncated, an object array, a hash mismatch,
            an array that ``shapes`` does not allow, or more than ``limit`` bytes of data
            (all but the last two checked on the npy headers before any array is read).
    """
    if not path.is_file():
        raise ModelFileError(f"{path}: weights file not found")
    if sha256 is not None and sha256_of(path) != sha256:
        raise ModelFileError(f"{path}: sha256 differs from its header's (the file changed or is corrupt)")
    try:
        check_npz_headers(path, shapes, min(limit, MAX_ARRAY_BYTES))
        data = np.load(path, allow_pickle=False)
        if not isinstance(data, np.lib.npyio.NpzFile):
            raise ModelFileError(f"{path}: not an .npz archive of arrays")
        with data:
            out = {key: data[key] for key in data.files}
    except ModelFileError:
        raise
    except (ValueError, OSError, EOFError, zipfile.BadZipFile, KeyError) as exc:
        raise ModelFileError(f"{path}: not a readable .npz of numeric arrays ({exc})") from None
    return out


def _json_error(path: Path, text: str, exc: json.JSONDecodeError) -> ModelFileError:
    return ModelFileError(f"{path}:{exc.lineno}: not valid JSON ({exc.msg})")


def read_header(path: Path) -> dict[str, Any]:
    """Read and check a header (format, kind, seat, names, weights file inside the folder).

    Raises:
        ModelFileError: unreadable, malformed, an old format, or a weights file outside the folder.
    """
    try:
        if path.stat().st_size > MAX_HEADER_BYTES:
            raise ModelFileError(f"{path}: larger than {MAX_HEADER_BYTES} bytes (a model header is a few KB)")
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise ModelFileError(f"{path}: not UTF-8 text") from None
    except OSError as exc:
        raise ModelFileError(f"{path}: cannot read ({exc.strerror})") from None
    try:
        header = json.loads(text)
    except json.JSONDecodeError as exc:
        raise _json_error(path, text, exc) from None
    except RecursionError:
        raise ModelFileError(f"{path}: JSON nested too deeply") from None
    if not isinstance(header, dict):
        raise ModelFileError(f"{path}: expected a JSON object")
    fmt = header.get("format")
    if fmt in ("hg_marl.sb3", "hg_marl.policy") and (header.get("kind") == "sb3" or fmt == "hg_marl.sb3"):
        target = path.with_suffix(".zip") if fmt == "hg_marl.sb3" else path.parent / str(header.get("file", ""))
        raise ModelFileError(convert_hint(target))
    if fmt not in (FORMAT, "hg_marl.policy") or header.get("kind") not in KINDS:
        raise ModelFileError(f"{path}: not an {FORMAT} header (field 'format' and 'kind' in {KINDS})")
    for key in ("fact_names", "action_names"):
        names = header.get(key)
        if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
            raise ModelFileError(f"{path}: field {key!r}: expected a list of names")
    if header.get("seat") not in ("robot", "human"):
        raise ModelFileError(f"{path}: field 'seat': expected 'robot' or 'human', got {header.get('seat')!r}")
    weights_file(path, header)
    if header["kind"] == "sb3" and (
        not isinstance(header.get("algo"), str) or header.get("observation") not in OBSERVATIONS
    ):
        raise ModelFileError(f"{path}: fields 'algo' and 'observation' ({', '.join(OBSERVATIONS)}) are required")
    return header


def weights_file(header_path: Path, header: Mapping[str, Any], key: str = "file") -> Path:
    """The weights file a header names, which must be a plain file name in the header's folder."""
    name = header.get(key)
    if not isinstance(name, str) or not name or Path(name).name != name or name in (".", ".."):
        raise ModelFileError(f"{header_path}: field {key!r} must name a file in the header's own folder, got {name!r}")
    target = header_path.parent / name
    if target.resolve().parent != header_path.resolve().parent:
        raise ModelFileError(f"{header_path}: field {key!r} points outside the header's folder: {name!r}")
    if target.suffix != ".npz":
        if zipfile.is_zipfile(target) if target.is_file() else target.suffix == ".zip":
            raise ModelFileError(convert_hint(target))
        raise ModelFileError(f"{header_path}: field {key!r} must name a .npz weights file, got {name!r}")
    return target


def resolve_header(path: str | Path, what: str = "--model") -> Path:
    """The header of a model given as its ``.json``, its ``.npz``, its stem, or its folder.

    Raises:
        ModelFileError: nothing there, or an SB3 zip (with the convert advice).
    """
    p = Path(path)
    if p.is_dir():
        for name in HEADER_NAMES:
            if (p / name).is_file():
                return p / name
        if (p / "model.zip").is_file():
            raise ModelFileError(convert_hint(p / "model.zip"))
        raise ModelFileError(f"{what} {p}: no {' or '.join(HEADER_NAMES)} in this folder")
    if p.suffix == ".zip" or (p.is_file() and p.suffix != ".json" and zipfile.is_zipfile(p) and p.suffix != ".npz"):
        if p.is_file() or p.with_suffix(".json").is_file():
            raise ModelFileError(convert_hint(p))
        raise ModelFileError(f"{what} {p}: no such file")
    header = p.with_suffix(".json") if p.suffix in ("", ".npz") else p
    if not header.is_file():
        if p.with_suffix(".zip").is_file():
            raise ModelFileError(convert_hint(p.with_suffix(".zip")))
        raise ModelFileError(f"{what} {p}: no such model header ({header.name})")
    return header


@dataclass
class ModelFile:
    """A loaded header and its weights."""

    path: Path
    """The header's path."""
    header: dict[str, Any]
    """The checked header."""
    arrays: dict[str, np.ndarray]
    """The weights (numeric arrays)."""


def load_model_file(path: str | Path, *, what: str = "--model", seat: str | None = None) -> ModelFile:
    """Resolve, read and check a model file and its weights (never unpickling).

    Args:
        path: the header, its weights, its stem or its folder.
        what: the user's option, for messages (``--model``, ``--resume``, ``path``).
        seat: refuse a model trained in another seat.
    """
    header_path = resolve_header(path, what)
    header = read_header(header_path)
    if seat is not None and header["seat"] != seat:
        raise ModelFileError(f"{header_path}: trained in the {header['seat']} seat, not the {seat}'s")
    sha = header.get("sha256")
    if not isinstance(sha, str) or not re.fullmatch(r"[0-9a-f]{64}", sha):
        raise ModelFileError(
            f"{header_path}: field 'sha256': expected the 64 hex digits of the weights file's sha256, got {sha!r}"
        )
    budget = (sb3_budget(header) if header["kind"] == "sb3" else None) or MAX_ARRAY_BYTES
    arrays = read_arrays(weights_file(header_path, header), sha, expected_shapes(header), budget)
    for key, value in arrays.items():
        if value.dtype.kind == "f" and not np.isfinite(value).all():
            raise ModelFileError(
                f"{weights_file(header_path, header)}: array {key!r} holds NaN or infinity (weights must be finite)"
            )
    return ModelFile(header_path, header, arrays)


def write_header(path: Path, header: Mapping[str, Any]) -> Path:
    """Write a header atomically (strict JSON: no NaN)."""
    try:
        text = json.dumps(dict(header), indent=1, sort_keys=True, allow_nan=False) + "\n"
    except (TypeError, ValueError) as exc:
        raise ModelFileError(f"{path}: header holds a value JSON cannot store ({exc})") from None
    atomic_write_bytes(path, text.encode())
    return path


def save_model_file(header_path: Path, header: Mapping[str, Any], arrays: Mapping[str, np.ndarray]) -> Path:
    """Write ``<stem>.npz`` then its header ``<stem>.json`` (the header names and hashes the weights)."""
    from hg_marl import __version__

    header_path = Path(header_path).with_suffix(".json")
    weights = header_path.with_suffix(".npz")
    sha = write_arrays(weights, arrays)
    full = {**header, "format": FORMAT, "version": VERSION, "file": weights.name, "sha256": sha}
    full.setdefault("package_version", __version__)
    return write_header(header_path, full)


def world_fields(world: Any, seat: Any, scenario: str | None = None) -> dict[str, Any]:
    """The header fields that tie a policy to a world and a seat."""
    return {
        "seat": seat.label,
        "scenario": scenario if scenario is not None else world.scenario.name,
        "scenario_name": world.scenario.name,
        "fact_names": list(world.fact_names),
        "action_names": list(world.action_names[seat]),
    }


def check_world(mf: ModelFile, world: Any, seat: Any) -> None:
    """Refuse a policy saved for other facts or actions than ``world``'s in ``seat``."""
    if mf.header["fact_names"] != list(world.fact_names) or mf.header["action_names"] != list(world.action_names[seat]):
        raise ModelFileError(
            f"{mf.path}: saved for scenario {mf.header.get('scenario')!r} ({mf.header['seat']}); "
            f"its facts or actions differ from {world.scenario.name!r} ({seat.label})"
        )


# -- SB3 ---------------------------------------------------------------------------------


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
            if not isinstance(shape, list) or not all(isinstance(n, int) and n > 0 for n in shape):
                raise fail("Box shape must be a list of positive integers")
            if int(np.prod(shape)) > MAX_SPACE_SIZE:
                raise fail(f"Box of {int(np.prod(shape))} elements is over the limit {MAX_SPACE_SIZE}")
            dtype = np.dtype(str(data.get("dtype")))
            if dtype.kind not in "biuf":
                raise fail(f"Box dtype {dtype} is not numeric")
            low = np.asarray(data.get("low"), dtype=np.float64)
            high = np.asarray(data.get("high"), dtype=np.float64)
            return spaces.Box(low.astype(dtype), high.astype(dtype), tuple(shape), dtype)
        if kind == "Discrete":
            n, start = data.get("n"), data.get("start", 0)
            if (
                not isinstance(n, int)
                or isinstance(n, bool)
                or not 0 < n <= MAX_SPACE_SIZE
                or not isinstance(start, int)
            ):
                raise fail(f"Discrete n must be an integer in [1, {MAX_SPACE_SIZE}]")
            return spaces.Discrete(n, start=start)
        if kind == "MultiBinary":
            n = data.get("n")
            if not isinstance(n, int) or not 0 < n <= MAX_SPACE_SIZE:
                raise fail(f"MultiBinary n must be an integer in [1, {MAX_SPACE_SIZE}]")
            return spaces.MultiBinary(n)
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
