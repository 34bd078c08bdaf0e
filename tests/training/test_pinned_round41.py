"""Round 41 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated independently of the code under test: the habit robot's
decision time is the cost model's documented constant (``agents/meta/cost.py``: "habit:
a constant ``habit`` seconds" in the default ``model`` mode), and the play statistics'
median response time is worked by hand (the median of an even count is the mean of the
two middle values, as ``statistics.median`` and every textbook define it).
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.core import Agent, World
from hg_marl.policy import Turn
from hg_marl.training.play.stats import PlayStats, summarise


@pytest.mark.parametrize(("cost", "charged"), [(None, 1e-3), (CostModel(habit=0.25), 0.25)])
def test_the_habit_robot_charges_the_cost_models_constant_per_decision(cost: CostModel | None, charged: float) -> None:
    """In the default ``model`` mode every habit decision is charged the model's ``habit``
    seconds (1 ms by default, 0.25 s here), whatever the machine measured: exactly that
    constant in each decision's record, never the (machine-dependent) wall time."""
    world = World("paper2015")
    robot = HabitRobot(cost=cost)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    for _ in range(5):
        obs = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
        action = robot.act(Turn(world, state, Agent.ROBOT, obs, reward=0.0))
        assert robot.last_decision.expert == "habit"
        assert robot.last_decision.decision_time == charged
        state = world.step(state, Agent.ROBOT, action).state
        state = world.step(state, Agent.HUMAN, world.feasible_indices(state, Agent.HUMAN)[0]).state


def _game(times: tuple[float, ...]) -> PlayStats:
    return PlayStats(
        who="p", robot="planner", moves=len(times), tasks=1, handover_acceptance=None, response_times=times
    )


def test_the_median_response_time_of_an_even_count_is_the_mean_of_the_two_middle_values() -> None:
    """Response times 1, 10 (one game) and 4, 2 (another): sorted 1, 2, 4, 10, so the
    median is (2 + 4) / 2 = 3 by hand, and the mean (1 + 10 + 4 + 2) / 4 = 4.25. With a
    fifth time, 7, the median is the middle value 4."""
    totals = summarise([_game((1.0, 10.0)), _game((4.0, 2.0))])
    assert totals["response_time_median"] == pytest.approx(3.0)
    assert totals["response_time_mean"] == pytest.approx(4.25)
    odd = summarise([_game((1.0, 10.0)), _game((4.0, 2.0, 7.0))])
    assert odd["response_time_median"] == pytest.approx(4.0)
