"""An existing output file that this process may not write is refused before any work.

Tests may run as root, for whom a file's permission bits refuse nothing, so the OS's
refusal is simulated: opening that one file for writing raises ``EACCES``, as it does for
an ordinary user on a 0444 file. The expected message is the rule of
``training/outputs.py`` (one line naming the option, the path and the reason), and the
file is left exactly as it was.
"""

from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.outputs import check_output


def test_an_existing_file_that_cannot_be_opened_for_writing_is_refused(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    target = tmp_path / "log.csv"
    target.write_text("kept")
    real_open = os.open

    def refusing(path: object, flags: int, *args: object) -> int:
        if Path(str(path)) == target and flags & (os.O_WRONLY | os.O_RDWR):
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(path))
        return real_open(path, flags, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(os, "open", refusing)
    with pytest.raises(ConfigError) as info:
        check_output(target, "--out")
    assert str(info.value) == f"--out {target}: file is not writable ({os.strerror(errno.EACCES)})"
    assert target.read_text() == "kept" and [p.name for p in tmp_path.iterdir()] == ["log.csv"]


def test_an_existing_writable_file_is_accepted_unchanged(tmp_path: Path) -> None:
    target = tmp_path / "log.csv"
    target.write_text("kept")
    assert check_output(target, "--out", suffixes=(".csv",)) == target
    assert target.read_text() == "kept" and [p.name for p in tmp_path.iterdir()] == ["log.csv"]
