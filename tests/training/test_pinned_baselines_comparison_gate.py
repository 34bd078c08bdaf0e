"""The comparison's settings, rows and text, pinned for the mutation gate.

Expected values are worked by hand: fractions are rates over the oracle's rate (80 over
100 is 0.8), the table's columns have the widths its header shows (agent 13, human 16,
then right-aligned 9, 9, 7, 14, 7, 9, 9), an interval prints as ``[low, high]`` to two
places, and the defaults are the documented ones (the paper's 20 minutes, evaluation
seeds 100 and 101, 100-cycle episodes). No training and no timing here.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path
from typing import Any

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.baselines.comparison import (
    BASELINE_ROBOTS,
    CompareConfig,
    aggregates,
    format_aggregate,
    format_table,
    summarise,
)

HEADER = "agent        human             tasks/h   oracle   frac        95% CI   best   to 50%   to 90%"


def _cell(algo: str, human: str, seed: int, curve: list[tuple[int, float]]) -> dict[str, Any]:
    return {"algo": algo, "human": human, "seed": seed, "curve": [list(p) for p in curve]}


def test_the_defaults_are_the_documented_ones() -> None:
    config = CompareConfig()
    assert config.algos == ("ppo", "maskable_ppo", "dqn", "a2c")
    assert config.humans == ("cooperative", "lazy", "no_handover")
    assert (config.scenario, config.steps, config.seeds, config.eval_every) == ("paper2015", 20_000, 3, 2_000)
    assert config.eval_seeds == (100, 101)
    assert (config.duration, config.deterministic, config.max_cycles) == (1200.0, False, 100)
    assert config.out == Path("runs/compare")
    assert BASELINE_ROBOTS == {"planner": {}, "hybrid": {"criterion": "entropy_and_cost"}}


def test_a_configuration_is_frozen() -> None:
    """One configuration names the cells already on disk: it cannot change under them."""
    with pytest.raises(dataclasses.FrozenInstanceError):
        CompareConfig().steps = 5


def test_the_smallest_settings_are_accepted() -> None:
    """One step, one seed, an evaluation every step, seed 0, one cycle: all at their lower bounds."""
    config = CompareConfig(
        algos=("a2c",), humans=("lazy",), steps=1, seeds=1, eval_every=1, eval_seeds=(0,), duration=0.5, max_cycles=1
    )
    assert (config.steps, config.seeds, config.eval_every, config.eval_seeds, config.max_cycles) == (1, 1, 1, (0,), 1)


@pytest.mark.parametrize(
    ("changes", "match"),
    [
        ({"algos": ()}, r"algos \(--algos\) and humans \(--humans\): expected at least one name each"),
        ({"humans": ()}, r"algos \(--algos\) and humans \(--humans\)"),
        ({"steps": 0}, r"steps \(--steps\): expected an integer >= 1"),
        ({"seeds": 0}, r"seeds \(--seeds\): expected an integer >= 1"),
        ({"eval_every": 0}, r"eval_every \(--eval-every\): expected an integer >= 1"),
        ({"eval_seeds": ()}, r"eval_seeds \(--eval-seeds\): expected at least one evaluation seed"),
        ({"eval_seeds": (3, -1)}, r"eval_seeds \(--eval-seeds\): expected an integer >= 0"),
        ({"duration": 0.0}, r"duration \(--duration\)"),
        ({"deterministic": "yes"}, r"deterministic \(--deterministic\): expected true or false"),
        ({"max_cycles": 0}, r"max_cycles: expected an integer >= 1"),
    ],
)
def test_each_setting_out_of_range_is_refused_by_its_option(changes: dict[str, Any], match: str) -> None:
    with pytest.raises(ConfigError, match=match):
        CompareConfig(**changes)


def test_rows_list_the_baselines_then_the_algorithms_per_human_worked_by_hand() -> None:
    """Two ppo seeds on ``lazy`` against an oracle of 100 (dqn has no cell, so no row).

    Seed 0's curve is 10, 60, 40 (final 40, best 60, reaches 50 at step 10); seed 1's is
    20, 95, 80 (final 80, best 95, 50 at step 10, 90 at step 10). Mean final 60: fraction
    0.6; mean best 77.5: 0.775; to 50%: the median of 10 and 10; seed 0 never reaches 90.
    """
    config = CompareConfig(algos=("ppo", "dqn"), humans=("lazy",), seeds=2, eval_seeds=(7, 8, 9))
    cells = [
        _cell("ppo", "lazy", 0, [(0, 10.0), (10, 60.0), (20, 40.0)]),
        _cell("ppo", "lazy", 1, [(0, 20.0), (10, 95.0), (20, 80.0)]),
        _cell("ppo", "other", 0, [(0, 100.0)]),
    ]
    rows = summarise(config, cells, {"lazy": {"oracle": 100.0, "planner": 90.0, "hybrid": None}})
    assert [r["agent"] for r in rows] == ["planner", "hybrid", "ppo"]
    planner, hybrid, ppo = rows
    assert planner == {
        "agent": "planner",
        "human": "lazy",
        "rate": 90.0,
        "oracle": 100.0,
        "fraction": 0.9,
        "best_fraction": None,
        "fraction_ci": None,
        "steps_to_50": None,
        "steps_to_90": None,
        "seeds": 3,
    }
    assert hybrid["rate"] is None and hybrid["fraction"] is None
    assert ppo["rate"] == pytest.approx(60.0) and ppo["fraction"] == pytest.approx(0.6)
    assert ppo["best_fraction"] == pytest.approx(0.775)
    assert ppo["steps_to_50"] == 10.0 and ppo["steps_to_90"] is None
    assert ppo["seeds"] == 2
    low, high = ppo["fraction_ci"]
    assert 0.4 <= low < 0.6 < high <= 0.8  # a bootstrap mean of the seeds' 0.4 and 0.8 lies between them


def test_the_steps_to_a_level_are_the_median_over_seeds() -> None:
    """Three seeds reach 50 (of an oracle of 100) at steps 10, 30 and 20: the median is 20, not the mean."""
    config = CompareConfig(algos=("ppo",), humans=("lazy",), seeds=3)
    cells = [
        _cell("ppo", "lazy", 0, [(0, 0.0), (10, 55.0)]),
        _cell("ppo", "lazy", 1, [(0, 0.0), (10, 10.0), (30, 91.0)]),
        _cell("ppo", "lazy", 2, [(0, 0.0), (20, 50.0), (90, 49.0)]),
    ]
    (ppo,) = [r for r in summarise(config, cells, {"lazy": {"oracle": 100.0}}) if r["agent"] == "ppo"]
    assert ppo["steps_to_50"] == 20.0
    assert ppo["steps_to_90"] is None


def test_without_an_oracle_rate_nothing_is_a_fraction() -> None:
    """An oracle of None or 0: no fraction, no interval, no steps to a level (not a division by 0)."""
    config = CompareConfig(algos=("ppo",), humans=("a", "b"), seeds=2)
    cells = [_cell("ppo", h, s, [(0, 1.0), (5, 2.0)]) for h in ("a", "b") for s in range(2)]
    rows = summarise(config, cells, {"a": {"oracle": None, "planner": 5.0}, "b": {"oracle": 0.0}})
    for row in rows:
        assert row["fraction"] is None and row["fraction_ci"] is None
        assert row["steps_to_50"] is None and row["steps_to_90"] is None
    ppo_rows = [r for r in rows if r["agent"] == "ppo"]
    assert [r["rate"] for r in ppo_rows] == [2.0, 2.0] and all(r["best_fraction"] is None for r in ppo_rows)


def test_the_aggregate_needs_two_seeds_and_an_oracle() -> None:
    """Two seeds on one human are enough; one seed, or no oracle rate, give nothing."""
    cells = [_cell("ppo", "lazy", s, [(0, 0.0), (5, rate)]) for s, rate in ((0, 30.0), (1, 50.0))]
    result = aggregates(CompareConfig(algos=("ppo",), humans=("lazy",), seeds=2), cells, {"lazy": 100.0})
    assert result["robots"]["ppo"]["mean"] == pytest.approx(0.4)  # (0.3 + 0.5) / 2: finals over the oracle
    assert result["robots"]["ppo"]["runs"] == 2
    assert aggregates(CompareConfig(seeds=1), cells, {"lazy": 100.0}) == {}
    assert aggregates(CompareConfig(seeds=2), cells, {"lazy": None}) == {}
    assert aggregates(CompareConfig(seeds=2), cells, {}) == {}


def test_the_table_is_fixed_width_with_dashes_for_what_is_missing() -> None:
    """Each column at its header's width; None and NaN print as ``-``; the interval low before high."""
    rows = [
        {
            "agent": "ppo",
            "human": "lazy",
            "rate": 80.0,
            "oracle": 100.0,
            "fraction": 0.8,
            "fraction_ci": [0.7, 0.9],
            "best_fraction": 0.85,
            "steps_to_50": 1500.0,
            "steps_to_90": None,
        },
        {
            "agent": "planner",
            "human": "no_handover",
            "rate": math.nan,
            "oracle": None,
            "fraction": None,
            "best_fraction": None,
            "steps_to_50": None,
            "steps_to_90": 7,
        },
    ]
    lines = format_table(rows).split("\n")
    assert lines[0] == HEADER
    assert lines[1] == "-" * len(HEADER)
    assert lines[2] == "ppo          lazy                 80.0    100.0   0.80  [0.70, 0.90]   0.85     1500        -"
    assert lines[3] == "planner      no_handover             -        -      -             -      -        -        7"
    assert len(lines) == 4


def test_the_aggregate_text_names_each_robot_and_each_pair() -> None:
    """IQM and mean with their intervals (``-`` without one); a robot without an IQM is left out."""
    result = {
        "robots": {
            "ppo": {"iqm": 0.5, "iqm_ci": [0.4, 0.6], "mean": 0.55, "mean_ci": None},
            "dqn": {"iqm": None, "iqm_ci": None, "mean": None, "mean_ci": None},
        },
        "improvement": {"ppo>dqn": {"p": 0.75, "ci": [0.5, 1.0]}},
    }
    assert format_aggregate(result).split("\n") == [
        "ppo           IQM 0.50 [0.40, 0.60]  mean 0.55 -",
        "P(ppo>dqn) = 0.75 [0.50, 1.00]",
    ]
    assert format_aggregate({}) == ""
