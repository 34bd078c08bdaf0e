"""Atomic writes: the file is complete or absent, 0644, its folder made, nothing left behind.

Each expected value is the rule of ``hg_marl/core/atomic.py`` stated from outside: the
bytes written, the permission bits (owner writes, everyone reads), the folder listing
after a success and after each kind of failure, and which failures become one
``OutputError`` line (a full disk, a read-only place) and which keep their traceback.
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

import pytest

from hg_marl.core.atomic import FILE_MODE, atomic_write
from hg_marl.core.errors import OutputError


def test_a_write_lands_complete_with_mode_0644_in_a_folder_it_creates(tmp_path: Path) -> None:
    target = tmp_path / "a" / "b" / "out.txt"
    old = os.umask(0o077)  # mkstemp's 0600 and a strict umask: the mode is set explicitly
    try:
        got = atomic_write(target, lambda tmp: tmp.write_text("complete"))
    finally:
        os.umask(old)
    assert got == target
    assert target.read_text() == "complete"
    assert FILE_MODE == 0o644
    assert stat.S_IMODE(target.stat().st_mode) == 0o644
    assert sorted(p.name for p in target.parent.iterdir()) == ["out.txt"]


def test_the_temporary_file_sits_beside_the_target_and_is_flushed(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    seen: list[Path] = []
    synced: list[int] = []
    real_fsync = os.fsync

    def record(fd: int) -> None:
        synced.append(fd)
        real_fsync(fd)

    monkeypatch.setattr(os, "fsync", record)
    target = tmp_path / "result.json"
    atomic_write(target, lambda tmp: (seen.append(tmp), tmp.write_text("{}")))
    assert seen[0].parent == tmp_path and seen[0].name.startswith(".result.json.") and seen[0].suffix == ".tmp"
    assert len(synced) == 2  # the file, then its folder's entry
    assert target.read_text() == "{}"


def test_a_replaced_file_is_the_new_one_whole(tmp_path: Path) -> None:
    target = tmp_path / "log.csv"
    target.write_text("old\n" * 100)
    atomic_write(target, lambda tmp: tmp.write_text("new\n"))
    assert target.read_text() == "new\n"
    assert [p.name for p in tmp_path.iterdir()] == ["log.csv"]


def test_a_failed_write_leaves_the_old_file_and_no_temporary(tmp_path: Path) -> None:
    target = tmp_path / "log.csv"
    target.write_text("old")

    def fail(tmp: Path) -> None:
        tmp.write_text("half")
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        atomic_write(target, fail)
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["log.csv"]


@pytest.mark.parametrize("code", [errno.ENOSPC, errno.EROFS, errno.EACCES])
def test_a_full_disk_or_read_only_place_is_one_line_and_nothing_is_left(tmp_path: Path, code: int) -> None:
    target = tmp_path / "out.bin"

    def fail(tmp: Path) -> None:
        tmp.write_bytes(b"x")
        raise OSError(code, os.strerror(code))

    with pytest.raises(OutputError, match=rf"^cannot write {target}: {os.strerror(code)}$"):
        atomic_write(target, fail)
    assert list(tmp_path.iterdir()) == []


def test_an_os_error_a_user_cannot_fix_keeps_its_type(tmp_path: Path) -> None:
    def fail(tmp: Path) -> None:
        raise OSError(errno.EBADF, "bad file descriptor")

    with pytest.raises(OSError) as info:
        atomic_write(tmp_path / "out.bin", fail)
    assert not isinstance(info.value, OutputError) and info.value.errno == errno.EBADF
    assert list(tmp_path.iterdir()) == []


def test_no_room_for_the_temporary_file_is_one_line(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    import tempfile

    def full(*args: object, **kwargs: object) -> tuple[int, str]:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(tempfile, "mkstemp", full)
    target = tmp_path / "out.txt"
    with pytest.raises(OutputError, match=rf"^cannot write {target}: {os.strerror(errno.ENOSPC)}$"):
        atomic_write(target, lambda tmp: tmp.write_text("x"))
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("failure", [OSError(errno.ENOSPC, "No space left on device"), KeyboardInterrupt()])
def test_a_writer_that_removed_its_temporary_file_keeps_its_own_error(tmp_path: Path, failure: BaseException) -> None:
    """A writer (a library that cleans up after itself) may delete the file before failing:
    the caller still sees that failure (one ``OutputError`` line, or the interrupt), not a
    ``FileNotFoundError`` from the clean-up."""

    def fail(tmp: Path) -> None:
        tmp.write_text("half")
        tmp.unlink()
        raise failure

    expected = OutputError if isinstance(failure, OSError) else KeyboardInterrupt
    with pytest.raises(expected):
        atomic_write(tmp_path / "out.bin", fail)
    assert list(tmp_path.iterdir()) == []


def test_a_folder_that_cannot_be_opened_for_its_sync_still_gets_the_file(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """Where a folder cannot be opened (some systems and file systems refuse it), syncing
    its entry is skipped: the file is in place all the same."""
    real_open = os.open

    def no_folders(path: object, flags: int, *args: object) -> int:
        if Path(str(path)).is_dir():
            raise PermissionError(errno.EACCES, "folders cannot be opened here", str(path))
        return real_open(path, flags, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(os, "open", no_folders)
    target = tmp_path / "out.txt"
    assert atomic_write(target, lambda tmp: tmp.write_text("whole")) == target
    assert target.read_text() == "whole" and [p.name for p in tmp_path.iterdir()] == ["out.txt"]
