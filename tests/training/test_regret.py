"""Regret and recovery on synthetic logs whose answers are worked out by hand."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from hg_marl.training.regret import bootstrap_ci, regret_at, tasks_lost, time_to_recover


def synthetic(completions: list[float], end: float, step: float = 10.0) -> pd.DataFrame:
    """A decision every ``step`` s; reward 1 at the decisions in ``completions``."""
    times = np.arange(step, end + 1e-9, step)
    reward = np.isin(times, completions).astype(float)
    return pd.DataFrame({"time": times, "reward": reward})


def test_a_robot_at_the_oracles_pace_loses_nothing() -> None:
    # oracle 120/h = one task per 30 s; the robot solves one every 30 s from the switch at 0
    log = synthetic(list(np.arange(30.0, 601.0, 30.0)), end=600.0)
    assert tasks_lost(log, 0.0, 120.0) == pytest.approx(0.0)
    assert time_to_recover(log, 0.0, 120.0) == 0.0


def test_a_robot_idle_for_300_s_then_at_pace() -> None:
    # nothing for 300 s after the switch, then one task per 30 s (330, 360, ..., 1200)
    log = synthetic(list(np.arange(330.0, 1201.0, 30.0)), end=1200.0)
    # by hand: the oracle solves 1200/30 = 40 tasks, the robot 30
    assert tasks_lost(log, 0.0, 120.0) == pytest.approx(10.0)
    assert regret_at(log, 0.0, 120.0, np.array([-5.0, 150.0, 330.0])) == pytest.approx([0.0, 5.0, 10.0])
    # from tau = 300 (D = 10) the worst later point is just before 330 (D = 11): within the 1-task slack;
    # from tau = 290 (D = 9.67) it is 1.33 behind: not yet recovered
    assert time_to_recover(log, 0.0, 120.0, slack=1.0) == 300.0


def test_switch_in_the_middle_and_a_robot_that_never_recovers() -> None:
    # switch at 600; after it the robot solves one task every 60 s against an oracle at one per 30 s
    before = list(np.arange(30.0, 601.0, 30.0))
    after = list(np.arange(660.0, 1801.0, 60.0))
    log = synthetic(before + after, end=1800.0)
    # by hand: after the switch the oracle solves 1200/30 = 40, the robot 20
    assert tasks_lost(log, 600.0, 120.0) == pytest.approx(20.0)
    assert time_to_recover(log, 600.0, 120.0) is None
    # at the robot's own pace (60/h) it never falls behind: recovered at once
    assert time_to_recover(log, 600.0, 60.0) == 0.0
    # a run shorter than the required tail cannot show a recovery
    assert time_to_recover(log, 600.0, 60.0, min_tail=1500.0) is None


def test_bootstrap_ci() -> None:
    mean, low, high = bootstrap_ci([1.0, 2.0, 3.0, 4.0])
    assert mean == 2.5 and 1.0 <= low < 2.5 < high <= 4.0
    assert bootstrap_ci([1.0, 2.0, 3.0, 4.0]) == (mean, low, high), "seeded: reproducible"
    assert bootstrap_ci([5.0]) == (5.0, 5.0, 5.0)
    assert bootstrap_ci([2.0] * 10) == (2.0, 2.0, 2.0)
    with pytest.raises(ValueError, match="finite"):
        bootstrap_ci([1.0, float("nan")])
