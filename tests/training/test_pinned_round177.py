"""Values that round 177's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.habit import QLearner, QLearnerConfig


def test_a_habit_with_an_uncertainty_prior_of_zero_is_accepted_and_starts_certain() -> None:
    # uncertainty_prior is v0, the squared TD error assumed for a never-updated pair: a
    # variance, so any v0 >= 0 is one, and 0 (the habit claims to know its zero Q-values) is
    # the legal end point; a negative variance is not. Worked by hand with v0 = 0 and rate 0.1:
    # every pair's sd starts at sqrt(0) = 0; a terminal update with reward 3 from Q = 0 is a TD
    # error of 3, so the state's variance moves a tenth of the way to 9, 0 + 0.1 * (9 - 0) = 0.9,
    # and every action there has sd sqrt(0.9) (the one taken, and the others by their state's).
    assert QLearnerConfig(uncertainty_prior=0.0).uncertainty_prior == 0.0
    with pytest.raises(ValueError, match="uncertainty_prior"):
        QLearnerConfig(uncertainty_prior=-0.5)
    q = QLearner(5, 4, QLearnerConfig(features="tabular", uncertainty_prior=0.0))
    s0, s1 = np.array([1, 0, 1, 0, 0], dtype=np.int8), np.array([0, 1, 0, 0, 1], dtype=np.int8)
    assert q.uncertainty(s0) == pytest.approx(np.zeros(4))
    assert q.update(s0, 2, 3.0, s1, done=True) == pytest.approx(3.0)
    assert q.uncertainty(s0) == pytest.approx(np.full(4, np.sqrt(0.9)))
    assert q.uncertainty(s1) == pytest.approx(np.zeros(4))


def test_the_recurrent_sb3_run_trains_with_the_learning_rate_it_was_given(tmp_path: Path) -> None:
    pytest.importorskip("sb3_contrib")
    from hg_marl.training.baselines.recurrent_ppo_sb3 import train
    from tests.training.test_recurrent_ppo_sb3 import _config

    # 1e-3 is not RecurrentPPO's own default (3e-4): the model, and the optimizer it stepped
    # with (a constant schedule), hold the rate the config asked for.
    config = _config(tmp_path, steps=16, num_envs=2, n_steps=8, batch_size=4, history=0, learning_rate=1e-3)
    result = train(config)
    assert result.model.learning_rate == pytest.approx(1e-3)
    assert [g["lr"] for g in result.model.policy.optimizer.param_groups] == pytest.approx([1e-3])
