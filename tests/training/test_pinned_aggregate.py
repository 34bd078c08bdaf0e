"""Probability of improvement with ties, against a plain double loop over run pairs.

Ties are common in studies: scores are whole task counts divided by a rate, and BR-Prox
is capped at 1, so two robots often share a score. rliable's probability of improvement
(the Mann-Whitney U over ``n_x n_y``) counts a tie as one half; the reference below is
that definition written out pair by pair.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from hg_marl.training.aggregate import aggregate, br_prox, improvement, iqm, mean, profile, stratified_bootstrap


def reference_improvement(x: list[list[float]], y: list[list[float]]) -> float:
    """P(X > Y) with ties counting 1/2, per task (columns), averaged over tasks."""
    tasks = len(x[0])
    total = 0.0
    for t in range(tasks):
        wins = 0.0
        pairs = 0
        for row_x in x:
            for row_y in y:
                a, b = row_x[t], row_y[t]
                wins += 1.0 if a > b else 0.5 if a == b else 0.0
                pairs += 1
        total += wins / pairs
    return total / tasks


def _frame(scores: dict[str, dict[str, list[float]]], column: str = "score") -> pd.DataFrame:
    rows = [
        {"robot": r, "human": h, "scenario": "s", "seed": i, column: v, "score": v}
        for r, by_human in scores.items()
        for h, values in by_human.items()
        for i, v in enumerate(values)
    ]
    return pd.DataFrame(rows)


def test_identical_robots_are_one_half() -> None:
    x = np.array([[1.0, 3.0], [2.0, 3.0]])
    assert float(improvement(x, x.copy())) == 0.5


def test_ties_count_one_half_worked_by_hand() -> None:
    # task 1: A = [1, 1], B = [1, 0]: pairs (1,1) tie, (1,0) win, twice -> (0.5 + 1 + 0.5 + 1) / 4 = 0.75
    # task 2: A = [2, 2], B = [2, 2]: all ties -> 0.5; mean over tasks: 0.625
    x = np.array([[1.0, 2.0], [1.0, 2.0]])
    y = np.array([[1.0, 2.0], [0.0, 2.0]])
    assert float(improvement(x, y)) == pytest.approx(0.625)
    assert float(improvement(y, x)) == pytest.approx(0.375)  # P(A > B) + P(B > A) = 1 when ties split


@pytest.mark.parametrize("seed", range(5))
def test_whole_task_counts_with_many_ties_match_the_pairwise_definition(seed: int) -> None:
    rng = np.random.default_rng(seed)
    x = rng.integers(0, 3, size=(4, 3)).astype(float)  # 3 values over 12 runs: ties everywhere
    y = rng.integers(0, 3, size=(5, 3)).astype(float)
    assert float(improvement(x, y)) == pytest.approx(reference_improvement(x.tolist(), y.tolist()))
    assert float(improvement(x, y)) + float(improvement(y, x)) == pytest.approx(1.0)


def test_br_prox_capped_at_one_ties_in_the_study_aggregate() -> None:
    # both robots reach the cap on 3 of 4 seeds; B is below it once: A > B wins 1 pair in 16... by hand:
    # A = [1, 1, 1, 1], B = [1, 1, 1, 0.5]: each A run ties 3 B runs (1.5) and beats one (1) -> 2.5 / 4 = 0.625
    frame = _frame({"A": {"h": [1.0, 1.0, 1.0, 1.0]}, "B": {"h": [1.0, 1.0, 1.0, 0.5]}})
    agg = aggregate(frame, reps=50, poi_reps=200)
    assert agg["improvement"]["A>B"]["p"] == pytest.approx(0.625)
    low, high = agg["improvement"]["A>B"]["ci"]
    assert 0.5 <= low <= 0.625 <= high <= 1.0  # every resample of A ties or beats every resample of B


def test_improvement_uses_only_the_tasks_both_robots_played() -> None:
    # A played h1 and h2, B only h2: the pair is judged on h2 alone (A loses it: 0.0), not on h1 (A would win)
    frame = _frame({"A": {"h1": [9.0, 9.0], "h2": [0.0, 0.0]}, "B": {"h2": [1.0, 1.0]}})
    agg = aggregate(frame, reps=20, poi_reps=20)
    assert agg["improvement"]["A>B"]["p"] == 0.0
    assert "B>A" not in agg["improvement"]  # one direction per pair, in study order


def test_a_pair_with_no_common_task_is_left_out() -> None:
    frame = _frame({"A": {"h1": [1.0, 2.0]}, "B": {"h2": [1.0, 2.0]}})
    assert aggregate(frame, reps=10, poi_reps=10)["improvement"] == {}


def test_bootstrap_of_a_tied_pair_never_leaves_one_half() -> None:
    x = np.ones((3, 2))
    lo, hi = stratified_bootstrap([x, x.copy()], improvement, 100)[:, 0]
    assert lo == hi == 0.5


def test_iqm_mean_and_profile_of_a_small_matrix_by_hand() -> None:
    m = np.array([[0.0, 4.0], [1.0, 5.0], [2.0, 6.0], [3.0, 7.0]])  # 8 scores 0..7
    assert float(iqm(m)) == pytest.approx(3.5)  # drop 0, 1 and 6, 7: mean(2, 3, 4, 5)
    assert float(mean(m)) == pytest.approx((1.5 + 5.5) / 2)
    assert profile(m, np.array([-1.0, 0.0, 3.5, 7.0])).tolist() == [1.0, 7 / 8, 4 / 8, 0.0]  # strictly above


def test_iqm_of_bootstrap_replications_is_per_replication() -> None:
    reps = np.stack([np.arange(8.0).reshape(4, 2), np.full((4, 2), 2.0)])  # (2 replications, 4 runs, 2 tasks)
    assert iqm(reps).tolist() == [3.5, 2.0]


def test_br_prox_rows_per_scenario_and_split() -> None:
    frame = _frame({"A": {"tr": [1.0, 1.0], "te": [0.5, 0.5]}}, column="br_prox")
    rows = br_prox(frame, {"tr": "train", "te": "test"}, reps=0)
    assert [(r["split"], r["iqm"], r["runs"], r["ci"]) for r in rows] == [
        ("train", 1.0, 2, None),
        ("test", 0.5, 2, None),
    ]
    assert [(r["split"], r["iqm"]) for r in br_prox(frame, None, reps=0)] == [("all", 0.75)]


def test_generalisation_split_reads_train_and_test_by_name() -> None:
    # "validation" partners belong to neither side of the gap
    frame = _frame({"A": {"tr": [0.9, 0.9], "va": [0.1, 0.1], "te": [0.6, 0.6]}})
    gap = aggregate(frame, {"tr": "train", "va": "validation", "te": "test"}, reps=20, poi_reps=5)["generalisation"]
    assert gap["A"]["train_iqm"] == pytest.approx(0.9) and gap["A"]["test_iqm"] == pytest.approx(0.6)
