"""The compiled planner robot beyond its budget: one cold plan per state up to relabelling.

A scenario with more robot-turn states than ``max_states`` (``roboergosum`` under the
default budget) is planned once per canonical state (interchangeable objects relabelled
in place order) and the answer mapped back. The expected answers here are computed
state by state with the scalar :class:`~hg_marl.core.relabel.Relabel` and a cold planner,
not with the packed arrays the compiler uses. ``paper2015`` has 1,892 robot-turn states,
328 up to relabelling its three tapes, so a budget of 1,000 takes the canonical path.
"""

from __future__ import annotations

import pytest

from hg_marl.agents import compiled_robot
from hg_marl.agents.compiled import CompileError
from hg_marl.agents.compiled_robot import enumerate_plans, planner_action, robot_states
from hg_marl.core import Agent, State, World
from hg_marl.core.relabel import Relabel


def test_over_the_budget_each_state_gets_its_canonical_states_cold_answer_mapped_back() -> None:
    world = World("paper2015")
    plans = enumerate_plans(world, max_states=1000)
    relabel = Relabel(world)
    assert len(plans) == len(robot_states(world)) == 1892
    cold: dict[State, int] = {}
    ties = 0
    for state, action in plans.items():
        canonical, orig = relabel.canonical(state)
        if canonical not in cold:
            cold[canonical] = planner_action(world, canonical)
        assert action == relabel.action_back(int(Agent.ROBOT), cold[canonical], orig)
        assert action in world.feasible_indices(state, Agent.ROBOT)
        own = planner_action(world, state) if canonical == state else None
        if own is not None:
            assert action == own  # a state that is its own canonical form: exactly its cold answer
        elif action != (own := planner_action(world, state)):
            # a tie between interchangeable objects: the same kind of action on an object of the same class
            spec, other = world.table.specs[Agent.ROBOT][action], world.table.specs[Agent.ROBOT][own]
            assert spec.kind is other.kind
            mine = spec.obj if spec.obj >= 0 else spec.target
            theirs = other.obj if other.obj >= 0 else other.target
            assert any(mine in members and theirs in members for members in relabel.classes)
            ties += 1
    assert len(cold) == 328
    assert 0 < ties < len(plans)  # some ties are broken differently, not most answers


def test_more_canonical_states_than_the_budget_is_refused_before_any_plan(monkeypatch: pytest.MonkeyPatch) -> None:
    def no_planning(*args: object) -> int:
        raise AssertionError("planned before the budget was checked")

    monkeypatch.setattr(compiled_robot, "planner_action", no_planning)
    refused = r"1892 robot-turn states, 328 up to relabelling .*over the 327 .*\(max_states\)"
    with pytest.raises(CompileError, match=refused):
        enumerate_plans(World("paper2015"), max_states=327)


def test_within_the_budget_every_state_gets_its_own_cold_answer() -> None:
    world = World("forced_coordination")
    plans = enumerate_plans(world)  # 845 states: within the default budget
    assert len(plans) == 845
    assert all(action == planner_action(world, state) for state, action in plans.items())


def test_a_budget_of_exactly_the_states_still_gives_each_its_own_cold_answer() -> None:
    """1,892 states and a budget of 1,892 cold plans: no relabelling (which would move the ties)."""
    world = World("paper2015")
    plans = enumerate_plans(world, max_states=1892)
    assert len(plans) == 1892
    assert all(action == planner_action(world, state) for state, action in plans.items())
