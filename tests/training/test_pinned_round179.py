"""Values that round 179's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.compiled_robot import compile_robot
from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.robots.registry import make_robot
from hg_marl.core import World
from hg_marl.core.batch import BatchState
from hg_marl.training.baselines.recipes import CoveragePartner
from hg_marl.training.outputs import check_output
from hg_marl.training.runner import COLUMNS, RunConfig, RunResult, run, summarise
from hg_marl.training.store import Store
from tests.agents.test_oracle import TINY
from tests.training.test_pinned_planted_recipes import _Member
from tests.training.test_pinned_store import JOB


def test_a_checked_output_path_comes_back_as_the_user_gave_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The check only refuses or accepts: the path a command goes on with (and names in its
    # messages) is the one the user typed, relative here, not the same place made absolute.
    monkeypatch.chdir(tmp_path)
    (tmp_path / "results").mkdir()
    assert check_output(Path("results/log.csv"), "--out", suffixes=(".csv",)) == Path("results/log.csv")
    assert check_output(Path("study/run1"), "--out", folder=True) == Path("study/run1")


def test_the_coverage_partner_is_named_after_its_members_with_the_coverage_mark() -> None:
    # The member is called "member"; the recipe's partner adds "~coverage" (as fcp's adds "~eps..."),
    # so a log tells a coverage run's partner from the bare members.
    partner = CoveragePartner(World("paper2015"), _Member())
    assert partner.name == "member~coverage"


def test_each_decision_is_logged_at_the_cycles_completed_before_it() -> None:
    # One robot decision per cycle: the robot moves, the human answers, and only then is the
    # cycle complete. So decision 0 is taken with no cycle completed (0), decision k after k
    # cycles: the column reads 0, 1, 2, ... down the log, one more per row.
    result = run(make_robot("random"), make_human("cooperative"), RunConfig(duration=30.0, seed=1))
    assert len(result.log) >= 5
    assert result.log["cycle"].tolist() == list(range(len(result.log)))


def test_a_stored_runs_log_reads_back_with_the_runners_columns_and_values(tmp_path: Path) -> None:
    # A two-row log of plain integers in the runner's columns: read back from the store, it has
    # exactly those columns (no extra index column) and the same values.
    log = pd.DataFrame({c: [0, 1] for c in COLUMNS})
    store = Store(tmp_path)
    store.put(JOB, RunResult(RunConfig(duration=60.0), log, summarise(log, 60.0)))
    again = store.get(JOB)
    assert again is not None
    back = again.log()
    assert list(back.columns) == list(COLUMNS)
    assert back.to_dict("list") == {c: [0, 1] for c in COLUMNS}


def test_stall_moves_taken_keeps_the_moves_of_a_table_reset_since() -> None:
    # As the gate's frozen table: one state that never changes, K = 3, six turns, so turns 4-6
    # are stall moves: 3 taken. A reset zeroes the table's own count, not what was taken in all.
    world = World(TINY)
    robot = compile_robot(world, cache=None, stall_after=3)
    state = world.initial_state(np.random.default_rng(11))
    robot.reset_rows(np.array([0]), np.random.default_rng(0))
    for _ in range(6):
        robot.act(BatchState.of([state]), np.array([-1]), np.random.default_rng(0))
    assert robot.stall_moves_taken == 3
    robot.reset_rows(np.array([0]), np.random.default_rng(0))
    assert robot.stall_count.tolist() == [0]
    assert robot.stall_moves_taken == 3
