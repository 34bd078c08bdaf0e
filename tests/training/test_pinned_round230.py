"""Values that round 230's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.training.baselines.comparison import CompareConfig, summarise
from hg_marl.training.play.stats import PlayStats
from hg_marl.training.play.stats import summarise as summarise_play
from tests.training.test_pinned_baselines_comparison_gate import _cell


def test_a_summary_with_moves_but_no_solved_task_has_no_moves_per_task() -> None:
    # One game of 7 moves that solved no task: moves per task is a ratio over no task, None (as
    # PlayStats.moves_per_task says per game), not the 7 moves; with 3 tasks in 12 moves it is 4.
    stuck = PlayStats("p", "planner", 7, 0, None, {"wait": 1.0})
    assert stuck.moves_per_task is None
    assert summarise_play([stuck])["moves_per_task"] is None
    solved = PlayStats("p", "planner", 12, 3, None, {"wait": 1.0})
    assert summarise_play([solved])["moves_per_task"] == pytest.approx(4.0)


def test_an_algorithms_best_fraction_is_the_mean_of_its_seeds_bests() -> None:
    # Three ppo seeds against lazy (oracle 100 tasks/h) peak at 10, 20 and 90 tasks/h (then fall
    # to half). Worked by hand: the mean of the peaks is (10 + 20 + 90) / 3 = 40, a best fraction
    # of 0.4; their median would be 20 (0.2). The finals 5, 10, 45 give the fraction 0.2.
    config = CompareConfig(algos=("ppo",), humans=("lazy",), seeds=3)
    cells = [
        _cell("ppo", "lazy", s, [(0, 0.0), (1000, best), (2000, best / 2)]) for s, best in enumerate((10.0, 20.0, 90.0))
    ]
    rows = summarise(config, cells, {"lazy": {"oracle": 100.0, "planner": None, "hybrid": None}})
    (ppo,) = [r for r in rows if r["agent"] == "ppo"]
    assert ppo["best_fraction"] == pytest.approx(0.4)
    assert ppo["fraction"] == pytest.approx(0.2)
