"""The play front ends' words: why the robot acted, what is pending, the scenario's rules.

Expected texts are read off the decision record's fields and the scenario file by the
rules they state (the higher value wins; plan iff VPI > threshold), not from the code's
own formatting helpers.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.core import Agent
from hg_marl.policy import decision_of
from hg_marl.training.play.explain import intro, pending, why
from hg_marl.training.play.session import PlaySession
from tests.play.reference import person_choice

ENTROPY_AND_COST = 'hybrid:criterion=entropy_and_cost,criterion_params={"min_visits":0}'


def test_a_planner_is_explained_without_habit_numbers() -> None:
    game = PlaySession("planner", seed=0)
    game.play("wait")
    record = decision_of(game.robot)
    text = " ".join(why(game.last_robot))
    assert f"{game.last_robot.name}, proposed by the planner." in text
    assert "weight amplitude" not in text and "=" not in text.replace("Value =", "")
    expected = game.world.action_names[Agent.HUMAN][record.expected_human_action]
    assert f"Its plan expects you to {expected} next." in text


def test_entropy_and_cost_numbers_in_words() -> None:
    game = PlaySession(ENTROPY_AND_COST, seed=0)
    stats = dict(decision_of(game.robot).stats)
    text = " ".join(why(game.last_robot))
    assert f"habit {100 * stats['h_habit']:.0f}%, planner {100 * stats['h_planner']:.0f}%" in text
    winner = "planner" if stats["value_planner"] > stats["value_habit"] else "habit"
    assert f"higher wins: {winner}." in text and game.last_robot.expert == winner
    assert "weight amplitude" in text  # a hybrid has a habit


def test_vpi_verdict_follows_the_rule() -> None:
    game = PlaySession('hybrid:criterion=vpi,criterion_params={"min_visits":0}', seed=0)
    for _ in range(6):
        stats = dict(decision_of(game.robot).stats)
        text = " ".join(why(game.last_robot))
        verdict = "worth planning" if stats["vpi"] > stats["threshold"] else "not worth planning"
        assert f": {verdict}." in text
        game.play(person_choice([c.name for c in game.choices()]))


def test_pending_offer_and_turn(tmp_path: Path) -> None:
    game = PlaySession("planner", seed=0)
    state = game.state
    assert pending(game.world, state) == "Your turn."
    offered = state._replace(offer_by=int(Agent.ROBOT), offer_obj=1)
    assert "The robot is offering you tape2: take(tape2) now" in pending(game.world, offered)


def test_intro_says_what_the_scenario_has() -> None:
    paper = " ".join(intro(PlaySession("planner", scenario="paper2015").world))
    # paper2015: one bin, for any object, reached from bin_side only; uncoloured tapes
    assert "every object into the bin." in paper and "colour" not in paper
    assert "trashbin (takes any object; reached by the robot from bin_side)" in paper
    assert "only you reach human_mat_1, human_mat_2" in paper
    rob = " ".join(intro(PlaySession("planner", scenario="roboergosum").world))
    # roboergosum.toml: green_bin from ROBOT_LOC, blue_bin from SECOND_LOC and the human
    assert "into a bin of its colour" in rob
    assert "green_bin (takes green objects; reached by the robot from ROBOT_LOC)" in rob
    assert "blue_bin (takes blue objects; reached by the robot from SECOND_LOC and you)" in rob


@pytest.mark.parametrize("robot", ["planner"])
def test_a_solved_task_is_announced_once(robot: str) -> None:
    pytest.importorskip("starlette")
    from hg_marl.training.play.web import board_html

    game = PlaySession(robot, seed=0)
    seen = 0
    for _ in range(60):
        before = game.tasks_solved
        game.play(person_choice([c.name for c in game.choices()]))
        announced = 'id="solved"' in board_html(game)
        assert announced == (game.tasks_solved > before)
        seen += announced
        if seen == 1 and game.tasks_solved == 1:
            break
    assert seen == 1 and "Task solved! That makes 1 task at t = " in board_html(game)


def test_a_handover_is_reported() -> None:
    game = PlaySession("planner", seed=0)
    state = game.state
    note = pending(game.world, state, "give(tape3)", "take(tape3)")
    assert note == "Handover done: you gave tape3 and the robot took it. Your turn."
    assert pending(game.world, state, "give(tape3)", "wait") == "Your turn."
