"""The model file format itself: its header and weights, read and written strictly (no SB3, no torch).

:mod:`hg_marl.agents.model_file` describes the format and re-exports this module;
:mod:`hg_marl.agents.model_sb3` rebuilds SB3 models from it.
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

import numpy as np

from hg_marl.agents.model_limits import Shape, check_npz_headers, expected_shapes, sb3_budget
from hg_marl.core.errors import ModelFileError, output_error

FORMAT = "hg_marl.model"
VERSION = 2
KINDS = ("sb3", "linear_softmax", "table", "memory")
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
