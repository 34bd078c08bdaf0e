"""Values that round 204's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.habit import QLearner, QLearnerConfig
from tests.agents.test_habit import N_ACTIONS, N_FACTS, S0, S1


def test_a_second_actions_sd_moves_from_its_own_prior_not_from_its_states_running_value() -> None:
    # Tabular habit, prior variance 1, rate 0.5, terminal steps (no bootstrap), Q starts at 0.
    # Worked by hand: action 0 with reward 2 is a TD error of 2 (squared 4): the pair's and the
    # state's variance both go 1 + 0.5 * (4 - 1) = 2.5. Action 1 with reward 0 is a TD error of 0:
    # its own pair was never updated, so it moves from the prior, 1 + 0.5 * (0 - 1) = 0.5, while
    # the state's running value goes 2.5 + 0.5 * (0 - 2.5) = 1.25 (what the untried actions show).
    q = QLearner(N_FACTS, N_ACTIONS, QLearnerConfig(features="tabular", uncertainty_rate=0.5))
    assert q.update(S0, 0, 2.0, S1, done=True) == pytest.approx(2.0)
    assert q.update(S0, 1, 0.0, S1, done=True) == pytest.approx(0.0)
    expected = np.sqrt([2.5, 0.5] + [1.25] * (N_ACTIONS - 2))
    assert q.uncertainty(S0) == pytest.approx(expected)
