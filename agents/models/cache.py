"""Exact results cached on disk by content, as the compiled partners are (``agents/compiled.py``).

An oracle's result (its rate, sizes, and its policy and values as packed keys and arrays)
is stored as one ``.npz`` under a folder the user named, keyed by everything that made it
(:mod:`hg_marl.agents.content`): the scenario and durations (their ``repr``), the human's
spec and the content of any file it names (``path=``), the oracle's options, and the code
of every module the oracle and the humans import. The entry stores its key and is refused
if the key differs; a corrupt entry is rebuilt. Writes are atomic (a temporary file in
the same folder, then a rename). ``cache=True`` uses ``$HG_MARL_CACHE/oracle`` when that
variable is set and no disk cache otherwise; a human given as an instance has no content
key and is never cached.
"""

from __future__ import annotations

import io
import os
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.core import World
from hg_marl.core.atomic import atomic_write
from hg_marl.core.errors import OutputError


def cache_folder(cache: Path | str | bool | None) -> Path | None:
    """The folder ``cache`` names (True: ``$HG_MARL_CACHE/oracle`` if set), or None for no disk cache."""
    if cache is None or cache is False:
        return None
    if cache is True:
        root = os.environ.get("HG_MARL_CACHE")
        return Path(root) / "oracle" if root else None
    return Path(cache)


def named_folder(folder: Path | str, option: str) -> Path:
    """A cache folder the user named, created if missing and tried with a temporary file before any work.

    A folder named by the user is an output: a typo or a folder nobody can write would
    otherwise leave every run solving its models again in silence. Created because the
    user named it, as every output folder is (docs/inputs.md); only ``$HG_MARL_CACHE``, a
    machine-wide convenience, stays best effort. Raises :class:`OutputError`, one line
    naming ``option``.
    """
    path = Path(folder)
    try:
        path.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".hg-marl-probe-", dir=path)
    except OSError as exc:
        raise OutputError(f"{option} {path}: cannot write in it ({exc.strerror or exc})") from None
    os.close(fd)
    os.unlink(tmp)
    return path


def result_key(world: World, spec: str, options: dict[str, Any]) -> str:
    """The content key of one result (:func:`hg_marl.agents.content.content_key`): the scenario, the
    durations, the human's spec (and the files it names), the options, and the code the oracle runs."""
    from hg_marl.agents import content
    from hg_marl.agents.humans.registry import HUMANS

    fields = {"scenario": repr(world.scenario), "durations": repr(world.durations), "spec": spec, "options": options}
    return content.content_key("oracle", fields, ("hg_marl.agents.oracle", *content.registry_targets(HUMANS)))


def entry_path(folder: Path, world: World, key: str) -> Path:
    """Where the entry of ``key`` lives."""
    return folder / f"{world.scenario.name.split(':')[0]}-{key[:24]}.npz"


def load_entry(path: Path, key: str) -> dict[str, np.ndarray] | None:
    """The arrays of the entry at ``path`` if it exists and holds ``key``; None otherwise (corrupt included)."""
    if not path.exists():
        return None
    try:
        with np.load(path, allow_pickle=False) as data:
            if str(data["key"]) != key:
                return None
            return {k: data[k] for k in data.files if k != "key"}
    except (OSError, ValueError, KeyError, EOFError):
        return None


def save_entry(path: Path, key: str, arrays: dict[str, np.ndarray]) -> None:
    """Write the entry atomically (no pickle); a folder that cannot be written is left alone."""
    buf = io.BytesIO()
    np.savez(buf, key=np.array(key), **arrays)  # type: ignore[arg-type]
    try:
        atomic_write(path, lambda tmp: tmp.write_bytes(buf.getvalue()))
    except (OSError, OutputError):
        return  # a cache is an optimisation: nothing half-written is left behind, nothing is raised
