"""Values that round 98's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.array_partners import LiveRobots
from hg_marl.agents.model_format import load_model_file
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.core import Agent, World
from hg_marl.core.errors import ModelFileError
from tests.fuzz.test_bounds import _sb3_model_declaring


def test_an_sb3_file_is_held_to_its_headers_budget_not_the_formats_gib(tmp_path: Path) -> None:
    # The header (paper2015's robot seat, PPO, net_arch [64, 64]) describes three networks of
    # (n_facts+1) x 64 + 65 x 64 + 65 x n_actions weights each; x 2 (targets) x 3 (Adam) x 8 bytes,
    # plus 1 MiB of slack: a few MB. An 8 MB array is far under the format's 1 GiB but over that.
    world = World("paper2015")
    inputs, outputs = world.n_facts, world.n_actions(Agent.ROBOT)
    per_network = (inputs + 1) * 64 + (64 + 1) * 64 + (64 + 1) * outputs
    limit = 3 * per_network * 2 * 3 * 8 + (1 << 20)
    assert limit < 1000 * 1000 * 8 < 1 << 30
    header = _sb3_model_declaring(tmp_path, (1000, 1000))
    refused = f"more than {limit:,} bytes of arrays declared, over the limit for its header"
    with pytest.raises(ModelFileError, match=refused):
        load_model_file(header)


def test_a_random_initial_state_draws_every_robot_start() -> None:
    # robot_start=(0, 1): "a uniform start", so over 400 seeded draws each start comes up about
    # half the time (binomial, sd 10 draws: 140-260 is six sd either side).
    world = World(dataclasses.replace(World("paper2015").scenario, robot_start=(0, 1)))
    rng = np.random.default_rng(3)
    starts = [world.initial_state(rng).robot_at for _ in range(400)]
    assert set(starts) == {0, 1}
    assert 140 <= starts.count(1) <= 260


def test_live_robots_given_an_actor_are_named_by_its_name() -> None:
    live = LiveRobots(World("paper2015"), RandomRobot(), 2)
    assert live.name == "random"
    assert LiveRobots(World("paper2015"), [RandomRobot(), "planner"], 2).name == "random"
