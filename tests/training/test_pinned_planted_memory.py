"""Pinned against a planted bug: the memory robot's hidden state starts at zero in every run.

A counting net (its hidden state is the number of steps taken) makes the property
visible: the hidden state each step receives must read 0, 1, 2 in every run, however
many runs came before.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent
from hg_marl.envs.table_cleaning import raw_env


class CountingNet:
    """Hidden state = steps since ``initial``; records the state each step receives."""

    def __init__(self, n_actions: int) -> None:
        self.n_actions = n_actions
        self.seen: list[float] = []

    def initial(self, n: int) -> np.ndarray:
        return np.zeros((n, 1))

    def step(self, obs: Any, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        self.seen.append(float(h[0, 0]))
        return np.zeros((1, self.n_actions)), h + 1.0


def test_each_run_starts_from_the_initial_hidden_state() -> None:
    env = raw_env(scenario="paper2015", continuing=True, max_cycles=None)
    net = CountingNet(env.world.n_actions(Agent.ROBOT))
    robot = make_robot("memory", net=net)
    wait_h = env.world.table.wait[Agent.HUMAN]
    for run in range(3):
        env.reset(seed=run)
        robot.reset(env.world, Agent.ROBOT, np.random.default_rng(run))
        for _ in range(3):
            env.step(robot.act(env.turn("robot")))
            env.step(wait_h)
    assert net.seen == [0.0, 1.0, 2.0] * 3
