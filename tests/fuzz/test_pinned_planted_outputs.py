"""Pinned against a planted bug: a file ending is accepted whatever its case (``OUT.PNG`` is a png)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.outputs import check_output


@pytest.mark.parametrize("name", ["plot.png", "plot.PNG", "plot.Png"])
def test_the_suffix_check_ignores_case(tmp_path: Path, name: str) -> None:
    assert check_output(tmp_path / name, "--out", suffixes=(".png",)) == tmp_path / name


def test_another_suffix_is_still_refused(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match=r"--out .*expected a file name ending in \.png"):
        check_output(tmp_path / "plot.jpg", "--out", suffixes=(".png",))
