"""The values round 18's missed planted bugs changed, pinned after the round.

Each expected value is worked from the rule the module's docstring states, not read from
the code: the largest ``--workers`` the machine accepts is accepted (``min(256, 4 x CPUs)``),
one more is not; a learning robot's way out of a stall is its habit's best feasible move
(ties drawn), whatever the seed; the planner's node budget is a cap that a search needing
exactly that many nodes meets and one node fewer does not.
"""

from __future__ import annotations

import os

import numpy as np
import pytest

from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.agents.planner.models import make_human_model
from hg_marl.agents.robots.base import habit_stall_move
from hg_marl.core import Agent, World
from hg_marl.policy import Turn
from hg_marl.training.backends import check_workers, max_workers


def test_the_largest_worker_count_the_machine_allows_is_accepted_and_one_more_is_not() -> None:
    top = min(256, 4 * (os.cpu_count() or 1))  # the documented rule
    assert max_workers() == top
    assert check_workers(top) == top
    assert check_workers(1) == 1
    with pytest.raises(ValueError, match="--workers"):
        check_workers(top + 1)


def _turn(world: World) -> Turn:
    state = world.initial_state(np.random.default_rng(0))
    mask = np.zeros(world.n_actions(Agent.ROBOT), dtype=np.int8)
    mask[world.feasible_indices(state, Agent.ROBOT)] = 1
    return Turn(world, state, Agent.ROBOT, {"observation": np.zeros(1), "action_mask": mask})


def test_a_stalled_learning_robot_takes_its_habits_best_feasible_move_whatever_the_seed() -> None:
    world = World("paper2015")
    turn = _turn(world)
    wait = world.n_actions(Agent.ROBOT) - 1
    moves = [int(i) for i in np.flatnonzero(turn.mask) if i != wait]
    assert len(moves) >= 3  # goto(tape1), goto(tape3), goto(human) on this table
    q = np.zeros(world.n_actions(Agent.ROBOT))
    q[moves[-1]] = 1.0
    q[wait] = 5.0  # wait is never the way out, however valued
    assert {habit_stall_move(turn, q, np.random.default_rng(seed)) for seed in range(20)} == {moves[-1]}
    # two moves tied at the top: both drawn over the seeds, never the third
    q[moves[0]] = 1.0
    assert {habit_stall_move(turn, q, np.random.default_rng(seed)) for seed in range(40)} == {moves[0], moves[-1]}


def test_the_node_budget_caps_a_stochastic_plan_at_exactly_that_many_nodes() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    model = make_human_model("cooperative", p_idle=0.3)
    needed = Planner(world, PlannerConfig(), model).plan(state)
    assert needed.success and needed.nodes > 20
    n = needed.nodes
    assert Planner(world, PlannerConfig(node_budget=n), model).plan(state).success
    short = Planner(world, PlannerConfig(node_budget=n - 1), model).plan(state)
    assert not short.success and short.nodes == n - 1
    assert f"node budget of {n - 1} exhausted ({n - 1} nodes)" in short.reason
    tiny = Planner(world, PlannerConfig(node_budget=10), model).plan(state)
    assert not tiny.success and tiny.nodes == 10
