"""Regret, time to recover and the bootstrap interval, pinned for the mutation gate.

Expected values come from the definitions in :mod:`hg_marl.training.regret`'s docstring,
recomputed here by a plain reference written from them (no numpy searches, no suffix
maxima): ``D(t) = rate / 3600 * (t - switch) - N(t)`` counted completion by completion,
and the time to recover found by trying every candidate ``tau`` in turn and taking the
supremum of ``D`` over ``[tau, stop]``, which (``D`` rising between completions) is
reached at ``stop`` or just before a completion. Logs are drawn from a seeded generator,
so every run checks the same cases. The bootstrap's interval is read from its stated
recipe: ``n_boot`` (2000 by default) means of resamples drawn with ``default_rng(seed)``
and the ``(1 - level) / 2`` tails cut from each side.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from hg_marl.training.regret import bootstrap_ci, regret_at, tasks_lost, time_to_recover


def _random_log(rng: np.random.Generator) -> pd.DataFrame:
    """Decisions every 10 s in bursts of work and idleness, so the robot falls behind and catches up."""
    n = int(rng.integers(5, 80))
    times = 10.0 * np.arange(1, n + 1)
    p_solve = rng.choice([0.0, 0.1, 0.4, 0.8], size=n)  # varying pace along the run
    reward = (rng.random(n) < p_solve).astype(float)
    return pd.DataFrame({"time": times, "reward": reward})


def _completions(log: pd.DataFrame, switch: float, upto: float) -> list[float]:
    return [float(t) for t, r in zip(log["time"], log["reward"], strict=True) if r > 0 and switch < t <= upto]


def _regret(log: pd.DataFrame, switch: float, rate: float, t: float) -> float:
    """``D(t)`` by its definition: the oracle's expected tasks since the switch minus those solved."""
    if t <= switch:
        return 0.0
    return rate / 3600.0 * (t - switch) - len(_completions(log, switch, t))


def _recover(
    log: pd.DataFrame, switch: float, rate: float, slack: float, min_tail: float, end: float | None
) -> float | None:
    """The earliest decision ``tau >= switch`` after which ``D`` never exceeds ``D(tau) + slack``."""
    stop = float(log["time"].iloc[-1]) if end is None else end
    if stop - switch < min_tail:
        return None
    done = _completions(log, switch, stop)
    candidates = [switch] + [float(t) for t in log["time"] if switch < t <= stop - min_tail]
    for tau in candidates:
        # just before completion c, D is the oracle's tasks at c minus the completions before c
        before = [rate / 3600.0 * (c - switch) - sum(1 for d in done if d < c) for c in done if c > tau]
        worst = max([_regret(log, switch, rate, stop), *before])
        if worst - _regret(log, switch, rate, tau) <= slack + 1e-9:
            return tau - switch
    return None


def test_regret_is_the_oracles_expected_tasks_minus_the_robots_at_every_time() -> None:
    rng = np.random.default_rng(7)
    for _ in range(100):
        log = _random_log(rng)
        switch = float(rng.choice([0.0, 35.0, 100.0, 250.0]))
        rate = float(rng.choice([36.0, 90.0, 120.0, 200.0]))
        grid = np.array([-10.0, switch, switch + 5.0, *log["time"], 1000.0])
        expected = [_regret(log, switch, rate, float(t)) for t in grid]
        assert regret_at(log, switch, rate, grid) == pytest.approx(expected, abs=1e-9)
        end = float(rng.choice([log["time"].iloc[-1], 600.0]))
        assert tasks_lost(log, switch, rate) == pytest.approx(_regret(log, switch, rate, float(log["time"].iloc[-1])))
        assert tasks_lost(log, switch, rate, end=end) == pytest.approx(_regret(log, switch, rate, end))


def test_recovery_is_the_first_decision_from_which_the_robot_never_falls_more_than_slack_behind() -> None:
    rng = np.random.default_rng(11)
    recovered = late = 0
    for _ in range(400):
        log = _random_log(rng)
        switch = float(rng.choice([0.0, 20.0, 95.0]))
        rate = float(rng.choice([36.0, 90.0, 120.0, 200.0]))
        slack = float(rng.choice([0.5, 1.0, 2.0, 3.5]))
        min_tail = float(rng.choice([0.0, 50.0, 200.0]))
        end = None if rng.random() < 0.7 else float(rng.choice([300.0, 900.0]))
        expected = _recover(log, switch, rate, slack, min_tail, end)
        assert time_to_recover(log, switch, rate, slack=slack, min_tail=min_tail, end=end) == expected
        recovered += expected is not None
        late += expected is not None and expected > 0
    assert recovered > 50 and late > 20  # the draw covers immediate, late and missing recoveries


def test_a_run_ends_at_its_last_logged_decision_unless_told() -> None:
    # oracle 36/h = one task per 100 s; decisions every 100 s to 700 s
    idle = pd.DataFrame({"time": 100.0 * np.arange(1, 8), "reward": [0.0] * 7})
    # by hand: the oracle solves 7 by 700 s (6 by 600 s), the idle robot none
    assert tasks_lost(idle, 0.0, 36.0) == pytest.approx(7.0)
    assert tasks_lost(idle, 0.0, 36.0, end=600.0) == pytest.approx(6.0)
    at_pace = pd.DataFrame({"time": 100.0 * np.arange(1, 8), "reward": [1.0] * 7})  # one task per decision
    # 700 s of run after the switch show a 650 s tail (600 s would not): recovered at once
    assert time_to_recover(at_pace, 0.0, 36.0, min_tail=650.0) == 0.0
    assert time_to_recover(at_pace, 0.0, 36.0, min_tail=650.0, end=600.0) is None


def test_only_a_positive_reward_is_a_task_solved() -> None:
    # oracle 36/h: 3 tasks by 300 s; the robot's rows at 100, 200, 300 s: nothing, a penalty, a task
    log = pd.DataFrame({"time": [100.0, 200.0, 300.0], "reward": [0.0, -1.0, 1.0]})
    assert tasks_lost(log, 0.0, 36.0) == pytest.approx(3.0 - 1.0)


def test_a_run_exactly_min_tail_long_can_show_a_recovery() -> None:
    # oracle 36/h = one task per 100 s; the robot solves one at 100, 200 and 300 s: it never lags
    # more than one task (D peaks at 1 just before each completion), so it is recovered at once
    at_pace = pd.DataFrame({"time": [100.0, 200.0, 300.0], "reward": [1.0, 1.0, 1.0]})
    assert time_to_recover(at_pace, 0.0, 36.0) == 0.0  # 300 s of run, the default tail
    assert time_to_recover(at_pace, 0.0, 36.0, min_tail=300.5) is None


def test_the_defaults_are_one_task_of_slack_and_300_s_of_tail() -> None:
    # oracle 36/h; the robot idle for 200 s, then one task every 100 s (300 ... 1000 s). D at the
    # decisions: 1 (100 s), 2 (200 s), then 2 after each completion; D peaks at 3 just before each.
    # From tau = 100 s the worst lag is 3 - 1 = 2 tasks, from 200 s it is 3 - 2 = 1.
    late = pd.DataFrame({"time": 100.0 * np.arange(1, 11), "reward": [0.0, 0.0] + [1.0] * 8})
    assert time_to_recover(late, 0.0, 36.0) == 200.0
    assert time_to_recover(late, 0.0, 36.0, slack=2.0) == 100.0
    # oracle 7200/h (2 tasks a second); the robot idle for 1 s, then 2 tasks a second (1.5, 2.0,
    # ..., 300.5 s). D: 1 at 0.5 s, 2 at 1.0 s, peaks of 3 just before each completion, so from
    # tau = 0, 0.5 and 1.0 s the worst lag is 3, 2 and 1: only tau = 1.0 s qualifies, and only a
    # tail of at most 299.5 s lets that decision be a candidate in a run of 300.5 s
    times = 0.5 * np.arange(1, 602)
    fast = pd.DataFrame({"time": times, "reward": (times >= 1.5).astype(float)})
    assert time_to_recover(fast, 0.0, 7200.0) is None
    assert time_to_recover(fast, 0.0, 7200.0, min_tail=299.0) == 1.0


def test_a_robot_that_solves_nothing_recovers_only_when_less_than_the_slack_is_left_to_lose() -> None:
    # oracle 3600/h = one task a second; nothing solved: D(t) = t and its worst later value is
    # D(1000) = 1000, so tau must reach 999 s; 998.8 s still has 1.2 tasks to lose
    times = [100.0 * k for k in range(1, 10)] + [998.8, 999.0, 1000.0]
    idle = pd.DataFrame({"time": times, "reward": [0.0] * len(times)})
    assert time_to_recover(idle, 0.0, 3600.0, min_tail=0.0) == 999.0


def _resampled_means(values: list[float], n_boot: int, seed: int) -> np.ndarray:
    x = np.asarray(values)
    return np.asarray(x[np.random.default_rng(seed).integers(0, x.size, size=(n_boot, x.size))].mean(axis=1))


VALUES = [0.31, 1.7, 2.23, 4.9, 8.15, 13.6, 21.4]
"""Uneven values: the resample means take many distinct values, so the percentiles move with the draw."""


def test_the_default_interval_cuts_2_5_percent_from_each_tail_of_2000_seeded_resamples() -> None:
    mean, low, high = bootstrap_ci(VALUES)
    means = _resampled_means(VALUES, 2000, 0)
    assert mean == pytest.approx(sum(VALUES) / len(VALUES))
    assert (low, high) == pytest.approx(tuple(np.percentile(means, [2.5, 97.5])), rel=1e-12)
    other = _resampled_means(VALUES, 1000, 0)  # another resample count gives another interval
    assert (low, high) != pytest.approx(tuple(np.percentile(other, [2.5, 97.5])), rel=1e-12)


def test_a_50_percent_interval_spans_the_quartiles_of_the_bootstrap_means() -> None:
    _, low, high = bootstrap_ci(VALUES, level=0.5, n_boot=500, seed=3)
    means = _resampled_means(VALUES, 500, 3)
    assert (low, high) == pytest.approx(tuple(np.percentile(means, [25.0, 75.0])), rel=1e-12)


def test_two_values_give_their_mean_and_both_values_as_the_interval() -> None:
    # a resample of [1, 3] has mean 1, 2 or 3 with chances 1/4, 1/2, 1/4: about 500 of the 2000
    # means are 1 and 500 are 3, far more than the 2.5% cut from each tail
    assert bootstrap_ci([1.0, 3.0]) == (2.0, 1.0, 3.0)


def test_no_values_or_a_non_finite_one_is_refused() -> None:
    for bad in ([], [1.0, float("inf")]):
        with pytest.raises(ValueError, match="at least one finite value"):
            bootstrap_ci(bad)
