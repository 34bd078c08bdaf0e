"""Round 40 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated independently of the code under test: from the documented
rule (``costs.robot_active``: "``wait`` does not [count as robot activity], nor does an
unknown action (-1)"), as a property (a search whose robot part is an unknown action
costs what the same search after a robot ``wait`` of the same duration costs), and by
hand for the one cycle where the rule matters, priced with the cost model's documented
terms (``costs.py``: ``effort_balance`` is ``max(0, e_h - e_r)``, weight 0.1 per second).
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig, make_human_model
from hg_marl.agents.planner.halfstep import astar
from hg_marl.core import Agent, Kind, State, World

BUDGET = 200_000


def _mid_task(world: World) -> State:
    """paper2015 two random joint cycles in (a fixed walk): the human has an object to pick."""
    rng = np.random.default_rng(1)
    s = world.initial_state(np.random.default_rng(0))
    for _ in range(2):
        s = world.step(s, Agent.ROBOT, int(rng.choice(world.feasible_indices(s, Agent.ROBOT)))).state
        s = world.step(s, Agent.HUMAN, int(rng.choice(world.feasible_indices(s, Agent.HUMAN)))).state
    return s


def test_an_unknown_robot_action_under_way_is_no_robot_activity() -> None:
    """At the human's turn with the robot's action under way but unknown (-1), the robot
    is not active in the first cycle (``robot_active``'s rule), exactly as after a robot
    ``wait`` of the same duration: the two searches find the same cycles at the same cost.
    After a robot pick of that duration (robot work) the same cycles cost less by the first
    cycle's ``effort_balance``: the human picks (2 s) within the robot's 10 s, so that term
    is 0.1 * 2 = 0.2 with an idle robot and 0 with a working one. Counting the unknown
    action as robot work would make it cost what the pick costs. (The planner passes a
    duration of 0 with an unknown action, where the rule changes no cost; the search is
    called here as a caller that knows how long the robot's action lasts, not which it was.)"""
    world = World("paper2015")
    planner = Planner(world, PlannerConfig(weights=CostWeights()), human_model=make_human_model("cooperative"))
    wait_r = world.table.wait[Agent.ROBOT]
    pick_r = next(i for i, a in enumerate(world.actions(Agent.ROBOT)) if a.kind is Kind.PICK)
    root = _mid_task(world)
    d = 10.0  # longer than any human action: the human's whole work falls within the robot's part
    unknown = astar(planner.space, root, Agent.HUMAN, (d, -1), BUDGET)
    waiting = astar(planner.space, root, Agent.HUMAN, (d, wait_r), BUDGET)
    working = astar(planner.space, root, Agent.HUMAN, (d, pick_r), BUDGET)
    assert unknown.cycles is not None and waiting.cycles is not None and working.cycles is not None
    assert unknown.cycles == waiting.cycles == working.cycles
    first_human = world.actions(Agent.HUMAN)[unknown.cycles[0][1]]
    assert first_human.kind is Kind.PICK  # a 2 s action (paper2015's durations)
    assert unknown.cost == pytest.approx(waiting.cost, abs=1e-9)
    assert unknown.cost - working.cost == pytest.approx(0.1 * 2.0, abs=1e-9)
