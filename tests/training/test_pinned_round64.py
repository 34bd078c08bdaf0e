"""The values round 64's missed planted bugs changed (``mutation/planted.py``, FRESH64), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from gymnasium import spaces

from hg_marl.agents.meta.entropy import EntropyCriterion
from hg_marl.agents.model_sb3 import space_from_json
from hg_marl.training.baselines.ppo_recurrent import RecurrentResult


def test_the_entropy_filter_keeps_the_lineages_default_rate() -> None:
    # The docstring: "rate: filter rate ``a`` (lineage default 0.6)", and the filter is
    # ``p <- (1 - a) p + a p_new`` starting at the first distribution it sees. By hand, with
    # a = 0.6: first [1, 0] (kept as is), then [0, 1] gives [0.4, 0.6], then [0, 1] again
    # gives [0.16, 0.84].
    criterion = EntropyCriterion()
    assert criterion.rate == pytest.approx(0.6)
    habit = criterion._habit
    first = habit.update(b"s", np.array([1.0, 0.0]))
    second = habit.update(b"s", np.array([0.0, 1.0]))
    third = habit.update(b"s", np.array([0.0, 1.0]))
    assert first.tolist() == [1.0, 0.0]
    assert second.tolist() == pytest.approx([0.4, 0.6])
    assert third.tolist() == pytest.approx([0.16, 0.84])


def test_a_bool_box_in_a_header_reads_back_as_a_bool_box() -> None:
    # A boolean dtype is numeric for the check ("Box dtype ... is not numeric" names only
    # non-numbers: strings, objects): a header's Box of two booleans, written by hand as
    # space_to_json writes it, reads back as a Box of shape (2,), dtype bool, bounds False and True.
    header = {"type": "Box", "low": [False, False], "high": [True, True], "shape": [2], "dtype": "bool"}
    space = space_from_json(header, "model.json: field 'observation_space'")
    assert isinstance(space, spaces.Box)
    assert space.shape == (2,)
    assert space.dtype == np.dtype(bool)
    assert space.low.tolist() == [False, False]
    assert space.high.tolist() == [True, True]


def test_learner_steps_per_second_count_the_learners_seconds_only() -> None:
    # The result's docstring: ``env_seconds`` is the wall time inside env.step and "the rest
    # of ``seconds`` is the learner's". By hand: 100 steps in 10 s of which 6 s in the env
    # give 100 / 6 env steps/s, 100 / (10 - 6) = 25 learner steps/s, and 100 / 10 = 10 overall.
    result = RecurrentResult(Path("out"), num_timesteps=100, seconds=10.0, env_seconds=6.0, rate_per_hour=0.0)
    assert result.learner_steps_per_second == pytest.approx(25.0)
    assert result.env_steps_per_second == pytest.approx(100 / 6)
    assert result.steps_per_second == pytest.approx(10.0)
