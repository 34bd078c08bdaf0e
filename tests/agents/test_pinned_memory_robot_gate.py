"""The memory robot's choice, pinned with a fixed policy on one hand-made paper2015 state.

The policy is a net that returns the same logits whatever it sees, so every expected
action follows from the logits and the rules alone. The state: the robot at ``bin_side``
(it reaches nothing but the bin from there), tape1 on ``mat_left``, tape2 on ``mat_right``
(both reached from a table location), tape3 on ``human_mat_1`` (out of the robot's reach
everywhere), no offer. The robot holds nothing, so no pick, throw, give or take; its
feasible moves are ``goto`` tape1 (12), ``goto`` tape2 (13), ``goto`` the human (16, to
``human_side``) and ``wait`` (17); ``goto`` tape3 (14) and ``goto`` the bin (15, already in
reach) are not. Masked logits never win, however large.

Sampled choices are counted over many draws and compared with the softmax worked by hand
(a tolerance of several binomial standard deviations; the draws are seeded). Times come
from a fake clock: the planning time is the difference of its two readings.
"""

from __future__ import annotations

import math
from collections import Counter
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

import hg_marl.agents.robots.memory as memory_module
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.robots.memory import MemoryRobot
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn

GOTO_TAPE1, GOTO_TAPE2, GOTO_TAPE3, GOTO_BIN, GOTO_HUMAN, WAIT = 12, 13, 14, 15, 16, 17
FEASIBLE = (GOTO_TAPE1, GOTO_TAPE2, GOTO_HUMAN, WAIT)
STATE = State((0, 2, 4), 0)
"""tape1 on mat_left, tape2 on mat_right, tape3 on human_mat_1; the robot at bin_side."""


class FixedNet:
    """A policy with memory that ignores its input: the same logits at every step."""

    def __init__(self, logits: dict[int, float], n_actions: int = 18) -> None:
        self.logits = np.full((1, n_actions), -5.0)
        for action, value in logits.items():
            self.logits[0, action] = value

    def initial(self, n: int) -> np.ndarray:
        return np.zeros((n, 1))

    def step(self, obs: np.ndarray, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return self.logits.copy(), h


def the_turn(world: World) -> Turn:
    mask = np.zeros(world.n_actions(Agent.ROBOT), dtype=np.int8)
    mask[list(FEASIBLE)] = 1
    facts = np.asarray(world.facts(STATE), dtype=np.float32)
    return Turn(world, STATE, Agent.ROBOT, {"observation": facts, "action_mask": mask})


def robot(logits: dict[int, float], seed: int = 0, **kwargs: Any) -> tuple[MemoryRobot, Turn]:
    world = World("paper2015")
    assert world.n_actions(Agent.ROBOT) == 18
    assert tuple(world.feasible_indices(STATE, Agent.ROBOT)) == FEASIBLE  # the hand-worked reach
    r = MemoryRobot(net=FixedNet(logits), **kwargs)
    r.reset(world, Agent.ROBOT, np.random.default_rng(seed))
    return r, the_turn(world)


def test_the_best_feasible_logit_wins_over_larger_masked_ones() -> None:
    # every feasible logit is negative, the infeasible goto tape3 and goto bin score higher
    r, turn = robot({GOTO_TAPE3: 9.0, GOTO_BIN: 8.0, GOTO_TAPE1: -3.0, GOTO_TAPE2: -1.0, GOTO_HUMAN: -2.0, WAIT: -4.0})
    assert r.act(turn) == GOTO_TAPE2
    assert r.last_decision is not None and r.last_decision.expert == "memory"


def test_sampling_follows_the_softmax_of_the_feasible_logits() -> None:
    # goto tape1 and goto tape2 differ by log 3: probabilities 3/4 and 1/4 (the other two
    # feasible moves are e^-52 below, never drawn); masked logits are out however large
    logits = {GOTO_TAPE1: 2.0, GOTO_TAPE2: 2.0 - math.log(3.0), GOTO_HUMAN: -50.0, WAIT: -50.0, GOTO_BIN: 9.0}
    r, turn = robot(logits, seed=7, deterministic=False, unstall=0)
    draws = 4000
    counts = Counter(r.act(turn) for _ in range(draws))
    assert set(counts) == {GOTO_TAPE1, GOTO_TAPE2}
    # one binomial standard deviation is sqrt(3/16 / 4000), under 0.007
    assert counts[GOTO_TAPE1] / draws == pytest.approx(0.75, abs=0.03)
    assert counts[GOTO_TAPE2] / draws == pytest.approx(0.25, abs=0.03)


class _Clock:
    """perf_counter readings 3.0, 10.0, 17.0, ...: each decision takes 7 s on this clock."""

    def __init__(self) -> None:
        self.now = 3.0

    def perf_counter(self) -> float:
        value = self.now
        self.now += 7.0
        return value


@pytest.mark.parametrize("deterministic", [True, False])
def test_the_planning_time_is_the_difference_of_two_clock_readings(
    monkeypatch: pytest.MonkeyPatch, deterministic: bool
) -> None:
    # goto human 25 above every other logit: sampled too, another move has a chance under 1e-10
    r, turn = robot({GOTO_HUMAN: 20.0}, deterministic=deterministic, cost=CostModel(mode="wall"))
    monkeypatch.setattr(memory_module, "time", SimpleNamespace(perf_counter=_Clock().perf_counter))
    assert r.act(turn) == GOTO_HUMAN
    decision = r.last_decision
    assert decision is not None
    assert (decision.expert, decision.planning_time, decision.decision_time) == ("memory", 7.0, 7.0)


def test_the_habit_constant_is_charged_by_default(monkeypatch: pytest.MonkeyPatch) -> None:
    r, turn = robot({GOTO_HUMAN: 1.0})
    monkeypatch.setattr(memory_module, "time", SimpleNamespace(perf_counter=_Clock().perf_counter))
    r.act(turn)
    assert r.last_decision is not None
    assert (r.last_decision.planning_time, r.last_decision.decision_time) == (7.0, CostModel().habit)


def test_the_guard_takes_the_policys_next_choices_after_k_unchanged_turns(monkeypatch: pytest.MonkeyPatch) -> None:
    # the policy's order: goto human 1.0, wait 0.5, goto tape2 0.0, goto tape1 -0.5. The state
    # never changes: turns 1 and 2 (unchanged 0, 1) play the policy; from turn 3 (unchanged 2 =
    # K) the guard plays the feasible non-wait moves without the one the policy keeps choosing,
    # best first, one further at each guard move: goto tape2, goto tape1, goto tape2 again
    r, turn = robot({GOTO_HUMAN: 1.0, WAIT: 0.5, GOTO_TAPE2: 0.0, GOTO_TAPE1: -0.5}, unstall=2)
    monkeypatch.setattr(memory_module, "time", SimpleNamespace(perf_counter=_Clock().perf_counter))
    played = []
    for _ in range(5):
        played.append(r.act(turn))
        assert r.last_decision is not None
        played.append(r.last_decision.expert)
    assert played == [
        *(GOTO_HUMAN, "memory"),
        *(GOTO_HUMAN, "memory"),
        *(GOTO_TAPE2, "guard"),
        *(GOTO_TAPE1, "guard"),
        *(GOTO_TAPE2, "guard"),
    ]
    assert r.last_decision is not None
    assert (r.last_decision.reason, r.last_decision.decision_time) == ("no_progress", CostModel().habit)
    # a new run starts the count afresh
    r.reset(turn.world, Agent.ROBOT, np.random.default_rng(0))
    assert [r.act(turn) for _ in range(3)] == [GOTO_HUMAN, GOTO_HUMAN, GOTO_TAPE2]


def test_unstall_zero_plays_the_policy_as_trained() -> None:
    r, turn = robot({WAIT: 1.0}, unstall=0)
    assert [r.act(turn) for _ in range(20)] == [WAIT] * 20


def test_by_default_the_guard_moves_after_eight_unchanged_turns(monkeypatch: pytest.MonkeyPatch) -> None:
    # the default K of the memory robot is 8 (docs/learned-robots.md, measured): at one state,
    # turns 1-8 (unchanged 0 to 7) play the policy, turns 9 and 10 (unchanged 8, 9) are the guard's
    r, turn = robot({GOTO_HUMAN: 1.0, WAIT: 0.5, GOTO_TAPE2: 0.0, GOTO_TAPE1: -0.5})
    monkeypatch.setattr(memory_module, "time", SimpleNamespace(perf_counter=_Clock().perf_counter))
    experts = []
    for _ in range(10):
        r.act(turn)
        assert r.last_decision is not None
        experts.append(r.last_decision.expert)
    assert experts == ["memory"] * 8 + ["guard"] * 2
