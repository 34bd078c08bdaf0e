"""Where a command may write: every output path is checked the same way, before any work starts.

The rule (docs/inputs.md states it for users):

- an output **file** (``run --out log.csv``, ``plan --png``, ``--video``) goes in a folder
  that exists: a missing folder is refused, not created (a typo in a folder name would
  otherwise leave a tree of folders the user never asked for);
- an output **folder** (``evaluate --out``, ``reproduce --out``, ``play --record``) is the
  one thing a command creates if it is missing, with its missing parents, since the
  user named it;
- either way, the place is tried before the work: a temporary file is created in the
  folder (or, for a folder still to be created, in its nearest existing ancestor) and
  removed at once. Asking the OS is the only check that holds for every user (``root``
  passes every permission test, yet cannot write under ``/proc`` or on a read-only
  disk), and it leaves nothing behind.

A refusal is one :class:`~hg_marl.core.errors.ConfigError` line naming the option.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from hg_marl.core.errors import ConfigError


def _try_writing_in(folder: Path, option: str, path: Path) -> None:
    """Create and remove a temporary file in ``folder``; an OS refusal becomes one line."""
    try:
        fd, tmp = tempfile.mkstemp(prefix=".hg-marl-probe-", dir=folder)
    except OSError as exc:
        raise ConfigError(f"{option} {path}: cannot write in {folder} ({exc.strerror or exc})") from None
    os.close(fd)
    os.unlink(tmp)


def _nearest_existing(path: Path) -> Path:
    """``path`` or its nearest ancestor that exists."""
    for candidate in (path, *path.parents):
        if candidate.exists():
            return candidate
    return Path(path.anchor or ".")


def check_output(path: Path, option: str, *, folder: bool = False, suffixes: tuple[str, ...] = ()) -> Path:
    """Refuse an output path this process cannot write, before any work (the module's rule).

    Args:
        path: the path the user gave.
        option: the option that gave it (``--out``), named in the message.
        folder: the path names a folder (created later if missing); else a file.
        suffixes: for a file, the accepted endings (``(".png",)``), lower case.

    Raises:
        ConfigError: one line naming ``option``, the path and what is wrong with it.
    """
    path = Path(path)
    try:
        if folder:
            if path.exists() and not path.is_dir():
                raise ConfigError(f"{option} {path}: is a file; name a folder")
            base = _nearest_existing(path)
            if not base.is_dir():
                raise ConfigError(f"{option} {path}: {base} is a file, not a folder")
        else:
            if suffixes and path.suffix.lower() not in suffixes:
                raise ConfigError(f"{option} {path}: expected a file name ending in {' or '.join(suffixes)}")
            if path.is_dir():
                raise ConfigError(f"{option} {path}: is a folder; name a file")
            base = path.parent
            if not base.is_dir():
                found = _nearest_existing(base)
                if found.exists() and not found.is_dir():
                    raise ConfigError(f"{option} {path}: {found} is a file, not a folder")
                raise ConfigError(f"{option} {path}: folder {base} does not exist (create it first)")
            if path.exists() and not path.is_file():  # a device or a pipe would be replaced, not written
                raise ConfigError(f"{option} {path}: not a regular file (results replace the file they name)")
            if path.exists():
                try:  # opened for appending and closed: the file is not changed
                    os.close(os.open(path, os.O_WRONLY | os.O_APPEND))
                except OSError as exc:
                    raise ConfigError(f"{option} {path}: file is not writable ({exc.strerror or exc})") from None
    except OSError as exc:  # a name too long, a path through something that is not a folder
        raise ConfigError(f"{option} {path}: not a usable path ({exc.strerror or exc})") from None
    _try_writing_in(base, option, path)
    return path
