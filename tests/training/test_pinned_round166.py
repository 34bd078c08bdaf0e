"""Values that round 166's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.training.baselines.comparison import CompareConfig, summarise
from tests.training.test_pinned_baselines_comparison_gate import _cell


def test_an_algorithms_fraction_of_the_oracle_is_the_mean_over_its_seeds() -> None:
    # Three ppo seeds against lazy (oracle 100 tasks/h) end at 10, 20 and 90 tasks/h. Worked by
    # hand: their mean is (10 + 20 + 90) / 3 = 40, so the rate is 40 and the fraction 0.4; their
    # median would be 20 (0.2). With two seeds the mean and the median agree, so three are needed.
    config = CompareConfig(algos=("ppo",), humans=("lazy",), seeds=3)
    cells = [_cell("ppo", "lazy", s, [(0, 0.0), (1000, final)]) for s, final in enumerate((10.0, 20.0, 90.0))]
    rows = summarise(config, cells, {"lazy": {"oracle": 100.0, "planner": None, "hybrid": None}})
    (ppo,) = [r for r in rows if r["agent"] == "ppo"]
    assert ppo["rate"] == pytest.approx(40.0)
    assert ppo["fraction"] == pytest.approx(0.4)
