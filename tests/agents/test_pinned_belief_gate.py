"""When the belief robot counts a wait as unexplained, pinned for the mutation gate.

Expected values by hand from the rule (agents/robots/belief.py): the run of both-waited
cycles only grows when the robot's previous turn was a ``wait`` at this very state; then
each cycle multiplies it by ``(1 - eps) * p_wait + eps / n``. ``p_wait`` is read from
the member's own answer distribution (the model's input), ``eps = 0.05``.
A previous turn at another state, or not a wait, starts the run afresh (not unexplained).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, World
from hg_marl.policy import Turn


def _robot(tmp_path: Path, world: World) -> BeliefRobot:
    path = tmp_path / "population.toml"
    members = '[[members]]\nname = "coop"\nsplit = "train"\nspec = "cooperative"\n'
    path.write_text(f'name = "t"\nscenario = "paper2015"\n\n{members}')
    robot = BeliefRobot(population=str(path), splits="train", unknown=0.0)
    for human in robot.posterior.humans:
        human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    robot._wait = world.n_actions(Agent.ROBOT) - 1
    robot._wait_run = 1.0
    return robot


def test_a_wait_answered_by_a_wait_at_the_same_unfinished_table_is_unexplained(tmp_path: Path) -> None:
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    mid = world.step(state, Agent.ROBOT, robot._wait).state
    n = len(world.feasible_indices(mid, Agent.HUMAN))
    assert n >= 2 and not world.is_clean(state)
    human = robot.posterior.humans[0]
    p_wait = dict(human.distribution(world, mid, -1)).get(world.n_actions(Agent.HUMAN) - 1, 0.0)
    p = 0.95 * p_wait + 0.05 / n  # the rule's formula, eps = 0.05 (the robot's default)
    turn = Turn(world, state, Agent.ROBOT, {})
    robot._prev = (state, robot._wait)
    assert robot._unexplained_waits(turn, [1.0]) == (p < 0.05)
    assert robot._wait_run == pytest.approx(p)
    assert robot._unexplained_waits(turn, [1.0]) == (p * p < 0.05)  # a second such cycle multiplies again
    assert robot._wait_run == pytest.approx(p * p)
    assert p < 1.0  # so the run differs from a fresh one


def test_a_previous_turn_elsewhere_or_not_waiting_starts_afresh(tmp_path: Path) -> None:
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    other = world.initial_state(np.random.default_rng(1))
    assert other != state
    turn = Turn(world, state, Agent.ROBOT, {})
    for prev in ((other, robot._wait), (state, 0)):
        robot._prev = prev
        robot._wait_run = 0.5
        assert not robot._unexplained_waits(turn, [1.0])
        assert robot._wait_run == 1.0


def test_a_turn_without_a_human_action_is_no_evidence(tmp_path: Path) -> None:
    """``last_actions[1] == -1`` (the Turn's documented "no action yet") updates nothing, whatever came before."""
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    robot._prev = (state, robot._wait)
    before = list(robot.posterior.posterior())
    calls: list[int] = []
    robot.posterior.observe = lambda *args: calls.append(1)  # type: ignore[method-assign]
    robot._observe(Turn(world, state, Agent.ROBOT, {}, last_actions=(robot._wait, -1)))
    assert calls == [] and list(robot.posterior.posterior()) == before
