"""The noisy human's scores, default temperature, softmax and per-world memo, pinned for the mutation gate.

Expected values are worked by hand from the rules: a cycle lasts as long as the longer of
its two actions, and an episode ends when the robot waits (1 s) on a clean table, so an
action that clears the table scores its cycle plus that closing wait. Durations (both
scenarios): pick, throw, place 2 s, take 1.5 s, goto 3 s, give and wait 1 s. The softmax is
checked as a property: any two actions' probabilities are in the ratio
``exp(-(c_i - c_j) / temperature)`` and they sum to one.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.noisy import NoisyHuman
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.durations import Durations
from hg_marl.policy import Turn

PAPER = World("paper2015")
ROBO = World("roboergosum")
FIRST = PAPER.initial_state(np.random.default_rng(0))
"""tape1 on mat_left, tape2 on human_mat_1, tape3 on mat_right; the human may pick tape2 (1) or wait (30)."""
LAST = State((7, 7, 7, 10, 8, 8), 0)
"""roboergosum: every object in its bin (green_bin 7, blue_bin 8) but blue1, in the human's hand (10)."""
THROW_BLUE1 = 9  # throw(o) = 6 + o on roboergosum's six objects


def check_softmax(dist: list[tuple[int, float]], scores: dict[int, float], temperature: float) -> None:
    """The answer covers the scored actions, sums to one, and weighs them by ``exp(-c / T)``."""
    p = dict(dist)
    assert set(p) == set(scores)
    assert math.fsum(p.values()) == pytest.approx(1.0, abs=1e-12)
    for i in p:
        for j in p:
            assert p[i] / p[j] == pytest.approx(math.exp(-(scores[i] - scores[j]) / temperature), rel=1e-9)


def test_the_setting_is_the_one_the_docstring_names() -> None:
    assert State((0, 4, 2), 0) == FIRST
    assert PAPER.feasible_indices(FIRST, Agent.HUMAN) == [1, 30]
    assert ROBO.action_names[Agent.HUMAN][THROW_BLUE1] == "throw(blue1)"
    assert ROBO.hand[Agent.HUMAN] == 10


def test_an_action_that_clears_the_table_scores_its_cycle_and_the_closing_wait() -> None:
    """throw(blue1) clears the table: 2 s of throw (nothing else under way) and the robot's
    closing wait of 1 s, 3 s; with the robot's goto (3 s) under way the cycle lasts 3 s: 4 s."""
    human = NoisyHuman()
    assert human.scores(ROBO, LAST)[THROW_BLUE1] == pytest.approx(3.0, abs=1e-12)
    goto = next(i for i, a in enumerate(ROBO.actions(Agent.ROBOT)) if a.kind is Kind.GOTO)
    assert human.scores(ROBO, LAST, goto)[THROW_BLUE1] == pytest.approx(4.0, abs=1e-12)


def test_the_robots_first_action_index_counts_as_a_robot_action() -> None:
    """Robot action 0 is pick(tape1), 2 s: under it the human's 1-s wait makes a 2-s cycle
    (one second more than alone), its 2-s pick a 2-s cycle (no change). Index 0 is an action,
    not "unknown" (only negative indices are)."""
    human = NoisyHuman()
    assert PAPER.actions(Agent.ROBOT)[0].kind is Kind.PICK
    alone, under_pick = human.scores(PAPER, FIRST), human.scores(PAPER, FIRST, 0)
    assert under_pick[30] == pytest.approx(alone[30] + 1.0, abs=1e-12)
    assert under_pick[1] == pytest.approx(alone[1], abs=1e-12)


def test_the_default_temperature_is_one_second() -> None:
    """``NoisyHuman()`` (and the registry's ``noisy``) weigh actions by ``exp(-c / 1 s)``."""
    for human in (NoisyHuman(), make_human("noisy")):
        assert isinstance(human, NoisyHuman)
        check_softmax(human.distribution(PAPER, FIRST), human.scores(PAPER, FIRST), 1.0)


def test_the_softmax_weighs_actions_by_their_score_differences_however_far_apart() -> None:
    """On the last object the scores run from 3 s (the throw) to more than twice that (a place
    back on the table), and each pair keeps the ratio ``exp(-(c_i - c_j))``."""
    human = NoisyHuman(temperature=1.0)
    scores = human.scores(ROBO, LAST)
    assert max(scores.values()) > 2 * min(scores.values())
    check_softmax(human.distribution(ROBO, LAST), scores, 1.0)


def test_a_cold_temperature_still_gives_a_distribution() -> None:
    """At 0.05 s the two actions of the first layout, a second apart, weigh ``exp(-20)`` to 1:
    the weights are taken relative to the best score, so none underflows to nothing."""
    human = NoisyHuman(temperature=0.05)
    scores = human.scores(PAPER, FIRST)
    assert abs(scores[1] - scores[30]) == pytest.approx(1.0, abs=1e-12)
    check_softmax(human.distribution(PAPER, FIRST), scores, 0.05)


def test_answers_remembered_in_one_world_are_not_given_in_another() -> None:
    """The same state in paper2015 and in paper2015 with a 3-s wait: the slower wait reverses
    which action is likelier; a human that answered in the first world answers in the second
    as a fresh human does."""
    slow = World("paper2015", Durations(wait=3.0))
    human = NoisyHuman()
    first = human.distribution(PAPER, FIRST)
    fresh = NoisyHuman().distribution(slow, FIRST)
    assert dict(first)[30] > dict(first)[1] and dict(fresh)[30] < dict(fresh)[1]
    assert human.distribution(slow, FIRST) == fresh
    assert human.distribution(PAPER, FIRST) == first


def test_a_temperature_cold_enough_to_underflow_lists_only_the_actions_it_may_take() -> None:
    """At 0.001 s the weaker action of the first layout weighs ``exp(-1000)``, which is 0.0 in
    floating point: the answer lists the best action alone, with probability 1 (an answer
    lists only actions it may take)."""
    human = NoisyHuman(temperature=0.001)
    assert math.exp(-1.0 / 0.001) == 0.0
    best = min(human.scores(PAPER, FIRST).items(), key=lambda kv: kv[1])[0]
    assert human.distribution(PAPER, FIRST) == [(best, 1.0)]


class _Spy(NoisyHuman):
    """A noisy human that notes the robot action each answer is asked under."""

    def __init__(self) -> None:
        super().__init__()
        self.asked: list[int] = []

    def distribution(self, world: World, state: State, robot_action: int = -1) -> list[tuple[int, float]]:
        self.asked.append(robot_action)
        return super().distribution(world, state, robot_action)


def test_when_it_acts_the_noisy_human_is_told_the_robots_action_under_way() -> None:
    """The noisy human scores the cycle with the robot's action (``uses_robot_action``): a turn
    whose robot action of the cycle is the goto (succeeded: no failure event) asks the answer
    under that goto, not under "unknown" (-1)."""
    goto = next(i for i, a in enumerate(PAPER.actions(Agent.ROBOT)) if a.kind is Kind.GOTO)
    state = PAPER.step(FIRST, Agent.ROBOT, goto).state
    obs = {"observation": PAPER.facts(state), "action_mask": PAPER.mask(state, Agent.HUMAN)}
    human = _Spy()
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    human.act(Turn(PAPER, state, Agent.HUMAN, obs, last_actions=(goto, -1)))
    assert human.asked == [goto]
