"""Values that round 146's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.content import content_key, named_files
from hg_marl.agents.humans.preference import PreferenceHuman
from hg_marl.agents.progress import PROGRESS_AFTER
from hg_marl.agents.robots import PlannerRobot
from hg_marl.agents.robots.habit import HabitRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario import load_scenario, resolve_scenario
from tests.training.test_pinned_round92 import WORLD, _turn
from tests.training.test_pinned_round121 import RELEASE


def test_a_file_named_inside_a_tuple_of_the_fields_is_keyed_by_its_bytes(tmp_path: Path) -> None:
    # "every text in the settings is looked at, inside tables, lists and specs": a tuple is a
    # list to the key's JSON (canonical writes it as one), so a file named in a tuple is keyed
    # by its name and the SHA-256 of its bytes, worked here with hashlib, and editing it changes the key.
    path = tmp_path / "t.jsonl"
    path.write_bytes(b"abc")
    fields = {"traces": (str(path),)}
    assert named_files(fields) == {str(path): {"t.jsonl": hashlib.sha256(b"abc").hexdigest()}}
    before = content_key("test", fields, ())
    path.write_bytes(b"abcd")
    assert named_files(fields) == {str(path): {"t.jsonl": hashlib.sha256(b"abcd").hexdigest()}}
    assert content_key("test", fields, ()) != before


def test_a_planner_robots_new_run_starts_its_progress_guard_afresh() -> None:
    # The guard takes a move when the state has not changed for K (PROGRESS_AFTER) of the
    # robot's turns *of this run* (round 92: K planner decisions on one state, then the
    # guard's). A run of K turns on one state, then a reset: the new run's first turn on the
    # same state has seen nothing unchanged yet, so it is the planner's, and no guard move is counted.
    robot = PlannerRobot()
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    state = WORLD.initial_state(np.random.default_rng(0))
    for _ in range(PROGRESS_AFTER):
        robot.act(_turn(state))
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(1))
    robot.act(_turn(state))
    assert robot.last_decision is not None
    assert robot.last_decision.expert == "planner"
    assert (robot.progress.unchanged, robot.progress.moves) == (0, 0)


def test_a_preference_human_moved_to_another_world_answers_from_that_worlds_rules() -> None:
    # paper2015's human holds tape1 (place code 8, the human's hand: 6 spots, 1 bin, then the
    # robot's and the human's hands) with the robot at human_side (location 3, the handover
    # location). Worked by hand with handover = 2 and self_work = 0.2: the human reaches no bin
    # (no throw), give(tape1) scores handover = 2, place on mat_shared (spot 3, the robot
    # reaches it) shared = 0.5, on a human mat keep = -1 (spot 4 holds tape3). The answer is
    # give(tape1), whatever the same human answered before in roboergosum (its own action table).
    human = PreferenceHuman(handover=2.0, self_work=0.2)
    other = World("roboergosum")
    human.distribution(other, other.initial_state(np.random.default_rng(0)))
    state = State((8, 0, 4), 3)
    give = WORLD.table.action_index(Agent.HUMAN, Kind.GIVE, 0)
    assert WORLD.action_names[Agent.HUMAN][give] == "give(tape1)"
    assert human.distribution(WORLD, state) == [(give, 1.0)]


@pytest.mark.parametrize("kept", [False, True])
def test_a_reset_learning_robot_takes_no_td_step_on_its_first_turn(kept: bool) -> None:
    # The module docstring: "The first turn of a run has no previous transition." A run that
    # stops without end() (continuing mode) leaves its last (facts, action) pending; reset()
    # starts a new run, so nothing is pending, and a first turn with reward 1 moves no weight:
    # the Q-values stay all zero, with a fresh learner and with one kept across resets alike.
    state = WORLD.initial_state(np.random.default_rng(0))
    robot = HabitRobot()
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    if kept:
        robot = HabitRobot(learner=robot.habit)
        robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    robot.act(_turn(state))
    assert robot.has_pending
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(1))
    assert not robot.has_pending
    robot.act(_turn(state, reward=1.0))
    assert not np.any(robot.habit.q_values(WORLD.facts(state)))


def test_a_scenario_file_whose_name_starts_with_generated_is_read_as_a_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Only "generated" and "generated:..." name the generated family; generated_release.toml is a
    # .toml path like any other: it resolves to the file and loads as the scenario it holds
    # (named "release"), and a bare word like "generatedx" is an unknown scenario.
    monkeypatch.chdir(tmp_path)
    Path("generated_release.toml").write_text(RELEASE, encoding="utf-8")
    assert resolve_scenario("generated_release.toml") == ("file", "generated_release.toml")
    assert load_scenario("generated_release.toml").name == "release"
    with pytest.raises(ScenarioError, match="unknown scenario 'generatedx'"):
        resolve_scenario("generatedx")
