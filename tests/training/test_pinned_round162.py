"""Values that round 162's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.array_partners import LiveRobots
from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchState
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario_file import parse_scenario
from hg_marl.policy import Turn
from hg_marl.training.aggregate import aggregate
from tests.training.test_aggregate import _table
from tests.training.test_pinned_round54 import _coloured
from tests.training.test_pinned_round130 import _Constant

# --- hg_marl/core/scenario_file.py ---


@pytest.mark.parametrize("name", [".hidden", ".", "..", ".x.toml"])
def test_a_scenario_name_starting_with_a_dot_is_refused(name: str) -> None:
    # SCENARIO_NAME_PATTERN's docstring: a scenario's name becomes part of trace file names, "so
    # it holds no path separator and does not start with a dot"; the refusal says what it may be
    # ("letters, digits, '_', '-' or '.'") and names the field. A leading dot would make a hidden
    # file (or '.', '..' a folder of the path itself).
    data = _coloured([""])
    data["name"] = name
    with pytest.raises(ScenarioError, match=r"field 'name': name '.*' must be letters, digits, '_', '-' or '\.'"):
        parse_scenario(data, "dot.toml", strict=True)


@pytest.mark.parametrize("name", ["hidden", "v1.2", "a..b", "0start", "x-y_z."])
def test_a_scenario_name_with_dots_after_its_first_character_loads(name: str) -> None:
    # The same pattern: a letter or digit first, then letters, digits, '_', '.' or '-'.
    data = _coloured([""])
    data["name"] = name
    assert parse_scenario(data, "dot.toml", strict=True).name == name


# --- training/aggregate.py ---


def test_a_robots_mean_interval_is_the_means_not_the_iqms() -> None:
    # Two seeds on four partners, every partner's two scores equal: a (0, 0), b (0, 0), c (0, 0),
    # d (10, 10). By hand: the mean is the mean of the per-partner means, (0 + 0 + 0 + 10) / 4 =
    # 2.5; the IQM sorts the 8 scores (six 0s, two 10s), drops int(8 / 4) = 2 at each end and
    # averages four 0s: 0. The stratified bootstrap resamples seeds within each partner, and
    # each partner's seeds are equal, so every replication is the data itself: the IQM's
    # interval is [0, 0] and the mean's [2.5, 2.5] (not the IQM's).
    frame = _table({"A": {"a": [0.0, 0.0], "b": [0.0, 0.0], "c": [0.0, 0.0], "d": [10.0, 10.0]}})
    robot = aggregate(frame, reps=50, poi_reps=10)["robots"]["A"]
    assert robot["iqm"] == pytest.approx(0.0) and robot["mean"] == pytest.approx(2.5)
    assert robot["iqm_ci"] == pytest.approx([0.0, 0.0])
    assert robot["mean_ci"] == pytest.approx([2.5, 2.5])


# --- agents/array_partners.py ---


class _Recorder(_Constant):
    """A robot stand-in that answers ``action`` and keeps the mask of each turn it is handed."""

    def __init__(self, action: int) -> None:
        super().__init__(action)
        self.masks: list[np.ndarray] = []

    def act(self, turn: Turn) -> int:
        self.masks.append(np.asarray(turn.mask))
        return self.action


def test_live_robots_in_the_human_seat_are_handed_the_robots_own_mask() -> None:
    # paper2015's clean table (every object in bin 6), the robot at location 0. By hand: the
    # robot has 18 actions (the last, 17, its wait) and can only go to its other location
    # (index 16) or wait; the human has 31 actions and can only wait (index 30). A live robot
    # playing the human's batched seat must be handed its own 18-entry mask with 16 and 17 set.
    world = World("paper2015")
    robot = _Recorder(17)
    live = LiveRobots(world, robot, 1)
    clean = State((6, 6, 6), 0, -1, -1)
    batch = BatchState(
        np.array([clean.where], dtype=np.int64),
        np.array([clean.robot_at], dtype=np.int64),
        np.full(1, clean.offer_by, dtype=np.int64),
        np.full(1, clean.offer_obj, dtype=np.int64),
        np.array([0]),
    )
    assert live.act(batch, np.zeros(1, dtype=bool), np.random.default_rng(0)).tolist() == [17]
    (mask,) = robot.masks
    assert len(mask) == 18
    assert np.flatnonzero(mask).tolist() == [16, 17]
    assert world.n_actions(Agent.ROBOT) == 18
