"""Values that round 148's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from typing import Any

import numpy as np

import hg_marl
from hg_marl.agents.adapters import scripted_v0
from hg_marl.agents.humans import make_human
from hg_marl.agents.views import HumanView
from hg_marl.core import Agent, World
from hg_marl.policy import Actor, Turn
from tests.agents.test_pinned_views_gate import N_ROBOT


class _SeatRecorder:
    """An actor that records the seat of every turn it is asked to act on, and sends its own seat's wait."""

    def __init__(self) -> None:
        self.turn_agents: list[Agent] = []

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.wait = world.n_actions(agent) - 1

    def act(self, turn: Turn) -> int:
        self.turn_agents.append(turn.agent)
        return self.wait


def test_a_scripted_robot_decides_on_the_robots_own_turn() -> None:
    # The spec sheet: one ``actor.act`` per turn, on the state when the seat is observed. The
    # robot seat's actor is asked on the robot's turn (Turn.agent is the robot), and the
    # one-hot mask it is shown sits on its answer: the robot's wait, its last action (index 17 of
    # paper2015's N_ROBOT = 18 robot actions).
    robot = _SeatRecorder()
    env = scripted_v0(hg_marl.env(), robot=robot)
    env.reset(seed=0)
    mask = env.observe("robot")["action_mask"]
    assert robot.turn_agents == [Agent.ROBOT]
    assert np.flatnonzero(mask).tolist() == [N_ROBOT - 1] == [17]


def _until_solved(view: HumanView, human: Actor) -> tuple[float, bool, dict[str, Any]]:
    """Human steps until one solves a task (at most 60); that step's reward, done flag and info."""
    for _ in range(60):
        _, reward, done, truncated, info = view.step(human.act(view.env.turn("human")))
        assert not truncated
        if info["task_reward"] > 0:
            return float(reward), bool(done), info
    raise AssertionError("no task solved in 60 steps")


def _cooperative_with_the_planner(continuing: bool) -> tuple[HumanView, Actor]:
    view = HumanView("paper2015", robot="planner", continuing=continuing, max_cycles=60)
    view.reset(seed=3)
    human = make_human("cooperative")
    human.reset(view.world, Agent.HUMAN, np.random.default_rng(0))
    return view, human


def test_a_continuing_human_view_plays_on_past_a_solved_task() -> None:
    # The module docstring: only in episodic mode does the human's episode end as soon as the
    # robot completes the task. A cooperative human with the planner solves paper2015's task
    # (task reward 1, effort weight 0: reward 1) in under 60 steps. Episodic: that step ends
    # the episode (done True). Continuing (the table re-drawn after each success): it does not
    # (done False), and the next step goes on with 1 task solved, neither done nor truncated.
    view, human = _cooperative_with_the_planner(continuing=False)
    assert _until_solved(view, human)[:2] == (1.0, True)
    view, human = _cooperative_with_the_planner(continuing=True)
    assert _until_solved(view, human)[:2] == (1.0, False)
    _, _, done, truncated, info = view.step(human.act(view.env.turn("human")))
    assert (done, truncated, info["tasks_solved"]) == (False, False, 1)
