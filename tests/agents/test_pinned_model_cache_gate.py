"""The exact results' disk cache, entry by entry: where it lives, what it returns.

Expected values are the rules of ``agents/models/cache.py`` stated from outside: ``True``
means ``$HG_MARL_CACHE/oracle`` when the variable is set and no disk cache otherwise; an
entry is returned only under the very key it was saved with (a smaller or a larger key
is another result), and a missing or corrupt file reads as no entry.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.models.cache import cache_folder, entry_path, load_entry, save_entry
from hg_marl.core import World


def test_true_is_the_environments_cache_folder_or_none(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("HG_MARL_CACHE", str(tmp_path))
    assert cache_folder(True) == tmp_path / "oracle"
    monkeypatch.setenv("HG_MARL_CACHE", "")
    assert cache_folder(True) is None
    monkeypatch.delenv("HG_MARL_CACHE")
    assert cache_folder(True) is None
    assert cache_folder(None) is None and cache_folder(False) is None
    assert cache_folder(str(tmp_path / "mine")) == tmp_path / "mine"


def test_an_entry_is_read_back_under_its_own_key_only(tmp_path: Path) -> None:
    path = entry_path(tmp_path, World("paper2015"), "b" * 64)
    assert path == tmp_path / f"paper2015-{'b' * 24}.npz"
    arrays = {"values": np.array([1.5, 2.5]), "policy": np.array([3, 4], dtype=np.int64)}
    save_entry(path, "b" * 64, arrays)
    got = load_entry(path, "b" * 64)
    assert got is not None and sorted(got) == ["policy", "values"]
    assert got["values"].tolist() == [1.5, 2.5] and got["policy"].tolist() == [3, 4]
    assert load_entry(path, "a" * 64) is None  # a smaller key
    assert load_entry(path, "c" * 64) is None  # a larger key
    assert load_entry(tmp_path / "absent.npz", "b" * 64) is None


def test_a_corrupt_entry_reads_as_none(tmp_path: Path) -> None:
    path = tmp_path / "paper2015-x.npz"
    path.write_bytes(b"not an npz at all")
    assert load_entry(path, "k") is None


def test_an_unwritable_cache_is_left_alone(tmp_path: Path) -> None:
    (tmp_path / "file").write_text("")
    save_entry(tmp_path / "file" / "entry.npz", "k", {"v": np.zeros(2)})  # a folder that is a file: no error
    assert [p.name for p in tmp_path.iterdir()] == ["file"]
