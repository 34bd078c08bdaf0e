"""The simulated spans a trainer plays (an episode, the greedy evaluation) are bounded before it starts.

An evaluation of 0 s divided 0 tasks by 0 s (a NaN rate written to the result); one of
1e300 s never ended. Both are refused in one line naming the option, as a run's
``--duration`` is: the longest span is MAX_CYCLES = 50,000,000 cycles of the shortest
action any scenario may have, 0.01 s, that is 500,000 s.
"""

from __future__ import annotations

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.baselines.ppo_batched import PPOBatchedConfig
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig
from hg_marl.training.runner import check_seconds

LONGEST = 500_000.0  # 50,000,000 cycles x 0.01 s, worked by hand


@pytest.mark.parametrize("value", [0, 0.0, -1.0, float("nan"), float("inf"), True, "60"])
def test_a_span_that_is_not_a_positive_number_is_refused_naming_the_option(value: object) -> None:
    with pytest.raises(ConfigError, match=r"^--eval-seconds: expected a positive number of seconds, got "):
        check_seconds(value, "--eval-seconds")


def test_the_longest_span_is_fifty_million_cycles_of_the_shortest_action() -> None:
    assert check_seconds(LONGEST, "--eval-seconds") == LONGEST
    assert check_seconds(7, "--eval-seconds") == 7.0
    with pytest.raises(ConfigError, match=r"^--eval-seconds 500001: .*\(0\.01 s\), over the limit 50,000,000$"):
        check_seconds(LONGEST + 1, "--eval-seconds")


def test_the_batched_trainer_refuses_an_evaluation_of_no_seconds_instead_of_reporting_nan() -> None:
    with pytest.raises(ConfigError, match=r"^--eval-seconds: expected a positive number of seconds, got 0$"):
        PPOBatchedConfig(eval_seconds=0).check()
    with pytest.raises(ConfigError, match=r"^--eval-seconds 1e\+300: "):
        PPOBatchedConfig(eval_seconds=1e300).check()
    assert PPOBatchedConfig(eval_seconds=LONGEST).check().eval_seconds == LONGEST


@pytest.mark.parametrize("name", ["episode_seconds", "eval_seconds"])
def test_the_recurrent_trainer_bounds_its_episodes_and_its_evaluation(name: str) -> None:
    option = "--" + name.replace("_", "-")
    with pytest.raises(ConfigError, match=rf"^{option} 1e\+300: .*over the limit 50,000,000$"):
        RecurrentConfig(**{name: 1e300}).check()
    with pytest.raises(ConfigError, match=rf"^{option}: expected a positive number of seconds, got 0$"):
        RecurrentConfig(**{name: 0}).check()
    assert getattr(RecurrentConfig(**{name: LONGEST}).check(), name) == LONGEST
