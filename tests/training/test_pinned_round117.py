"""Values that round 117's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.meta.learning_state import LearningStateCriterion
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.core.scenario_generated import generate_scenario
from hg_marl.envs.history import HistoryTracker, check_history
from hg_marl.training.baselines.bc import Dataset, fit_linear


def test_the_largest_documented_history_length_64_is_accepted_and_65_refused() -> None:
    # MAX_HISTORY is documented as 64, the largest k accepted. Worked by hand: the seven action
    # kinds (pick, throw, give, take, place, goto, wait) one-hot plus a failed flag, for 64 cycles,
    # for the partner and for the robot itself: 2 * 64 * (7 + 1) = 1024 entries, and the "cycles
    # since progress" one-hot over 0 .. 8 adds 9: 1033.
    assert check_history(64) == 64
    tracker = HistoryTracker(World("paper2015"), 64)
    assert tracker.size == 1033
    assert tracker.features(Agent.ROBOT).shape == (1, 1033)
    with pytest.raises(ConfigError, match="<= 64"):
        check_history(65)


def test_a_bad_min_visits_is_refused_under_its_own_name() -> None:
    # The refusal names the parameter the user got wrong, not the criterion's other one.
    with pytest.raises(ValueError, match=r"^learning_state\.min_visits: expected a non-negative integer, got -1$"):
        LearningStateCriterion(min_visits=-1)
    with pytest.raises(ValueError, match=r"^learning_state\.threshold: "):
        LearningStateCriterion(threshold=0.0)


def test_a_generated_scenario_with_the_default_spots_names_its_spot_count() -> None:
    # spots defaults to objects + 2 = 5 for 3 objects; the name spells every argument's value
    # (so two scenarios of different sizes never share a name), the spot count included.
    scenario = generate_scenario(objects=3, seed=2)
    assert len(scenario.spots) == 5
    assert scenario.name == "generated:objects=3,spots=5,locations=2,bins=1,human_only=0.3,seed=2"
    assert generate_scenario(objects=3, spots=5, seed=2).name == scenario.name


def test_the_linear_fit_shrinks_its_weights_by_the_l2_penalty_not_its_bias() -> None:
    # One row with the single fact 1, two actions, action 0 recorded; rate 0.5, l2 = 1, two steps.
    # Step 1 (w = b = 0): p = (1/2, 1/2), gradient p - y = (-1/2, 1/2); the penalty 1 * w is 0, so
    # w = b = (1/4, -1/4). Step 2: logits w + b = (1/2, -1/2), p_0 = sigmoid(1), gradient
    # g = (p_0 - 1, 1 - p_0). The bias: b - g/2 = 1/4 + (1 - p_0)/2. The weight with its penalty:
    # w - (g + w)/2 = w/2 - g/2 = 1/8 + (1 - p_0)/2 (without the penalty it would equal the bias).
    data = Dataset(
        np.ones((1, 1), dtype=np.int8),
        np.ones((1, 2), dtype=bool),
        np.zeros(1, dtype=np.int64),
        "paper2015",
        Agent.HUMAN,
    )
    w, b = fit_linear(data, 2, iterations=2, learning_rate=0.5, l2=1.0)
    p0 = 1.0 / (1.0 + math.exp(-1.0))
    assert np.allclose(b, [0.25 + (1 - p0) / 2, -0.25 - (1 - p0) / 2])
    assert np.allclose(w[:, 0], [0.125 + (1 - p0) / 2, -0.125 - (1 - p0) / 2])
