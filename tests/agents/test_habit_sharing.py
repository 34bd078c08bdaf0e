"""The habit's shared update on interchangeable objects, on hand-built ``paper2015`` states.

``paper2015``'s three tapes are interchangeable (one bin accepts them all). With
``share_objects`` the habit learns on the state with the tapes in canonical order, so a
TD step taken for ``pick(tape1)`` with tape1 on ``mat_left`` and tape2 on ``mat_right``
is also the value of ``pick(tape2)`` in the mirror state (tape2 on ``mat_left``, tape1
on ``mat_right``), and of nothing else there.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.base import LearningRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Turn

# spots: 0 mat_left, 2 mat_right, 4 human_mat_1; robot location 1 = table_left (reaches mat_left)
STATE = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
MIRROR = State(where=(2, 0, 4), robot_at=1, offer_by=-1, offer_obj=-1)


def _turn(world: World, state: State) -> Turn:
    mask = np.zeros(world.n_actions(Agent.ROBOT), dtype=np.int8)
    mask[world.feasible_indices(state, Agent.ROBOT)] = 1
    observation = {"observation": world.facts(state), "action_mask": mask}
    return Turn(world=world, state=state, agent=Agent.ROBOT, observation=observation)


def _pick(world: World, obj: int) -> int:
    return next(i for i, a in enumerate(world.actions(Agent.ROBOT)) if a.kind is Kind.PICK and a.obj == obj)


def _robot(world: World, share: bool) -> LearningRobot:
    robot = make_robot("habit", share_objects=share, q_config={"features": "tabular"})
    assert isinstance(robot, LearningRobot)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    return robot


def _q_after_one_step(share: bool) -> tuple[np.ndarray, np.ndarray]:
    """Q at STATE and at MIRROR after one terminal TD step of reward 1 on (STATE, pick(tape1))."""
    world = World("paper2015")
    robot = _robot(world, share)
    facts = robot._habit_facts(_turn(world, STATE))
    robot._remember(facts, _pick(world, 0))
    robot._learn_from(1.0, facts, done=True)
    q = {}
    for name, state in (("state", STATE), ("mirror", MIRROR)):
        facts = robot._habit_facts(_turn(world, state))
        q[name] = robot._to_robot_actions(robot.habit.q_values(facts))
    return q["state"], q["mirror"]


def test_a_shared_step_is_learnt_for_the_interchangeable_twin() -> None:
    world = World("paper2015")
    at_state, at_mirror = _q_after_one_step(share=True)
    alpha = 0.6  # the habit's default learning rate: Q moves by alpha * (1 - 0)
    expected_state = np.zeros(world.n_actions(Agent.ROBOT))
    expected_state[_pick(world, 0)] = alpha
    expected_mirror = np.zeros(world.n_actions(Agent.ROBOT))
    expected_mirror[_pick(world, 1)] = alpha  # tape2 is where tape1 was
    np.testing.assert_allclose(at_state, expected_state)
    np.testing.assert_allclose(at_mirror, expected_mirror)


def test_without_sharing_the_twin_learns_nothing() -> None:
    at_state, at_mirror = _q_after_one_step(share=False)
    world = World("paper2015")
    assert at_state[_pick(world, 0)] == pytest.approx(0.6)
    np.testing.assert_allclose(at_mirror, 0.0)


def test_shared_hybrid_spares_the_planner_sooner() -> None:
    """Cooperative human, 600 s: the shared habit is trusted in more decisions than the unshared one."""
    from hg_marl.agents.humans import make_human
    from hg_marl.training.runner import RunConfig, run

    config = RunConfig(duration=600, seed=0)
    shares = {
        share: run(make_robot("hybrid", share_objects=share), make_human("cooperative"), config).summary
        for share in (False, True)
    }
    assert shares[True]["tasks_solved"] >= shares[False]["tasks_solved"] - 1
    assert shares[True]["planner_share"] < shares[False]["planner_share"]
