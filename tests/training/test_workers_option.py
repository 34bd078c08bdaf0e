"""``--workers``: one limit for every command, the one the backends enforce, and one default."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.commands.common import check_workers, default_workers
from tests.cli_helpers import error_lines, run_main

STUDY = Path(__file__).resolve().parents[2] / "studies" / "crossplay.toml"


@pytest.fixture
def two_cpus(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(os, "cpu_count", lambda: 2)


@pytest.mark.usefixtures("two_cpus")
def test_a_command_accepts_four_workers_per_cpu_and_no_more() -> None:
    """On two CPUs the backends take 1 to 8 workers (4 per CPU); the commands took up to 64 before."""
    assert [check_workers(n) for n in range(1, 9)] == list(range(1, 9))
    for refused in (0, 9, 64):
        with pytest.raises(ConfigError, match=rf"^--workers: expected an integer from 1 to 8 .*got {refused}$"):
            check_workers(refused)


@pytest.mark.usefixtures("two_cpus")
def test_evaluate_refuses_more_workers_than_the_backends_take_before_reading_the_study(tmp_path: Path) -> None:
    code, _, err = run_main(["evaluate", str(STUDY), "--out", str(tmp_path / "out"), "--workers", "9"])
    assert code == 2
    assert error_lines(err) == ["error: --workers: expected an integer from 1 to 8 (4 per CPU, at most 256), got 9"]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(("cpus", "expected"), [(1, 1), (2, 2), (16, 2), (None, 1)])
def test_the_default_is_two_workers_or_one_per_cpu_below_that(
    monkeypatch: pytest.MonkeyPatch, cpus: int | None, expected: int
) -> None:
    monkeypatch.setattr(os, "cpu_count", lambda: cpus)
    assert default_workers() == expected
