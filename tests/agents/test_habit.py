"""The habitual expert: TD update, Boltzmann sampling, persistence, uncertainty, speed."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from hg_marl.agents.habit import QLearner, QLearnerConfig, sample, softmax

N_FACTS, N_ACTIONS = 5, 4
S0 = np.array([1, 0, 1, 0, 0], dtype=np.int8)
S1 = np.array([0, 1, 0, 0, 1], dtype=np.int8)


def test_q_update_matches_hand_computation() -> None:
    q = QLearner(N_FACTS, N_ACTIONS)
    q.weights[2] = [0.5, 0.0, 0.1, 0.0, 0.0]
    q.bias[2] = 0.2
    q.weights[1] = [0.0, 0.3, 0.0, 0.0, 0.4]  # max over S1 is action 1: 0.3 + 0.4 = 0.7
    # Q(S0, 2) = 0.5 + 0.1 + 0.2 = 0.8; delta = 1 + 0.9 * 0.7 - 0.8 = 0.83
    delta = q.update(S0, 2, 1.0, S1)
    assert delta == pytest.approx(0.83)
    step = 0.6 * 0.83 / (2 + 1)  # NLMS: |phi|^2 = 2 plus the bias
    assert q.weights[2] == pytest.approx([0.5 + step, 0.0, 0.1 + step, 0.0, 0.0])
    assert q.bias[2] == pytest.approx(0.2 + step)
    # The normalised step moves Q(S0, 2) by exactly alpha * delta.
    assert q.q_values(S0)[2] == pytest.approx(0.8 + 0.6 * 0.83)


def test_terminal_update_does_not_bootstrap() -> None:
    q = QLearner(N_FACTS, N_ACTIONS)
    q.bias[:] = 5.0
    assert q.update(S0, 0, 1.0, S1, done=True) == pytest.approx(1.0 - 5.0)


def test_tabular_update_is_textbook() -> None:
    q = QLearner(N_FACTS, N_ACTIONS, QLearnerConfig(features="tabular"))
    assert q.update(S0, 1, 1.0, S1) == pytest.approx(1.0)
    assert q.q_values(S0)[1] == pytest.approx(0.6)
    assert q.q_values(S1).tolist() == [0.0] * N_ACTIONS  # no generalisation, no bias
    # delta = 0 + 0.9 * 0.6 - 0 on the S1 -> S0 transition
    assert q.update(S1, 3, 0.0, S0) == pytest.approx(0.54)
    assert q.n_states == 2


def test_tabular_grows_past_initial_capacity() -> None:
    q = QLearner(8, 3, QLearnerConfig(features="tabular"))
    states = [np.array([(i >> k) & 1 for k in range(8)], dtype=np.int8) for i in range(100)]
    for s, s2 in itertools.pairwise(states):
        q.update(s, 0, 1.0, s2)
    assert q.n_states == 100
    assert q.q_values(states[0])[0] > 0


def test_normalised_update_converges_where_plain_diverges() -> None:
    dense = np.ones(10, dtype=np.int8)
    for normalise, bounded in ((True, True), (False, False)):
        q = QLearner(10, 2, QLearnerConfig(normalise=normalise))
        with np.errstate(all="ignore"):
            for _ in range(60):
                q.update(dense, 0, 1.0, dense, done=True)
        value = q.q_values(dense)[0]
        assert bool(abs(value - 1.0) < 1e-6) == bounded


def test_boltzmann_frequencies_match_policy() -> None:
    q = QLearner(N_FACTS, N_ACTIONS, QLearnerConfig(beta=2.0))
    q.bias[:] = [0.0, 0.5, 1.0, -0.5]
    p = q.policy(S0)
    expected = np.exp(2.0 * q.bias) / np.exp(2.0 * q.bias).sum()
    assert p == pytest.approx(expected)
    rng = np.random.default_rng(1)
    n = 20_000
    counts = np.bincount([q.act(S0, rng) for _ in range(n)], minlength=N_ACTIONS)
    chi2 = float((((counts - n * p) ** 2) / (n * p)).sum())
    assert chi2 < 16.3  # chi-square, 3 dof, p = 0.001


def test_softmax_is_stable_for_large_beta() -> None:
    p = softmax(np.array([1000.0, 999.0, 0.0]), 50.0)
    assert np.isfinite(p).all() and p.sum() == pytest.approx(1.0) and p[0] > 0.999


def test_sample_degenerate_distribution() -> None:
    rng = np.random.default_rng(0)
    assert {sample(np.array([0.0, 0.0, 1.0]), rng) for _ in range(50)} == {2}


def test_sample_scales_the_draw_by_the_total_so_weights_need_not_sum_to_one() -> None:
    # weights 1 and 3 (total 4): index 1 is drawn with probability 3/4, index 0 with 1/4;
    # 4,000 draws: standard deviation of the share sqrt(0.75 * 0.25 / 4000) = 0.0068
    rng = np.random.default_rng(7)
    draws = np.array([sample(np.array([1.0, 3.0]), rng) for _ in range(4000)])
    assert set(draws.tolist()) == {0, 1}
    assert (draws == 1).mean() == pytest.approx(0.75, abs=0.03)


def test_weight_amplitude_is_sum_of_abs_weights() -> None:
    q = QLearner(N_FACTS, N_ACTIONS)
    assert q.weight_amplitude == 0.0
    q.weights[0, 0], q.weights[1, 1], q.bias[0] = -0.5, 0.25, 10.0
    assert q.weight_amplitude == pytest.approx(0.75)


def test_uncertainty_prior_then_shrinks() -> None:
    q = QLearner(N_FACTS, N_ACTIONS, QLearnerConfig(uncertainty_prior=1.0))
    assert q.uncertainty(S0) == pytest.approx(np.ones(N_ACTIONS))
    for _ in range(200):
        q.update(S0, 1, 1.0, S0, done=True)
    sd = q.uncertainty(S0)
    assert sd[1] < 0.01
    # untried actions borrow the state's running value, not the prior
    assert sd[0] == pytest.approx(sd[2]) and sd[0] < 0.01
    assert q.uncertainty(S1) == pytest.approx(np.ones(N_ACTIONS))  # unseen state: prior


@pytest.mark.parametrize("features", ["facts", "tabular"])
def test_save_load_round_trip(tmp_path, features: str) -> None:
    q = QLearner(N_FACTS, N_ACTIONS, QLearnerConfig(features=features, beta=7.0))  # type: ignore[arg-type]
    rng = np.random.default_rng(0)
    for _ in range(30):
        q.update(S0, int(rng.integers(N_ACTIONS)), float(rng.random()), S1)
        q.update(S1, int(rng.integers(N_ACTIONS)), 0.0, S0)
    path = q.save(tmp_path / "sub" / "habit.npz")
    assert [p.name for p in path.parent.iterdir()] == ["habit.npz"]  # no temp file left
    r = QLearner.load(path)
    assert r.config == q.config and r.n_updates == q.n_updates and r.n_states == q.n_states
    for s in (S0, S1):
        assert r.q_values(s) == pytest.approx(q.q_values(s))
        assert r.uncertainty(s) == pytest.approx(q.uncertainty(s))
    # 30 updates were made from each state: what it has learnt there survives the file
    assert (r.visits(S0), r.visits(S1)) == (q.visits(S0), q.visits(S1)) == (30, 30)
    assert r.update(S0, 0, 1.0, S1) == pytest.approx(q.update(S0, 0, 1.0, S1))


def test_save_is_atomic_on_failure(tmp_path, monkeypatch) -> None:
    q = QLearner(N_FACTS, N_ACTIONS)
    path = q.save(tmp_path / "habit.npz")
    before = path.read_bytes()

    def boom(*args: object, **kwargs: object) -> None:
        raise OSError("disk full")

    monkeypatch.setattr(np, "savez", boom)
    q.bias[:] = 1.0
    with pytest.raises(OSError):
        q.save(path)
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["habit.npz"]


def test_a_saved_habit_is_readable_by_others_as_every_result_is(tmp_path) -> None:
    """The habit's file goes through the project's atomic write: mode 0644 like every result
    file (it was 0600, ``mkstemp``'s own, and written without a flush to disk)."""
    import stat

    path = QLearner(N_FACTS, N_ACTIONS).save(tmp_path / "habit.npz")
    assert stat.S_IMODE(path.stat().st_mode) == 0o644


def test_the_uncertainty_follows_the_squared_td_error_worked_by_hand() -> None:
    """Prior variance 1, rate 0.1. A first update with reward 3 on a terminal step from a
    zero Q is a TD error of 3: the pair's and the state's variance move a tenth of the way
    to 9, 1 + 0.1 * (9 - 1) = 1.8, so the sd is sqrt(1.8) for the action taken and, untried
    there, for the others (their state's running value); another state keeps the prior's 1."""
    q = QLearner(N_FACTS, N_ACTIONS, QLearnerConfig(features="tabular"))
    assert q.update(S0, 1, 3.0, S1, done=True) == pytest.approx(3.0)
    assert q.uncertainty(S0) == pytest.approx(np.full(N_ACTIONS, np.sqrt(1.8)))
    assert q.uncertainty(S1) == pytest.approx(np.ones(N_ACTIONS))


@pytest.mark.parametrize(
    "kwargs",
    [{"features": "deep"}, {"alpha": 0.0}, {"gamma": 1.5}, {"beta": -1.0}, {"uncertainty_rate": 0.0}],
)
def test_config_rejects_bad_values(kwargs: dict) -> None:
    with pytest.raises(ValueError, match="QLearnerConfig"):
        QLearnerConfig(**kwargs)
