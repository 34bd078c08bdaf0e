"""Round 56's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.habit import QLearner, QLearnerConfig
from hg_marl.agents.humans.preference import PreferenceHuman
from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Turn

PAPER = World("paper2015")


def robot_turn(state: State, reward: float = 0.0) -> Turn:
    obs = {"observation": PAPER.facts(state), "action_mask": PAPER.mask(state, Agent.ROBOT)}
    return Turn(PAPER, state, Agent.ROBOT, obs, reward=reward)


# --- agents/robots/base.py ---


def test_a_truncated_episodes_last_td_step_bootstraps_from_the_last_state() -> None:
    # base.py's module docstring: call ``end`` with ``terminated=False`` on truncation, which
    # bootstraps from the last state, and the habit's docstring gives the step:
    # delta = r + gamma * max_a' Q(s', a') * (1 - done) - Q(s, a), Q(s, a) += alpha * delta
    # (tabular). Here Q(s, a) = 0, r = 0 and max_a' Q(s', .) = 1 (set in the test), so a
    # truncation moves Q(s, a) to 0.6 * 0.9 * 1 = 0.54 (worked by hand) and a termination
    # leaves it at 0.
    config = QLearnerConfig(alpha=0.6, gamma=0.9, features="tabular")
    first = PAPER.initial_state(np.random.default_rng(0))
    # a next state whose facts differ from the first's (so its Q-values are another row)
    nexts = (PAPER.step(first, Agent.ROBOT, i).state for i in PAPER.feasible_indices(first, Agent.ROBOT))
    last = next(s for s in nexts if not np.array_equal(PAPER.facts(first), PAPER.facts(s)))
    results = {}
    for terminated in (False, True):
        learner = QLearner(PAPER.n_facts, PAPER.n_actions(Agent.ROBOT), config)
        robot = HabitRobot(learner=learner)
        robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(1))
        action = robot.act(robot_turn(first))
        learner.weights[:, learner.state_code(PAPER.facts(last))] = 0.0
        learner.weights[0, learner.state_code(PAPER.facts(last))] = 1.0  # max_a' Q(s', a') = 1
        robot.end(robot_turn(last), terminated=terminated)
        results[terminated] = float(learner.q_values(PAPER.facts(first))[action])
    assert results[False] == np.float64(0.6 * 0.9 * 1.0)
    assert results[True] == 0.0


# --- agents/humans/preference.py ---


def test_no_preferred_colour_gives_no_colour_bonus_to_colourless_objects() -> None:
    # preference.py: "colour: objects of this colour get colour_bonus when picked ('' for
    # none ...)", so with colour='' the bonus applies to no object, and a human with a large
    # colour_bonus scores every action as the same human with colour_bonus=0. paper2015's
    # objects are all colourless (''), the case where '' must not read as a colour.
    assert set(PAPER.scenario.object_colours) == {""}
    state = PAPER.initial_state(np.random.default_rng(0))
    plain = PreferenceHuman(colour="", colour_bonus=0.0)
    bonus = PreferenceHuman(colour="", colour_bonus=5.0)
    expected = plain.scores(PAPER, state)
    picks = [i for i in expected if PAPER.actions(Agent.HUMAN)[i].kind is Kind.PICK]
    assert picks  # the comparison covers scored picks
    assert bonus.scores(PAPER, state) == expected
    assert bonus.distribution(PAPER, state) == plain.distribution(PAPER, state)


# --- agents/humans/switching.py ---


def test_each_phases_human_plays_with_its_own_child_of_the_switching_humans_generator() -> None:
    # switching.py's class docstring: "Every phase's human is reset at reset with its own
    # child generator spawned from the switching human's, so adding a phase does not change
    # the others' draws". The reference: numpy's spawn of a generator seeded alike gives the
    # children; each phase's human must draw what its child draws, never what the parent
    # (or the other phase's human) draws.
    human = SwitchingHuman(["lazy:p_idle=0.5", "lazy:p_idle=0.5"], at=[600.0])
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(7))
    children = np.random.default_rng(7).spawn(2)
    parent = np.random.default_rng(7).random(4)
    assert human.humans[0].rng is not human.humans[1].rng
    for phase, child in zip(human.humans, children, strict=True):
        drawn = phase.rng.random(4)
        np.testing.assert_array_equal(drawn, child.random(4))
        assert not np.array_equal(drawn, parent)
