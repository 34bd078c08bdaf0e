"""Values that round 170's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.vector_envs import robot_vector_env
from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchedRules, BatchState
from hg_marl.training import adaptation
from hg_marl.training.adaptation import AdaptationConfig
from hg_marl.training.aggregate import aggregate
from hg_marl.training.baselines.recipes import CoveragePartner
from hg_marl.training.store import Job, Store
from tests.training.test_aggregate import _table
from tests.training.test_pinned_adaptation import SLOW, THERE_AND_BACK
from tests.training.test_pinned_round80 import _clean_state, _Table, _Waiting
from tests.training.test_pinned_store import _result


def test_the_coverage_recipe_moves_a_table_reset_on_its_own() -> None:
    # One table reset alone (the batched table resets each table as its episode ends). With
    # cycles=1 it draws 0 random moves, so it stays as given: the clean table. The recipe's rule
    # holds for every reset table: one its moves leave clean is re-drawn (a fresh layout is never
    # clean: every object starts on a spot) and marked stale, as when several reset together.
    world = World("paper2015")
    rules = BatchedRules(world)
    table = _Table(BatchState.of([_clean_state(world)]))
    partner = CoveragePartner(world, _Waiting(world), cycles=1)
    partner.attach(table)
    partner.reset_rows(np.array([0]), np.random.default_rng(0))
    assert not rules.is_clean(table.state).any()
    assert table._stale.tolist() == [True]


def test_a_stored_run_keeps_the_jobs_description_with_its_label(tmp_path: Path) -> None:
    # The entry's "job" is the job as plain JSON (Job.describe: every field, the label included,
    # for people asking why a run was made), written out here field by field.
    job = Job(robot="planner", seed=2, duration=60.0, human="cooperative", label="table row 3")
    described = {
        "robot": "planner",
        "seed": 2,
        "scenario": "paper2015",
        "duration": 60.0,
        "human": "cooperative",
        "robot_params": {},
        "human_params": {},
        "label": "table row 3",
        "charge_decision_time": True,
    }
    store = Store(tmp_path)
    assert store.put(job, _result()).job == described
    found = store.get(job)
    assert found is not None and found.job == described


def test_the_robot_seat_truncates_at_its_time_budget() -> None:
    # Both seats wait (1 s each by default), so each cycle adds 1 s to the table's clock. With a
    # time budget of 2.5 s and no cycle cap the episode is truncated once the clock reaches it:
    # at 1 s and 2 s it goes on, at 3 s (>= 2.5) it is truncated, never terminated (no success).
    world = World("paper2015")
    env = robot_vector_env(num_envs=1, max_cycles=None, time_budget=2.5, partner=_Waiting(world))
    env.reset(seed=0)
    wait = np.array([world.table.wait[Agent.ROBOT]])
    seen = []
    for _ in range(3):
        _, _, terminated, truncated, _ = env.step(wait)
        seen.append((bool(terminated[0]), bool(truncated[0])))
    assert seen == [(False, False), (False, False), (False, True)]


def test_a_bin_is_reached_by_the_robot_from_its_location_and_never_by_the_human() -> None:
    # paper2015's trashbin (bin 0): robot_reach = ["bin_side"] (location 0), human_reach = false.
    world = World("paper2015")
    at_bin, at_table = State((0, 1, 4), 0), State((0, 1, 4), 1)
    assert world.bin_reachable(at_bin, Agent.ROBOT, 0) is True
    assert world.bin_reachable(at_table, Agent.ROBOT, 0) is False
    assert world.bin_reachable(at_bin, Agent.HUMAN, 0) is False
    assert world.bin_reachable(at_table, Agent.HUMAN, 0) is False


def test_the_adaptation_summary_counts_seeds_per_robot_not_jobs(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    # Two seeds of two robots on one switch: 4 jobs, but each (robot, switch) has 2 seeds, and the
    # summary (and the table's first line) says 2. The sweep, oracle and figures are stand-ins.
    class Rate:
        rate_per_hour = 36.0

    monkeypatch.setattr("hg_marl.agents.oracle.oracle_rate", lambda scenario, human: Rate())
    monkeypatch.setattr(adaptation, "run_sweep", lambda jobs, out, workers=1, on_done=None: None)
    monkeypatch.setattr(adaptation, "load_log", lambda job, out: SLOW)
    monkeypatch.setattr("hg_marl.training.plots.adaptation", lambda *args: args[-1])
    monkeypatch.setattr("hg_marl.training.plots.regret_bars", lambda results, path: path)
    config = AdaptationConfig(
        seeds=2, duration=1000.0, switches=("back",), robots=("planner", "habit"), custom={"back": THERE_AND_BACK}
    )
    assert len(adaptation.adaptation_jobs(config)) == 4
    summary, _ = adaptation.run_adaptation(tmp_path, config)
    assert summary["seeds"] == 2
    assert adaptation.adaptation_table(summary).splitlines()[0].startswith("adaptation: 2 seeds, 1000 s runs;")


def _improvement(reps: int, poi_reps: int) -> dict[str, Any]:
    frame: pd.DataFrame = _table({"A": {"h": [1.0, 2.0, 0.0]}, "B": {"h": [1.5, 0.5, 3.0]}})
    agg = aggregate(frame, reps=reps, poi_reps=poi_reps)
    assert agg["bootstrap"]["poi_reps"] == poi_reps
    return dict(agg["improvement"]["A>B"])


def test_improvement_intervals_take_poi_reps_replications_whatever_reps() -> None:
    # One replication of the probability of improvement is one resampled value, so its 95%
    # percentile interval is that value twice (low == high); and the IQM's replications (reps)
    # play no part in it: the same interval with reps 50 and 400.
    one = _improvement(reps=400, poi_reps=1)
    assert one["ci"][0] == one["ci"][1]
    assert _improvement(reps=50, poi_reps=1) == one
    assert _improvement(reps=50, poi_reps=200) == _improvement(reps=400, poi_reps=200)
