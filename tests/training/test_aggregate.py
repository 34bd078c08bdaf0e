"""rliable aggregates on synthetic score tables whose answers are worked out by hand."""

from __future__ import annotations

import pandas as pd
import pytest

from hg_marl.training.aggregate import aggregate, score_matrix


def _table(scores: dict[str, dict[str, list[float]]]) -> pd.DataFrame:
    """scores[robot][human] = one score per seed."""
    rows = [
        {"robot": r, "human": h, "scenario": "s", "seed": i, "score": v}
        for r, by_human in scores.items()
        for h, values in by_human.items()
        for i, v in enumerate(values)
    ]
    return pd.DataFrame(rows)


def test_iqm_and_mean_known_values() -> None:
    # 8 scores: the IQM drops the 2 lowest and the 2 highest: mean(0.2, 0.3, 0.4, 0.5) = 0.35;
    # the mean is the mean of per-human means: a (0..0.3) -> 0.15, b (0.4, 0.5, 0.6, 10) -> 2.875.
    a_scores, b_scores = [0.0, 0.1, 0.2, 0.3], [0.4, 0.5, 0.6, 10.0]
    frame = _table({"A": {"a": a_scores, "b": b_scores}, "B": {"a": [0.5] * 4, "b": [0.5] * 4}})
    agg = aggregate(frame, reps=200, poi_reps=50)
    a = agg["robots"]["A"]
    assert a["iqm"] == pytest.approx(0.35)
    assert a["mean"] == pytest.approx((0.15 + 2.875) / 2)
    assert a["iqm_ci"][0] <= a["iqm"] <= a["iqm_ci"][1]
    assert a["iqm_ci"][0] >= 0.0 and a["iqm_ci"][1] <= 10.0
    b = agg["robots"]["B"]  # a constant robot: every resample gives 0.5
    assert b["iqm"] == b["mean"] == 0.5 and b["iqm_ci"] == [0.5, 0.5] and b["mean_ci"] == [0.5, 0.5]
    assert a["runs"] == b["runs"] == 8


def test_probability_of_improvement_known_values() -> None:
    # One human: A = [1, 2], B = [1.5, 0.5]: A wins 3 of the 4 pairs (2>1.5, 2>0.5, 1>0.5).
    frame = _table({"A": {"h": [1.0, 2.0]}, "B": {"h": [1.5, 0.5]}, "C": {"h": [3.0, 4.0]}})
    agg = aggregate(frame, reps=100, poi_reps=100)
    assert agg["improvement"]["A>B"]["p"] == pytest.approx(0.75)
    assert agg["improvement"]["A>C"]["p"] == 0.0 and agg["improvement"]["A>C"]["ci"] == [0.0, 0.0]
    assert agg["improvement"]["B>C"]["p"] == 0.0
    assert set(agg["improvement"]) == {"A>B", "A>C", "B>C"}


def test_generalisation_gap_known_values() -> None:
    frame = _table({"A": {"tr1": [0.8, 0.8], "tr2": [0.8, 0.8], "te": [0.5, 0.5]}})
    agg = aggregate(frame, {"tr1": "train", "tr2": "train", "te": "test"}, reps=100, poi_reps=10)
    gap = agg["generalisation"]["A"]
    assert gap["train_iqm"] == pytest.approx(0.8) and gap["test_iqm"] == pytest.approx(0.5)
    assert gap["gap"] == pytest.approx(0.3) and gap["gap_ci"] == pytest.approx([0.3, 0.3])


def test_rows_without_score_are_left_out_and_matrix_is_seeds_by_humans() -> None:
    frame = _table({"A": {"h1": [0.1, 0.2, 0.3], "h2": [0.4, 0.5, 0.6]}})
    assert score_matrix(frame, "A").tolist() == [[0.1, 0.4], [0.2, 0.5], [0.3, 0.6]]
    frame.loc[frame["human"] == "h2", "score"] = float("nan")
    assert score_matrix(frame, "A").tolist() == [[0.1], [0.2], [0.3]]


def test_aggregate_is_reproducible() -> None:
    frame = _table({"A": {"h": [0.1, 0.9, 0.4, 0.7]}, "B": {"h": [0.2, 0.3, 0.8, 0.6]}})
    assert aggregate(frame, reps=300, poi_reps=50) == aggregate(frame, reps=300, poi_reps=50)


def test_one_seed_gives_no_interval_and_a_flag() -> None:
    # One seed per task: every stratified resample is the data itself, so an "interval"
    # would be the point (zero width); none is reported and the flag says why.
    frame = _table({"A": {"h": [0.2], "k": [0.4]}, "B": {"h": [0.5], "k": [0.1]}})
    agg = aggregate(frame)
    assert agg["bootstrap"]["seeds_per_task"] == 1 and "1 seed" in agg["bootstrap"]["flag"]
    assert agg["robots"]["A"]["iqm_ci"] is None and agg["robots"]["A"]["mean_ci"] is None
    assert agg["robots"]["A"]["mean"] == pytest.approx(0.3)
    # A wins on k, loses on h: (0 + 1) / 2
    assert agg["improvement"]["A>B"] == {"p": pytest.approx(0.5), "ci": None}


def test_few_seeds_are_flagged_and_enough_are_not() -> None:
    few = _table({"A": {"h": [0.1, 0.2, 0.3]}})
    enough = _table({"A": {"h": [0.1, 0.2, 0.3, 0.4, 0.5]}})
    assert "only 3 seeds" in aggregate(few, reps=50)["bootstrap"]["flag"]
    assert aggregate(enough, reps=50)["bootstrap"]["flag"] == ""


def test_vectorised_bootstrap_matches_rliable() -> None:
    """Same statistic, same resampling scheme: the intervals agree with rliable's to Monte Carlo error."""
    import numpy as np
    from rliable import library as rly
    from rliable import metrics

    from hg_marl.training.aggregate import improvement, iqm, mean, stratified_bootstrap

    rng = np.random.default_rng(3)
    x, y = rng.random((6, 3)), rng.random((6, 3)) * 0.8
    assert iqm(x) == pytest.approx(metrics.aggregate_iqm(x)) and mean(x) == pytest.approx(metrics.aggregate_mean(x))
    assert improvement(x, y) == pytest.approx(metrics.probability_of_improvement(x, y))
    ours = stratified_bootstrap([x, y], improvement, 4000)[:, 0]
    np.random.seed(0)
    _, theirs = rly.get_interval_estimates(
        {"p": [x, y]},
        lambda a, b: np.array([metrics.probability_of_improvement(a, b)]),
        reps=400,
        random_state=np.random.RandomState(0),
    )
    assert ours == pytest.approx(theirs["p"][:, 0], abs=0.05)
    ours_iqm = stratified_bootstrap([x], lambda a: iqm(a)[..., None], 4000)[:, 0]
    _, theirs_iqm = rly.get_interval_estimates(
        {"x": x}, lambda a: np.array([metrics.aggregate_iqm(a)]), reps=2000, random_state=np.random.RandomState(0)
    )
    assert ours_iqm == pytest.approx(theirs_iqm["x"][:, 0], abs=0.04)


def test_profile_counts_the_runs_above_each_threshold() -> None:
    import numpy as np

    from hg_marl.training.aggregate import profiles

    # A's 4 runs score 0.1, 0.4, 0.6, 0.9: above 0.0 all 4, above 0.5 two, above 0.9 none (strict)
    frame = _table({"A": {"h": [0.1, 0.4], "k": [0.6, 0.9]}})
    curves, bands = profiles(frame, np.array([0.0, 0.5, 0.9]), reps=100)
    assert curves["A"].tolist() == [1.0, 0.5, 0.0]
    assert bands["A"].shape == (2, 3) and (bands["A"][0] <= curves["A"]).all() and (curves["A"] <= bands["A"][1]).all()
