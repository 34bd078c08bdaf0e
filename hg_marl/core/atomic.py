"""Atomic writes: a file is either absent or complete, never half-written.

The file goes to a temporary file in the same directory, is flushed to disk
(``fsync``), then ``os.replace`` puts it in place (atomic on POSIX) and the directory
entry is synced too, so an interrupted run or a power cut leaves no torn file and a
resumed run can trust whatever it finds. Files are made readable by others (0644):
results are meant to be shared, and ``mkstemp`` alone would leave them 0600.

It lives in the core (stdlib only) so that every layer can write atomically: the
agents' compiled-table caches as well as the training runs' results
(``hg_marl.training.io`` adds the JSON and text writers on top).
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from pathlib import Path

from hg_marl.core.errors import output_error

FILE_MODE = 0o644
"""Permissions of every result file: the owner writes, everyone reads."""


def _fsync_dir(directory: Path) -> None:
    """Make a rename in ``directory`` durable (a no-op where directories cannot be opened)."""
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def atomic_write(path: str | Path, write: Callable[[Path], object]) -> Path:
    """Call ``write(tmp_path)``, flush it to disk, then move it onto ``path`` (mode 0644).

    Raises:
        OutputError: a full disk, a forbidden or read-only folder (the temporary file is
            removed: nothing half-written is left behind).
    """
    path = Path(path)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    except OSError as exc:
        raise (output_error(exc, path) or exc) from None
    os.close(fd)
    try:
        write(Path(tmp))
        fd = os.open(tmp, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)
        os.chmod(tmp, FILE_MODE)
        os.replace(tmp, path)
        _fsync_dir(path.parent)
    except OSError as exc:
        Path(tmp).unlink(missing_ok=True)
        error = output_error(exc, path)
        if error is None:
            raise
        raise error from None
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path
