"""Pinned against planted bugs: the memory robot's hidden state and the history it reads.

A counting net (its hidden state is the number of steps taken) makes the property
visible: the hidden state each step receives must read 0, 1, 2 in every run, however
many runs came before.

The history the robot rebuilds from its turn says whose action failed: a turn after one
cycle (the robot's ``goto``, the human's ``pick``) with a ``failed`` event of one agent
only must show exactly that agent's failure. Worked by hand for ``k = 1`` from the
layout of ``history_names``: the partner's kind, the partner's failure, the robot's own
kind, its own failure, then cycles since the partner's progress (0 after the human's
successful pick, 1 after its failed one).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.memory import MemoryRobot
from hg_marl.core import Agent, State, World
from hg_marl.core.types import Event
from hg_marl.envs.history import history_names
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.policy import Turn


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


ROBOT_GOTO_TAPE3, ROBOT_GOTO_TAPE1, HUMAN_PICK_TAPE3 = 14, 12, 2


@pytest.mark.parametrize(
    ("robot_action", "failed", "expected"),
    [
        (
            ROBOT_GOTO_TAPE3,
            "robot",
            {"partner_kind[-1]=pick", "own_kind[-1]=goto", "own_failed[-1]", "partner_since_progress=0"},
        ),
        (
            ROBOT_GOTO_TAPE1,
            "human",
            {"partner_kind[-1]=pick", "partner_failed[-1]", "own_kind[-1]=goto", "partner_since_progress=1"},
        ),
    ],
)
def test_the_history_shows_the_failure_of_the_agent_whose_action_failed(
    robot_action: int, failed: str, expected: set[str]
) -> None:
    world = World("paper2015")
    assert world.action_name(Agent.ROBOT, robot_action).startswith("goto")
    assert world.action_name(Agent.HUMAN, HUMAN_PICK_TAPE3) == "pick(tape3)"
    robot = MemoryRobot(net=CountingNet(world.n_actions(Agent.ROBOT)), history=1, unstall=0)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = State((0, 2, 4), 0)
    mask = np.ones(world.n_actions(Agent.ROBOT), dtype=np.int8)
    turn = Turn(
        world,
        state,
        Agent.ROBOT,
        {"observation": np.asarray(world.facts(state), dtype=np.float32), "action_mask": mask},
        events=(Event("failed", failed),),
        last_actions=(robot_action, HUMAN_PICK_TAPE3),
    )
    robot.act(turn)
    assert robot.last_obs is not None
    features = robot.last_obs[world.n_facts :]
    names = history_names(1, 8)
    assert len(features) == len(names)
    assert {name for name, on in zip(names, features, strict=True) if on} == expected
