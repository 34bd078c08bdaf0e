"""Pinned against round 14 of fresh planted bugs: user-facing numbers worked by hand.

Each expected value is stated from its definition, independently of the code under test.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from hg_marl.training.baselines.comparison import CompareConfig
from hg_marl.training.baselines.comparison import summarise as compare_summary
from hg_marl.training.colours import colours
from hg_marl.training.paper import crossing, mean_amplitude
from hg_marl.training.play.explain import criterion_words
from hg_marl.training.play.stats import PlayStats
from hg_marl.training.play.stats import summarise as play_summary
from hg_marl.training.plots import _band
from hg_marl.training.regret import bootstrap_ci


def test_a_95_percent_interval_cuts_2_5_percent_from_each_tail() -> None:
    # 0..9, mean 4.5; the bootstrap means' 2.5th and 97.5th percentiles with seed 0:
    # a 90% interval (5th to 95th) would be narrower on both sides
    mean, low, high = bootstrap_ci(list(range(10)))
    means = np.arange(10.0)[np.random.default_rng(0).integers(0, 10, size=(2000, 10))].mean(axis=1)
    assert mean == 4.5
    assert (low, high) == tuple(np.percentile(means, [2.5, 97.5]))
    assert low < np.percentile(means, 5.0) and high > np.percentile(means, 95.0)


def test_a_game_without_offers_leaves_the_acceptance_out() -> None:
    offered = PlayStats("a", "planner", moves=4, tasks=1, handover_acceptance=1.0)
    never = PlayStats("b", "planner", moves=4, tasks=1, handover_acceptance=None)
    assert play_summary([offered, never])["handover_acceptance"] == 1.0  # not (1 + 0) / 2
    assert play_summary([never])["handover_acceptance"] is None


def test_a_finished_run_holds_its_last_amplitude() -> None:
    short, long = pd.DataFrame({"weight_amplitude": [0.0, 2.0]}), pd.DataFrame({"weight_amplitude": [0.0, 2.0, 4.0]})
    assert mean_amplitude([short, long]).tolist() == [0.0, 2.0, 3.0]  # (2 + 4) / 2 at the third decision
    flat, rising = pd.DataFrame({"weight_amplitude": [0.0, 0.0]}), pd.DataFrame({"weight_amplitude": [0.0, 0.0, 1.5]})
    curve = mean_amplitude([flat, rising])
    assert curve.tolist() == [0.0, 0.0, 0.75] and crossing(curve, 1.0) is None


def test_the_best_fraction_is_the_mean_of_each_seeds_best() -> None:
    config = CompareConfig(algos=("ppo",), humans=("cooperative",), seeds=2)
    cells = [
        {"algo": "ppo", "human": "cooperative", "curve": [(1000, 10.0), (2000, 20.0)]},
        {"algo": "ppo", "human": "cooperative", "curve": [(1000, 40.0), (2000, 30.0)]},
    ]
    rows = compare_summary(config, cells, {"cooperative": {"oracle": 100.0}})
    ppo = next(r for r in rows if r["agent"] == "ppo")
    assert ppo["best_fraction"] == pytest.approx(0.30)  # bests 20 and 40, mean 30, of 100
    assert ppo["fraction"] == pytest.approx(0.25)  # finals 20 and 30


def test_the_adaptation_band_is_the_95_percent_interval() -> None:
    curves = np.array([[0.0], [1.0], [2.0], [3.0], [10.0]])
    mean, low, high = _band(curves)
    boot = curves[np.random.default_rng(0).integers(0, 5, size=(1000, 5))].mean(axis=1)
    assert mean.tolist() == [3.2]
    np.testing.assert_allclose([low[0], high[0]], np.percentile(boot, [2.5, 97.5], axis=0)[:, 0])
    assert low[0] < np.percentile(boot, 5.0) and high[0] > np.percentile(boot, 95.0)


@pytest.mark.parametrize(("visits", "words"), [(0.0, "0 times"), (1.0, "1 time"), (2.0, "2 times")])
def test_the_habits_count_reads_in_english(visits: float, words: str) -> None:
    assert f"learnt from this situation {words}." in " ".join(criterion_words({"visits": visits}))


def test_a_label_seen_twice_keeps_its_first_colour() -> None:
    once = colours(["a", "b", "c"])
    assert colours(["a", "b", "a", "c"]) == once
    assert once == {"a": "#1f77b4", "b": "#ff7f0e", "c": "#2ca02c"}  # matplotlib's first three


def test_narrowing_the_humans_narrows_the_test_partners(tmp_path: object) -> None:
    from hg_marl.training.study import Actor, Study

    study = Study(
        name="s",
        path=tmp_path,
        robots=(Actor("planner", label="planner"),),
        humans=tuple(Actor(h, label=h) for h in ("cooperative", "lazy", "no_handover")),
        scenarios=("paper2015",),
        seeds=(0,),
        duration=100.0,
        train=("cooperative",),
        test=("lazy", "no_handover"),
    )
    narrowed = study.narrowed(humans=["cooperative", "lazy"])
    assert narrowed.test == ("lazy",) and narrowed.train == ("cooperative",)


def test_the_best_robot_reference_is_the_best_mean_rate() -> None:
    # fo_bursts has no exact best response: the reference is the robot with the best mean rate.
    # planner 10 and 20 tasks an hour, habit 4 and 24: means 15 and 14, so the planner (not the
    # habit's best seed, 24); the planner's seed 0 scores 10 / 15.
    from hg_marl.training.evaluate import Cell, score_table
    from hg_marl.training.study import Actor, Study

    robots = (Actor("planner", label="planner"), Actor("habit", label="habit"))
    human = Actor("fo_bursts", label="fo_bursts")
    study = Study(
        "s", path=None, robots=robots, humans=(human,), scenarios=("paper2015",), seeds=(0, 1), duration=3600.0
    )
    rates = {("planner", 0): 10.0, ("planner", 1): 20.0, ("habit", 0): 4.0, ("habit", 1): 24.0}
    plan = [Cell(r, human, "paper2015", s, None) for r in robots for s in (0, 1)]
    runs = [
        SimpleNamespace(tasks=int(rates[(c.robot.label, c.seed)]), rate=rates[(c.robot.label, c.seed)], key=f"k{i}")
        for i, c in enumerate(plan)
    ]
    frame = score_table(study, plan, runs, store=None)
    assert set(frame["oracle_rate"]) == {15.0} and set(frame["reference"]) == {"best robot (planner)"}
    planner0 = frame[(frame["robot"] == "planner") & (frame["seed"] == 0)]
    assert planner0["score"].iloc[0] == pytest.approx(10.0 / 15.0)
