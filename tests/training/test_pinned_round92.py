"""The values round 92's missed planted bugs changed, pinned after the round.

Round 92 planted 16 bugs in sixteen gated modules, written blind; 12 were caught. Each
value below is stated from the rule the module documents (or a simpler reference written
here, or a property), not read from the code under test:

- the noisy human's answer is a function of the state and the robot action under way
  (its memo is a pure cache): asking with another robot action first changes nothing;
- a planner robot's progress-guard move is recorded as the guard's (``no_progress``);
- a learning robot built with ``learn=False`` is a frozen habit: it takes no TD step;
- ``trace_paths`` of a directory is every ``*.jsonl`` below it, subfolders included.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hg_marl.agents.humans.noisy import NoisyHuman
from hg_marl.agents.humans.trace import trace_paths
from hg_marl.agents.progress import PROGRESS_AFTER
from hg_marl.agents.robots import PlannerRobot
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.core import Agent, State, World
from hg_marl.policy import Decision, Turn

WORLD = World("paper2015")


def _turn(state: State, reward: float = 0.0) -> Turn:
    obs = {"observation": WORLD.facts(state), "action_mask": WORLD.mask(state, Agent.ROBOT)}
    return Turn(WORLD, state, Agent.ROBOT, obs, reward=reward, last_actions=(-1, -1))


def test_a_noisy_humans_answer_does_not_depend_on_what_it_was_asked_before() -> None:
    # The property: distribution(state, robot_action) is a function of its arguments; a memo
    # is a pure cache. So a human first asked about a robot action under way answers the
    # query without one as a human asked nothing before does. The robot action is one whose
    # answer differs from the one without (found below), so a mix-up of the two can be seen.
    state = WORLD.initial_state(np.random.default_rng(0))
    fresh = NoisyHuman(temperature=1.0).distribution(WORLD, state, -1)
    differing = [
        r
        for r in WORLD.feasible_indices(state, Agent.ROBOT)
        if NoisyHuman(temperature=1.0).distribution(WORLD, state, r) != fresh
    ]
    assert differing
    for r in differing:
        asked = NoisyHuman(temperature=1.0)
        asked.distribution(WORLD, state, r)
        assert asked.distribution(WORLD, state, -1) == fresh
        assert asked.distribution(WORLD, state, r) == NoisyHuman(temperature=1.0).distribution(WORLD, state, r)


def test_a_planner_robots_progress_guard_move_is_recorded_as_the_guards() -> None:
    # The state stands still at the robot's turn: after PROGRESS_AFTER planner decisions the
    # progress guard takes a move (the module docstring: reason "no_progress"), recorded as
    # the guard's, not as a random move for a stalled partner.
    robot = PlannerRobot()
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    state = WORLD.initial_state(np.random.default_rng(0))
    for _ in range(PROGRESS_AFTER):
        robot.act(_turn(state))
    robot.act(_turn(state))
    record = robot.last_decision
    assert isinstance(record, Decision)
    assert (record.expert, record.reason) == ("guard", "no_progress")


def test_a_habit_built_with_learn_false_takes_no_td_step() -> None:
    # LearningRobot's docstring: learn=False is a frozen habit, for evaluation. A fresh
    # learner starts at zero weights; a transition with reward 1 would move them, and does
    # with learn=True (checked), so the frozen habit's Q-values stay all zero.
    state = WORLD.initial_state(np.random.default_rng(0))
    facts = WORLD.facts(state)
    for learn in (True, False):
        robot = HabitRobot(learn=learn)
        robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
        robot.act(_turn(state))
        robot.act(_turn(state, reward=1.0))
        moved = bool(np.any(robot.habit.q_values(facts) != 0.0))
        assert moved is learn


def test_trace_paths_of_a_directory_finds_the_traces_in_its_subfolders(tmp_path: Path) -> None:
    # The docstring: "every *.jsonl under a directory (sorted)", what --traces DIR means
    # (hg-marl play records into subfolders); other files are left out.
    (tmp_path / "sub" / "deeper").mkdir(parents=True)
    for name in ("a.jsonl", "sub/b.jsonl", "sub/deeper/c.jsonl", "sub/notes.txt"):
        (tmp_path / name).write_text("{}\n")
    found = trace_paths(tmp_path)
    assert [p.relative_to(tmp_path).as_posix() for p in found] == ["a.jsonl", "sub/b.jsonl", "sub/deeper/c.jsonl"]
