"""Values that round 127's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from collections.abc import Iterator
from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents import member_models
from hg_marl.agents.humans.cooperative import CooperativeHuman
from hg_marl.agents.humans.noisy import NoisyHuman
from hg_marl.agents.member_models import MemberModels, clear_memo
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.robots import HybridRobot
from hg_marl.agents.robots import base as robot_base
from hg_marl.core import Agent, World
from tests.agents.test_pinned_robot_base_gate import WORLD, _state, _turn


def test_a_hybrid_habit_decision_in_wall_mode_is_charged_the_clock_read_around_it(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # A stand-in clock read twice around the habit's proposal: 0.5 then 1.25, so 0.75 s measured.
    # The "habit" criterion never consults the planner, so the decision's time is the habit's alone.
    reads = iter([0.5, 1.25])
    monkeypatch.setattr(robot_base, "time", SimpleNamespace(perf_counter=lambda: next(reads)))
    robot = HybridRobot(criterion="habit", cost=CostModel(mode="wall"))
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    robot.act(_turn(_state()))
    assert robot.last_decision is not None
    assert not robot.last_decision.planner_consulted
    assert robot.last_decision.decision_time == pytest.approx(0.75)


@pytest.fixture
def stub_oracle(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[str]]:
    """The oracle replaced by a stand-in that records the specs it solves; a fresh process memo."""
    clear_memo()
    solved: list[str] = []

    def fake(world: World, spec: str, **kwargs: object) -> object:
        solved.append(spec)
        return object()

    monkeypatch.setattr(member_models, "oracle_rate", fake)
    yield solved
    clear_memo()


def test_the_solved_count_counts_the_results_taken_not_the_members_index(stub_oracle: list[str]) -> None:
    # Three members; only the third (index 2) is consulted, twice: one result taken, so 1 (not 3).
    # Then the first: two results taken in all.
    models = MemberModels(("cooperative", "preference", "preference:p_idle=0.5"), "")
    models.cache = None
    models.reset(World("paper2015"))
    models.result(2)
    models.result(2)
    assert models.solved == 1
    models.result(0)
    assert models.solved == 2
    assert stub_oracle == ["preference:p_idle=0.5", "cooperative"]


def test_a_negative_charge_is_refused_naming_the_value_given() -> None:
    with pytest.raises(ValueError, match=r"CostModel\.habit: expected a finite non-negative number, got -0\.25"):
        CostModel(habit=-0.25)


def test_the_noisy_human_at_temperature_zero_answers_the_robots_action_as_the_cooperative_one() -> None:
    # The reference is the cooperative human itself (temperature 0 is documented as exactly it), at
    # every robot action of the initial state; at least one of them changes its answer from the one
    # it gives when the robot's action is unknown (-1), so the robot's action must be passed on.
    # The states: a seeded random walk of three cycles from a seeded start of paper2015, and after
    # each feasible robot action there, the state the human answers in.
    world = World("paper2015")
    coop, noisy = CooperativeHuman(), NoisyHuman(temperature=0.0)
    rng = np.random.default_rng(0)
    state = world.initial_state(np.random.default_rng(0))
    changed = 0
    for _ in range(3):
        for a in world.feasible_indices(state, Agent.ROBOT):
            mid = world.step(state, Agent.ROBOT, a).state
            answer = coop.distribution(world, mid, a)
            changed += answer != coop.distribution(world, mid, -1)
            assert noisy.distribution(world, mid, a) == answer
        state = world.step(state, Agent.ROBOT, int(rng.choice(world.feasible_indices(state, Agent.ROBOT)))).state
        state = world.step(state, Agent.HUMAN, int(rng.choice(world.feasible_indices(state, Agent.HUMAN)))).state
    assert changed > 0
