"""Values that round 139's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.agents.humans.random_human import RandomHuman
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, State
from tests.agents.test_pinned_human_random_gate import PAPER


def test_a_random_robot_without_the_mask_draws_among_the_robots_own_actions() -> None:
    # The random actor is seat-agnostic: on the robot's seat, feasible_only=False is uniform over
    # the robot's actions. paper2015's robot has 18 (a pick, throw, give, take and goto per object
    # for its 3 objects, then goto(trashbin), goto(human) and wait), the human 31: the robot's draw
    # is 18 options of 1/18 each, never an index of the human's 31.
    dist = RandomHuman(feasible_only=False).distribution_for(PAPER, State((0, 1, 4), 0), Agent.ROBOT)
    assert dist == [(i, 1.0 / 18) for i in range(18)]


def test_the_robot_views_info_counts_the_cycles_run() -> None:
    # Three steps of the robot's wait (the last robot action) against the cooperative human: each
    # step is one cycle, and three waits cannot solve the table, so the cycle count is 1, 2, 3
    # while the tasks solved stay 0.
    view = RobotView("paper2015", human="cooperative")
    view.reset(seed=0)
    wait = view.world.n_actions(Agent.ROBOT) - 1
    counts = [view.step(wait)[4] for _ in range(3)]
    assert [(info["cycle"], info["tasks_solved"]) for info in counts] == [(1, 0), (2, 0), (3, 0)]
