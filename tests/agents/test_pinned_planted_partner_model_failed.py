"""Pinned against a planted bug: a partner's answer to a failed robot action is counted as one.

:func:`~hg_marl.agents.partner_model.observe_move` replays the robot's previous action; when
it failed, the partner answered to nothing the robot did, and the learned model keeps that
answer in the ``failed`` context (robot kind ``-1``), not in the context of the kind the
robot tried. Worked by hand on the first table of ``paper2015`` (seed 0): the human holds
nothing, nothing is offered, the robot stands at location 0 (the handover place is 3). The
robot tries to take object 0 while nothing is offered, which fails and changes nothing; the
human then picks. The model's only counts are ``{(False, False, False, -1): {pick: 1.0}}``,
and with ``alpha = 1`` over the human's two feasible kinds (pick, wait) it predicts the pick
after a failed robot action with ``(1 + 1) / (1 + 1 + 0 + 1) = 2/3``. A robot action that
succeeds (wait) is counted under its own kind, for contrast.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.partner_model import FAILED, LearnedPartner, observe_move
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Turn


def first_table(world: World) -> State:
    state = world.initial_state(np.random.default_rng(0))
    assert world.holding(state, Agent.HUMAN) == -1 and state.offer_by == -1
    assert state.robot_at not in world.scenario.handover_locations
    return state


def index_of(world: World, agent: Agent, kind: Kind, obj: int) -> int:
    return next(i for i, a in enumerate(world.actions(agent)) if a.kind is kind and a.obj == obj)


def human_pick(world: World, state: State) -> int:
    """The human's only feasible pick at ``state`` (its other feasible kind is wait)."""
    acts = world.actions(Agent.HUMAN)
    feasible = world.feasible_indices(state, Agent.HUMAN)
    assert {acts[i].kind for i in feasible} == {Kind.PICK, Kind.WAIT}
    (pick,) = (i for i in feasible if acts[i].kind is Kind.PICK)
    return pick


def observe(world: World, state: State, robot_action: int, human_action: int) -> LearnedPartner:
    """A fresh model after one observed cycle: the robot's ``robot_action``, then the human's answer."""
    after_robot = world.step(state, Agent.ROBOT, robot_action).state
    after_human = world.step(after_robot, Agent.HUMAN, human_action).state
    turn = Turn(world, after_human, Agent.ROBOT, {}, last_actions=(robot_action, human_action))
    model = LearnedPartner(alpha=1.0, forget=0.95)
    observe_move(model, world, (state, robot_action), turn)
    return model


def test_an_answer_to_a_failed_robot_action_is_counted_in_the_failed_context() -> None:
    world = World("paper2015")
    state = first_table(world)
    take = index_of(world, Agent.ROBOT, Kind.TAKE, 0)  # nothing is offered: the take must fail
    assert take not in world.feasible_indices(state, Agent.ROBOT)
    pick = human_pick(world, state)  # the failed take changed nothing: the human answers at the same state
    model = observe(world, state, take, pick)
    assert model.counts == {(False, False, False, FAILED): {int(Kind.PICK): 1.0}}
    assert model.predict(world, state, FAILED, pick) == pytest.approx(2 / 3)
    assert model.predict(world, state, take, pick) == pytest.approx(1 / 2)  # the take's context learnt nothing


def test_an_answer_to_a_successful_robot_action_is_counted_under_its_kind() -> None:
    world = World("paper2015")
    state = first_table(world)
    wait = index_of(world, Agent.ROBOT, Kind.WAIT, -1)
    assert wait in world.feasible_indices(state, Agent.ROBOT)
    pick = human_pick(world, state)
    model = observe(world, state, wait, pick)
    assert model.counts == {(False, False, False, int(Kind.WAIT)): {int(Kind.PICK): 1.0}}
