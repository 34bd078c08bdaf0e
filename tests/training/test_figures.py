"""The figures read from what they draw: legend entries visible, no overlapping text, n/a as n/a.

Synthetic inputs whose expected drawing is worked out by hand; each figure is built by
its ``*_figure`` function and inspected through matplotlib's artists and renderer.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.colors as mcolors
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest

from hg_marl.training import paper, plots
from hg_marl.training.aggregate import aggregate
from hg_marl.training.colours import colours
from hg_marl.training.report import crossplay_figure, intervals_figure, profiles_figure
from tests.figure_checks import hidden_lines, legend_inside_data, legend_labels, overlapping_texts


@pytest.fixture(autouse=True)
def _close_figures() -> object:
    yield
    plt.close("all")


def _log(rewards_at: list[float], amplitude: list[float], end: float = 100.0) -> pd.DataFrame:
    """A per-decision log: one decision per amplitude value, evenly spread over ``end`` s."""
    n = len(amplitude)
    times = np.linspace(1.0, end, n)
    reward = np.zeros(n)
    for t in rewards_at:
        reward[int(np.searchsorted(times, t))] = 1.0
    return pd.DataFrame(
        {"time": times, "reward": reward, "weight_amplitude": amplitude, "expert": "planner", "failed": False}
    )


def _scores(table: dict[str, dict[str, list[float]]]) -> pd.DataFrame:
    rows = [
        {"robot": r, "human": h, "scenario": "s", "seed": i, "score": v}
        for r, by_human in table.items()
        for h, values in by_human.items()
        for i, v in enumerate(values)
    ]
    return pd.DataFrame(rows)


def test_fig5_reports_where_the_drawn_mean_curve_crosses() -> None:
    # Seed a crosses 1.0 at decision 4, seed b never does. The mean of the crossing seeds
    # would say 4; the drawn mean curve (b held at 0.1) is 0.65 from decision 4 on: it
    # never crosses. Second condition: c = [0, 3, 3], d = [0, .5, .5, .5] -> mean curve
    # [0, 1.75, 1.75, 1.75] (c held at 3): crosses at decision 1.
    logs = {
        "habit": [_log([], [0, 0, 0, 0, 1.2]), _log([], [0, 0.1, 0.1, 0.1, 0.1, 0.1])],
        "random": [_log([], [0, 3, 3]), _log([], [0, 0.5, 0.5, 0.5])],
    }
    assert paper.crossing(paper.mean_amplitude(logs["habit"])) is None
    assert paper.crossing(paper.mean_amplitude(logs["random"])) == 1
    rows = {k: paper.summarise_condition(paper.ConditionLogs(k, v)) for k, v in logs.items()}
    assert rows["habit"]["amplitude_rise_decision"] is None and rows["random"]["amplitude_rise_decision"] == 1
    fig = plots.weight_amplitude_figure(logs)
    titles = [ax.get_title() for ax in fig.axes if ax.get_visible()]
    assert titles[0].startswith("habit\nnever reaches 1") and titles[1].startswith("random\ncrosses 1 at decision 1 ")
    habit = next(line for line in fig.axes[0].get_lines() if line.get_label() == "habit")
    assert np.nanmax(habit.get_ydata()) == pytest.approx(0.65)
    assert overlapping_texts(fig) == []


def test_fig5_puts_nearly_equal_curves_in_panels_of_their_own() -> None:
    # Two conditions a hair apart (0.1%): on one axes one would hide the other.
    ramp = list(np.linspace(0.1, 5.0, 40))
    logs = {"entropy": [_log([], ramp)], "vpi": [_log([], [v * 1.001 for v in ramp])]}
    fig = plots.weight_amplitude_figure(logs)
    for ax, name in zip(fig.axes, logs, strict=True):
        mine = [line for line in ax.get_lines() if line.get_label() == name]
        assert len(mine) == 1 and mine[0] is ax.get_lines()[-2]  # drawn over the grey context, under the threshold
        assert name not in hidden_lines(ax)


def test_fig3_shows_every_condition_it_names() -> None:
    # planner and entropy solve the same tasks at the same times: one curve, both names.
    # vpi solves one task more, 50 s in: its cumulative curve runs one task above the
    # planner's from then on; on the left that is a one-task gap, on the right a step.
    base = [10.0, 30.0, 70.0]
    logs = {
        "planner": [_log(base, [0.0] * 50)],
        "entropy": [_log(base, [0.0] * 50)],
        "vpi": [_log([*base, 50.0], [0.0] * 50)],
        "habit": [_log([90.0], [0.0] * 50)],
    }
    fig = plots.cumulative_reward_figure(logs, 100.0)
    labels = legend_labels(fig)
    assert labels == ["planner = entropy (coincide)", "vpi", "habit"]
    left, right = fig.axes
    assert hidden_lines(left) == [] and hidden_lines(right) == []
    # right: vpi, habit (3 planner tasks by 70 s against none, one of its own at 90 s: -3 then -2),
    # then the planner (the zero line) on top
    vpi, habit, planner = right.get_lines()
    assert vpi.get_ydata().max() == 1.0 and not planner.get_ydata().any()
    assert habit.get_ydata().min() == -3.0 and habit.get_ydata()[-1] == -2.0
    assert right.get_yscale() == "symlog"
    assert legend_inside_data(fig) == [] and overlapping_texts(fig) == []


def test_fig4_long_condition_names_do_not_overlap() -> None:
    names = ["planner", "habit", "random", "entropy", "entropy_and_cost", "vpi", "learning_state"]
    logs = {n: [_log([], [0.0] * (10 + i)), _log([], [0.0] * (12 + i))] for i, n in enumerate(names)}
    fig = plots.actions_per_run_figure(logs)
    assert overlapping_texts(fig) == []
    # one colour per condition, the same as the shared map gives it
    dots = [c for c in fig.axes[0].collections if c.get_offsets().shape[0] == 2]
    assert [mcolors.to_hex(d.get_facecolor()[0]) for d in dots] == list(colours(names).values())


def test_crossplay_draws_na_as_na_not_as_zero() -> None:
    frame = _scores({"A": {"h": [0.0, 0.0], "k": [0.9, 0.8]}, "B": {"h": [0.5, 0.5], "k": [0.7, 0.7]}})
    frame.loc[frame["human"] == "k", "score"] = np.nan  # no reference for k: n/a
    fig = crossplay_figure(frame, "t")
    ax = fig.axes[0]
    image = ax.get_images()[0]
    rgba = image.to_rgba(image.get_array())
    # A with h scores 0: viridis' bottom colour; every k cell: the grey n/a colour.
    assert mcolors.to_hex(rgba[0, 0]) == "#440154"
    assert mcolors.to_hex(rgba[0, 1]) == mcolors.to_hex(rgba[1, 1]) == "#d9d9d9"
    texts = {(round(t.get_position()[0]), round(t.get_position()[1])): t.get_text() for t in ax.texts}
    assert texts[(1, 0)] == texts[(1, 1)] == "n/a" and texts[(0, 0)] == "0.00"
    assert overlapping_texts(fig) == []


def test_profiles_legend_is_outside_and_every_robot_is_seen() -> None:
    # A and C score alike everywhere: one curve named "A = C (identical)"; B differs by a
    # little near the top score, D scores low.
    frame = _scores(
        {
            "A": {"h": [0.95, 0.97, 0.99]},
            "B": {"h": [0.94, 0.96, 0.98]},
            "C": {"h": [0.95, 0.97, 0.99]},
            "D": {"h": [0.2, 0.3, 0.25]},
        }
    )
    fig = profiles_figure(frame)
    labels = legend_labels(fig)
    assert labels == ["A\n= C (identical)", "B", "D"]
    assert legend_inside_data(fig) == []
    zoom = fig.axes[1]
    assert hidden_lines(zoom, pixels=1.0) == []
    look = {str(line.get_label()): (line.get_color(), line.get_linestyle()) for line in zoom.get_lines()}
    assert len(set(look.values())) == 3


def test_one_colour_per_robot_across_a_reports_figures() -> None:
    frame = _scores({"A": {"h": [0.2, 0.4]}, "B": {"h": [0.5, 0.7]}, "C": {"h": [0.9, 0.8]}})
    agg = aggregate(frame, reps=50, poi_reps=10)
    want = colours(["A", "B", "C"])
    lines = profiles_figure(frame).axes[1].get_lines()
    prof = {str(line.get_label()): mcolors.to_hex(line.get_color()) for line in lines}
    assert prof == want
    fig = intervals_figure(agg)
    bars = {}
    for ax in fig.axes:
        for patch in ax.patches:
            bars.setdefault(mcolors.to_hex(patch.get_facecolor()), 0)
    assert set(bars) == set(want.values())


def test_regret_bars_scale_fits_the_compared_robots_and_cut_bars_say_their_value() -> None:
    def ci(mean: float, half: float) -> dict[str, dict[str, float]]:
        return {"tasks_lost": {"mean": mean, "low": mean - half, "high": mean + half}}

    results = {
        "a": {
            "humans": ["cooperative", "lazy"],
            "robots": {"planner": ci(1.0, 0.5), "hybrid": ci(2.0, 0.5), "habit": ci(27.0, 1.0), "vpi": ci(0.5, 0.5)},
        }
    }
    fig = plots.regret_bars_figure(results)
    ax = fig.axes[0]
    # bar tops 1.5, 2.5, 28, 1.0: median 2.0, so only the habit (28 > 4 x 2) is cut; the
    # axis ends 15% above the tallest kept top, 2.5 -> 2.875, and the 1-task difference
    # between planner and hybrid spans 1 / 2.875 = 35% of it.
    assert ax.get_ylim()[1] == pytest.approx(2.875)
    assert [t.get_text() for t in ax.texts] == ["27.0\n[26.0, 28.0]\n(cut)"]
    assert overlapping_texts(fig) == []
    heights = [round(p.get_height(), 3) for p in ax.patches]
    assert heights == [1.0, 2.0, 2.875, 0.5]


@pytest.mark.parametrize("robots", [3, 5])
def test_adaptation_title_clears_the_panel_titles(robots: int) -> None:
    grid = np.arange(300.0, 1501.0, 10.0)
    curves = {f"robot_{k}": np.full((2, len(grid)), 100.0 + k) for k in range(robots)}
    fig = plots.adaptation_figure(grid, curves, [(0.0, 118.0), (600.0, 112.0)], "Human: a -> b; a long title")
    assert overlapping_texts(fig) == []
    for ax in fig.axes:
        if ax.get_visible():  # the robot's curve shows (the switch's axvline lives in axes coordinates)
            assert "robot (mean)" not in hidden_lines(ax) and "line 0" not in hidden_lines(ax)
    plt.close(fig)
