"""Values that round 118's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.member_models import MemberModels
from hg_marl.agents.planner import Planner
from hg_marl.core import Agent, Kind, State, World
from hg_marl.training.baselines.comparison import summarise
from tests.training.test_comparison import REFERENCES, config


def test_each_members_one_step_model_answers_as_that_member() -> None:
    # Member 0 is the preference human, member 1 the same with p_idle=0.5. After the robot's wait
    # at paper2015's first table, member 0 makes its one planned move (the table changes, a 2 s
    # cycle); member 1 idles half the time (its own wait: the table unchanged, a 1 s cycle) and
    # otherwise makes that same move: two answers of probability 0.5 each.
    world = World("paper2015")
    members = MemberModels(("preference", "preference:p_idle=0.5"))
    members.reset(world)
    state = world.initial_state(np.random.default_rng(0))
    wait = world.n_actions(Agent.ROBOT) - 1
    first = [(nxt == state, p, tau) for nxt, p, tau in members.model(0).replies(state, 0.0, wait)]
    second = sorted((nxt == state, p, tau) for nxt, p, tau in members.model(1).replies(state, 0.0, wait))
    assert first == [(False, 1.0, 2.0)]
    assert second == [(False, 0.5, 2.0), (True, 0.5, 1.0)]


def test_the_planner_offers_a_place_on_each_class_of_placemat() -> None:
    # roboergosum, the human holding green1 (its hand is place 10), green2 and green3 on placemats
    # 1 and 2 (places 0, 1), the blue tapes in the blue bin (place 8), the robot at ROBOT_LOC.
    # The placemats the human reaches, all free, are 3 to 7 (places 2 to 6); by the robot's reach
    # they fall in three classes: placemat3 (ROBOT_LOC), placemats 4 and 5 (both locations),
    # placemats 6 and 7 (SECOND_LOC). Interchangeable spots are tried once, the first free one of
    # each class: the human's places are on places 2, 3 and 5, not on one placemat only.
    world = World("roboergosum")
    space = Planner(world).space
    state = State((10, 0, 1, 8, 8, 8), 0, -1, -1)
    actions = world.table.actions[Agent.HUMAN]
    places = [actions[i].target for i in space.candidates(state, Agent.HUMAN) if actions[i].kind is Kind.PLACE]
    assert places == [2, 3, 5]


def test_the_steps_to_reach_a_level_are_the_seeds_median() -> None:
    # Three ppo seeds against lazy (oracle 100 tasks/h) first reach 50 tasks/h at 1000, 2000 and
    # 6000 steps: the median is 2000 (their mean would be 3000); each reaches 90 at 6000.
    curves = (
        [[0, 0.0], [1000, 60.0], [6000, 90.0]],
        [[0, 0.0], [1000, 10.0], [2000, 55.0], [6000, 95.0]],
        [[0, 0.0], [1000, 10.0], [2000, 20.0], [6000, 92.0]],
    )
    cells = [{"algo": "ppo", "human": "lazy", "seed": s, "curve": c} for s, c in enumerate(curves)]
    (row,) = [r for r in summarise(config(3), cells, REFERENCES) if r["agent"] == "ppo" and r["human"] == "lazy"]
    assert row["steps_to_50"] == pytest.approx(2000.0)
    assert row["steps_to_90"] == pytest.approx(6000.0)
