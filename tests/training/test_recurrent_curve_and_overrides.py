"""The recurrent PPO's learning curve starts from nothing counted, and a bad ``--hp`` value is one line."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.baselines.ppo_recurrent import config_from_options
from tests.training.test_pinned_round37 import train_clocked


def test_each_rollouts_curve_row_counts_only_its_own_tasks_and_seconds(tmp_path: Path) -> None:
    """The clocked toy solves no task: every row's rate is 0 and no time is negative
    (a rollout's counters start at 0, not carried or offset)."""
    train_clocked(tmp_path, steps=48)
    header, *rows = (tmp_path / "curve.csv").read_text().splitlines()
    assert header == "steps,tasks_per_hour,env_seconds,learner_seconds"
    assert [row.split(",")[:2] for row in rows] == [["24", "0.000"], ["48", "0.000"]]
    assert all(float(row.split(",")[2]) >= 0 for row in rows)


@pytest.mark.parametrize(
    ("override", "message"),
    [
        ("gamma=abc", "--hp 'gamma=abc': gamma must be a float"),
        ("hidden=1.5", "--hp 'hidden=1.5': hidden must be a int"),
    ],
)
def test_an_override_of_the_wrong_type_is_one_line_naming_it(override: str, message: str) -> None:
    with pytest.raises(ConfigError) as refused:
        config_from_options({}, (override,))
    assert str(refused.value) == message
