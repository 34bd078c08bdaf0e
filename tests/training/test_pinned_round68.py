"""The values round 68's missed planted bugs changed (``mutation/planted.py``, FRESH68), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

import numpy as np

import hg_marl
from hg_marl.agents.meta.controller import Decision
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.canonical import CanonicalView
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn
from hg_marl.wrappers import flatten_v0


def test_a_state_with_its_first_tape_in_place_and_the_others_swapped_is_relabelled() -> None:
    # paper2015's three tapes are interchangeable (one bin takes them all) and the canonical
    # state sorts them by place code. By hand: tapes on places (0, 4, 2) sort to (0, 2, 4), the
    # canonical tape c being tape (0, 2, 1)[c]: tape 0 stays, tapes 1 and 2 swap. The robot's
    # per-tape actions are numbered picks 0-2, throws 3-5, gives 6-8, takes 9-11, so canonical
    # pick(1) stands for pick(2) and back (a swap is its own inverse); wait (17) stays put.
    world = World("paper2015")
    view = CanonicalView(world, Agent.ROBOT)
    state = State(where=(0, 4, 2), robot_at=1, offer_by=-1, offer_obj=-1)
    sorted_state = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    facts, to_original, to_canonical = view.view(state, world.facts(state))
    np.testing.assert_array_equal(facts, world.facts(sorted_state))
    assert to_original is not None and to_canonical is not None
    for first in (0, 3, 6, 9):
        assert [int(to_original[first + c]) for c in range(3)] == [first + o for o in (0, 2, 1)]
        assert [int(to_canonical[first + o]) for o in range(3)] == [first + c for c in (0, 2, 1)]
    assert int(to_original[17]) == 17 and int(to_canonical[17]) == 17


def habit_robot_turns(turns: int = 10) -> list[tuple[int, Decision | None]]:
    """A habit robot's actions and logged decisions over ``turns`` turns at paper2015's first table."""
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    robot = make_robot("habit")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(1))
    out = []
    for _ in range(turns):
        observation = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
        action = robot.act(Turn(world, state, Agent.ROBOT, observation))
        out.append((action, robot.last_decision))
    return out


def test_the_habit_robots_decisions_log_the_habits_proposal_as_the_action_taken() -> None:
    # The habit robot is "the model-free Q-learner alone": every action it takes is its habit's
    # proposal, and Decision.habit_action is "the habit's proposal (-1: no habit)". So each
    # decision's habit_action is the executed action, never -1 (checked over ten turns).
    for action, decision in habit_robot_turns():
        assert decision is not None and decision.expert == "habit"
        assert decision.habit_action == decision.action == action != -1


def test_the_flat_wrappers_info_mode_keeps_the_wrapped_envs_info_beside_the_mask() -> None:
    # The spec sheet: with mask="info", infos are "the wrapped env's infos; each also carries
    # the agent's current mask". So, after the reset and after a step, every agent's info is
    # the inner env's info (clock, failed, events, ...) plus one action_mask entry.
    env = flatten_v0(hg_marl.env(), mask="info")
    env.reset(seed=3)
    for _ in range(2):
        for agent in env.agents:
            info = env.infos[agent]
            inner = env.env.infos[agent]
            assert {"clock", "failed", "events"} <= set(inner)
            assert set(info) == {*inner, "action_mask"}
            assert {k: v for k, v in info.items() if k != "action_mask"} == inner
        agent = env.agent_selection
        env.step(int(np.flatnonzero(env.infos[agent]["action_mask"])[0]))
