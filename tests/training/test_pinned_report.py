"""What report.md says, on hand-made aggregates: which pairs are clear, the tables, the files.

A pair is *clear* when its 95% interval of P(A > B) excludes one half: the whole
interval above 0.5 or the whole interval below it. An interval that touches 0.5 does
not exclude it.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest

from hg_marl.training.report import (
    br_prox_section,
    crossplay_table,
    intervals_figure,
    markdown,
    mean_table,
    profiles_figure,
    robot_table,
    write_outputs,
)
from hg_marl.training.study import Actor, Study


@pytest.fixture(autouse=True)
def _close_figures() -> Any:
    yield
    plt.close("all")


def _study(seeds: int = 2) -> Study:
    return Study(
        name="hand",
        path=Path("hand.toml"),
        robots=(Actor("A", label="A"), Actor("B", label="B")),
        humans=(Actor("h", label="h"), Actor("k", label="k")),
        scenarios=("paper2015",),
        seeds=tuple(range(seeds)),
        duration=60.0,
    )


def _frame(scores: dict[str, dict[str, list[float]]]) -> pd.DataFrame:
    rows = [
        {
            "robot": r,
            "human": h,
            "scenario": "paper2015",
            "seed": i,
            "score": v,
            "oracle_rate": 100.0 if h == "h" else float("nan"),
            "reference": "oracle" if h == "h" else "best robot",
        }
        for r, by_human in scores.items()
        for h, values in by_human.items()
        for i, v in enumerate(values)
    ]
    return pd.DataFrame(rows)


def _agg(pairs: Mapping[str, list[float] | None], flag: str = "", seeds: int = 5) -> dict[str, Any]:
    return {
        "robots": {"A": {"iqm": 0.5, "iqm_ci": [0.4, 0.6], "mean": 0.55, "mean_ci": None, "runs": 4}},
        "improvement": {k: {"p": 0.5 if ci is None else sum(ci) / 2, "ci": ci} for k, ci in pairs.items()},
        "bootstrap": {"reps": 10, "poi_reps": 20, "seed": 0, "ci": 0.95, "seeds_per_task": seeds, "flag": flag},
        "br_prox": [],
    }


PAIRS = {
    "A>B": [0.55, 0.9],  # above 0.5: clear
    "A>C": [0.1, 0.45],  # below 0.5: clear
    "B>C": [0.4, 0.6],  # straddles 0.5
    "C>D": [0.5, 0.7],  # touches 0.5 from above: does not exclude it
    "D>E": [0.3, 0.5],  # touches 0.5 from below
}


def _section(text: str, title: str) -> list[str]:
    lines = text.splitlines()
    start = lines.index(title)
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    return lines[start:end]


def test_clear_pairs_are_those_whose_interval_excludes_one_half() -> None:
    text = markdown(_study(), _frame({"A": {"h": [0.5, 0.6]}}), _agg(PAIRS), {"ran": 2, "reused": 0})
    section = _section(text, "## Probability of improvement")
    assert "2 of 5 pairs have a 95% CI that excludes 0.5 (all pairs in aggregate.json):" in section
    rows = [line for line in section if line.startswith("| A>") or line.startswith("| B>") or line.startswith("| C>")]
    assert rows == ["| A>B | 0.73 | [0.55, 0.90] |", "| A>C | 0.28 | [0.10, 0.45] |"]


def test_a_flag_is_repeated_beside_the_clear_pairs() -> None:
    text = markdown(
        _study(), _frame({"A": {"h": [0.5, 0.6]}}), _agg(PAIRS, flag="only 2 seeds"), {"ran": 2, "reused": 0}
    )
    assert "2 of 5 pairs have a 95% CI that excludes 0.5 (all pairs in aggregate.json) (only 2 seeds):" in text
    assert "**Caution: only 2 seeds.**" in text


def test_without_intervals_no_pair_is_called_clear() -> None:
    agg = _agg({"A>B": None, "A>C": None, "B>C": None}, seeds=1)
    text = markdown(_study(1), _frame({"A": {"h": [0.5]}}), agg, {"ran": 1, "reused": 0})
    section = _section(text, "## Probability of improvement")
    assert section[2].startswith("No interval with 1 seed per task, so no pair can be called clearly better;")
    assert "the 3 point estimates are in aggregate.json." in section[2]
    assert not any(line.startswith("| pair") for line in section)


def test_header_counts_runs_and_the_store() -> None:
    frame = _frame({"A": {"h": [0.5, 0.6], "k": [0.1, 0.2]}, "B": {"h": [0.3, 0.3], "k": [0.2, 0.2]}})
    text = markdown(_study(), frame, _agg({}), {"ran": 5, "reused": 3})
    assert "8 runs: 2 robots x 2 humans x 1 scenario(s) x 2 seeds, 60 simulated s each (5 run now, 3 reused" in text
    assert "10 replications (20 for the probability of improvement" in text


def test_mean_table_and_crossplay_table_by_hand() -> None:
    frame = _frame({"B": {"k": [0.2, 0.4], "h": [1.0, 0.5]}, "A": {"k": [0.0, 0.1], "h": [0.3, 0.3]}})
    table = mean_table(frame)
    assert list(table.index) == ["B", "A"] and list(table.columns) == ["k", "h"]  # study order, not sorted
    np.testing.assert_allclose(table.to_numpy(), [[0.3, 0.75], [0.05, 0.3]])
    lines = crossplay_table(frame).splitlines()
    assert lines[:4] == ["| robot | k | h |", "|---|---:|---:|", "| B | 0.30 | 0.75 |", "| A | 0.05 | 0.30 |"]
    assert "| k | paper2015 | - | best robot |" in lines and "| h | paper2015 | 100.00 | oracle |" in lines


def test_robot_table_prints_missing_values_as_dashes() -> None:
    agg = {"robots": {"A": {"iqm": 0.5, "iqm_ci": [0.4, 0.6], "mean": None, "mean_ci": None, "runs": 0}}}
    assert robot_table(agg).splitlines()[2] == "| A | 0.50 | [0.40, 0.60] | - | - | 0 |"


def test_br_prox_section_lists_every_row_with_its_headroom() -> None:
    rows = [
        {"robot": "A", "scenario": "paper2015", "split": "test", "iqm": 0.8, "ci": [0.7, 0.9], "runs": 4},
        {"robot": "B", "scenario": "other", "split": "all", "iqm": 1.0, "ci": None, "runs": 2},
    ]
    lines = br_prox_section({"br_prox": rows}, {"paper2015": 0.25})
    assert lines[0].startswith("## BR-Prox")
    assert lines[-3:] == [
        "| paper2015 | 0.25 | test | A | 0.80 | [0.70, 0.90] | 4 |",
        "| other | - | all | B | 1.00 | - | 2 |",
        "",
    ]
    assert br_prox_section({"br_prox": []}, {}) == [] and br_prox_section({}, {}) == []


def test_intervals_figure_height_grows_with_the_robots() -> None:
    agg: dict[str, Any] = {
        "robots": {r: {"iqm": 0.5, "iqm_ci": [0.4, 0.6], "mean": 0.5, "mean_ci": [0.4, 0.6]} for r in "ABC"},
        "bootstrap": {"flag": ""},
    }
    agg["robots"]["D"] = {"iqm": None, "iqm_ci": None, "mean": None, "mean_ci": None}  # no score: no row
    fig = intervals_figure(agg)
    assert tuple(fig.get_size_inches()) == pytest.approx((8.0, 0.45 * 3 + 1.4))
    assert [t.get_text() for t in fig.axes[0].get_yticklabels()] == ["A", "B", "C"]


@pytest.mark.parametrize(("top", "end"), [(2.0, 2.1), (0.5, 1.05)])
def test_profiles_span_every_score_and_five_percent_more(top: float, end: float) -> None:
    frame = _frame({"A": {"h": [0.1, top]}, "B": {"h": [0.2, 0.3]}})
    fig = profiles_figure(frame)
    grid = fig.axes[0].get_lines()[0].get_xdata()
    assert (len(grid), grid[0], grid[-1]) == (61, 0.0, pytest.approx(end))
    zoom = fig.axes[1].get_lines()[0].get_xdata()
    assert zoom[-1] == pytest.approx(max(top, 0.05) * 1.01) and len(zoom) == 61


def test_write_outputs_writes_every_file(tmp_path: Path) -> None:
    frame = _frame({"A": {"h": [0.5, 0.6], "k": [0.1, 0.2]}, "B": {"h": [0.3, 0.3], "k": [0.2, 0.2]}})
    agg = write_outputs(_study(), frame, tmp_path, {"ran": 8, "reused": 0}, {"paper2015": 0.5})
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["aggregate.json", "crossplay.png", "intervals.png", "profiles.png", "report.md", "scores.csv"]
    saved = json.loads((tmp_path / "aggregate.json").read_text())
    assert saved["headroom"] == {"paper2015": 0.5} and "seconds" not in saved and agg["seconds"] >= 0.0
    assert saved["robots"]["B"]["iqm"] == pytest.approx(0.25)
    back = pd.read_csv(tmp_path / "scores.csv")
    assert np.allclose(back["score"], frame["score"]) and list(back.columns) == list(frame.columns)
    assert (tmp_path / "report.md").read_text().startswith("# Study hand\n")


def test_write_outputs_without_any_score_draws_no_profile(tmp_path: Path) -> None:
    frame = _frame({"A": {"h": [0.5, 0.6]}})
    frame["score"] = float("nan")
    write_outputs(_study(), frame, tmp_path, {"ran": 2, "reused": 0})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["aggregate.json", "crossplay.png", "report.md", "scores.csv"]


def test_the_reference_table_has_a_row_per_human_and_scenario() -> None:
    """One human on two scenarios has two references (its exact rate differs per table): two rows."""
    frame = pd.DataFrame(
        {
            "robot": ["A", "A", "A", "A"],
            "human": ["k", "k", "h", "h"],
            "scenario": ["paper2015", "scenarios/big.toml", "paper2015", "scenarios/big.toml"],
            "score": [0.5, 0.6, 0.7, 0.8],
            "oracle_rate": [100.0, 40.0, 90.0, np.nan],
            "reference": ["oracle", "oracle", "oracle", "best robot"],
        }
    )
    lines = crossplay_table(frame).splitlines()
    refs = lines[lines.index("| human | scenario | reference rate (tasks/h) | reference |") + 2 :]
    assert refs == [
        "| k | paper2015 | 100.00 | oracle |",
        "| k | big.toml | 40.00 | oracle |",
        "| h | paper2015 | 90.00 | oracle |",
        "| h | big.toml | - | best robot |",
    ]
