"""Values that round 125's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import os
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import pytest

from hg_marl.agents.models.budget import Budget, OverBudget
from hg_marl.agents.models.forked import Forked
from hg_marl.core.errors import ConfigError
from hg_marl.core.world import World
from hg_marl.training.backends import LocalBackend
from hg_marl.training.baselines.recipes import FCP_LEVELS, NoisyPartner
from hg_marl.training.outputs import check_output
from tests.fuzz.test_outputs import needs_proc
from tests.training.test_pinned_round62 import _Inner


def test_a_machine_short_of_memory_advises_raising_max_states() -> None:
    # A machine with no memory left: the refusal names the machine's floor, and the option that
    # makes the build fit (a smaller model: --max-states), not the process's own memory budget
    # (--max-memory would only let the build grow further). No states, time or memory budget.
    budget = Budget(None, None, None, subject="the test", free_memory=lambda: 0)
    with pytest.raises(OverBudget) as info:
        budget.check("explore", 1, memory=True)
    message = str(info.value)
    assert "less than 512 MB of memory left" in message
    assert "raise --max-states or" in message
    assert "--max-memory" not in message


def test_forked_jobs_are_checked_and_zero_means_one_per_cpu() -> None:
    # check_jobs: "0: one per CPU", at most MAX_JOBS = 256; a negative count is refused in one line.
    expected = min(os.cpu_count() or 1, 256)
    assert Forked(lambda i: i, jobs=0).jobs == expected >= 1
    assert Forked(lambda i: i, jobs=3).jobs == 3
    with pytest.raises(ValueError, match=r"jobs must be a whole number from 0 \(one per CPU\) to 256, got -1"):
        Forked(lambda i: i, jobs=-1)


@needs_proc
def test_an_unwritable_folder_is_named_as_the_folder_not_the_file() -> None:
    # An output file in /proc: the folder exists, but no file can be created there (not even by
    # root), so the probe's refusal names the folder it could not write in, "/proc", and stops there.
    path = Path("/proc/hg-marl-probe-out.csv")
    with pytest.raises(ConfigError) as info:
        check_output(path, "--out")
    message = str(info.value)
    assert message.startswith(f"--out {path}: cannot write in /proc (")
    assert f"cannot write in {path}" not in message


def test_a_noisy_partners_name_lists_its_levels_in_the_shortest_form() -> None:
    # FCP_LEVELS = (0.0, 0.3, 0.6) written with Python's 'g' format: 0.0 -> "0", 0.3 -> "0.3".
    partner = NoisyPartner(World("paper2015"), _Inner(), FCP_LEVELS)
    assert partner.name == "stub~eps0/0.3/0.6"
    assert NoisyPartner(World("paper2015"), _Inner(), (1.0,)).name == "stub~eps1"


def test_two_local_workers_are_a_pool_of_two_processes() -> None:
    # The module docstring: "workers=1 runs jobs in this process; more starts a spawn process
    # pool". A pool starts no process before a job is submitted, so nothing runs here.
    one = LocalBackend(1)
    two = LocalBackend(2)
    try:
        assert one._pool is None
        assert isinstance(two._pool, ProcessPoolExecutor)
        assert vars(two._pool)["_max_workers"] == 2  # the pool of two the user asked for
        assert two.capacity == 2
    finally:
        one.close()
        two.close()
