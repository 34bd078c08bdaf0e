"""The play session's arguments, moves, counts and records, pinned for the mutation gate.

Expected values follow the module's documented rules, worked by hand or read off the
world's own rules (its masks and names) as the reference: a seed is a non-negative
integer; a move is an action name or an index in ``[0, n_actions)`` that is feasible now,
anything else is one ``HumanError`` line and nothing happens; the feasible actions get the
shortcuts ``1``, ``2``, ... in order and ``wait`` gets ``w``; a response time is the wall
time from the choice shown to the move (never negative); the robot's record shows only
finite numbers and names the person's move it expects only when it is an action.
"""

from __future__ import annotations

import getpass
import json
import math
import re
from itertools import count
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, HumanError, RobotError
from hg_marl.policy import Decision
from hg_marl.training.play import session as session_module
from hg_marl.training.play.session import SHORTCUTS, PlaySession, build_robot, robot_move
from tests.play.reference import person_choice


def ticking(step: float = 1.5) -> Any:
    """A wall clock that advances ``step`` seconds per reading."""
    ticks = count()
    return lambda: next(ticks) * step


@pytest.mark.parametrize("seed", [-1, True, 1.0, "3"])
def test_a_seed_is_a_non_negative_integer(seed: Any) -> None:
    with pytest.raises(ConfigError, match=r"^--seed: expected a non-negative integer, got "):
        PlaySession(seed=seed)


def test_seed_zero_is_accepted_and_named_in_the_trace_file(tmp_path: Path) -> None:
    session = PlaySession(seed=0, record=tmp_path, player="ann", frontend="terminal")
    path = session.close()
    assert path is not None and path.parent == tmp_path
    assert path.name.startswith("play-") and path.name.endswith("-paper2015-seed0.jsonl")
    header = json.loads(path.read_text().splitlines()[0])
    assert header["seed"] == 0
    assert (header["meta"]["player"], header["meta"]["robot"], header["meta"]["frontend"]) == (
        "ann",
        "planner",
        "terminal",
    )


def test_a_record_folder_that_is_a_file_is_refused(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(ConfigError, match="--record"):
        PlaySession(record=blocker)


def test_an_unknown_robot_or_a_bad_parameter_is_a_robot_error_naming_the_spec() -> None:
    with pytest.raises(RobotError, match=r"^--robot 'nobody': unknown robot 'nobody'; available: "):
        build_robot("nobody")
    with pytest.raises(RobotError, match="hybrid"):
        build_robot("hybrid:criterion=nothing_like_it")


def test_the_player_defaults_to_the_login_and_to_anonymous_without_one(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(getpass, "getuser", lambda: "login-name")
    assert PlaySession().player == "login-name"

    def no_login() -> str:
        raise KeyError("uid")

    monkeypatch.setattr(getpass, "getuser", no_login)
    assert PlaySession().player == "anonymous"
    monkeypatch.setattr(getpass, "getuser", lambda: (_ for _ in ()).throw(OSError("no tty")))
    assert PlaySession().player == "anonymous"


def test_choices_are_the_feasible_actions_with_keys_in_order_and_w_for_wait() -> None:
    session = PlaySession(player="p")
    mask = session.world.mask(session.state, Agent.HUMAN)
    names = session.world.action_names[Agent.HUMAN]
    feasible = [int(i) for i in np.flatnonzero(mask)]
    choices = session.choices()
    assert [c.index for c in choices] == feasible
    assert [c.name for c in choices] == [names[i] for i in feasible]
    others = [c.key for c in choices if c.name != "wait"]
    assert others == list(SHORTCUTS[: len(others)])
    assert [c.key for c in choices if c.name == "wait"] == ["w"]


@pytest.mark.parametrize(
    ("bad", "message"),
    [
        (True, r"^action True is not an index in \[0, \d+\)$"),
        (-1, r"^action -1 is not an index in \[0, \d+\)$"),
        (1.0, r"^action 1\.0 is not an index in \[0, \d+\)$"),
        ("fly(tape1)", r"^unknown action 'fly\(tape1\)'; the human's actions: "),
    ],
)
def test_a_move_that_is_not_an_action_is_refused_and_nothing_happens(bad: Any, message: str) -> None:
    session = PlaySession(player="p", timer=ticking())
    before = (session.clock, session.cycle, len(session.response_times))
    with pytest.raises(HumanError, match=message):
        session.play(bad)
    assert (session.clock, session.cycle, len(session.response_times)) == before


def test_an_infeasible_action_is_refused_naming_the_feasible_ones() -> None:
    session = PlaySession(player="p", timer=ticking())
    mask = session.world.mask(session.state, Agent.HUMAN)
    names = session.world.action_names[Agent.HUMAN]
    infeasible = int(np.flatnonzero(mask == 0)[0])
    feasible = ", ".join(c.name for c in session.choices())
    with pytest.raises(HumanError, match=rf"^{re.escape(names[infeasible])} is not feasible now; feasible: ") as info:
        session.play(infeasible)
    assert str(info.value).endswith(feasible)


def test_a_numpy_index_and_a_name_are_the_same_move() -> None:
    a, b = PlaySession(player="p", seed=2), PlaySession(player="p", seed=2)
    name = person_choice([c.name for c in a.choices()])
    index = a.world.action_names[Agent.HUMAN].index(name)
    a.play(np.int64(index))
    b.play(name)
    assert a.last_human == b.last_human == name
    assert (a.clock, a.state) == (b.clock, b.state)


def test_response_times_are_the_wall_time_since_the_choice_was_shown_never_negative(tmp_path: Path) -> None:
    """The clock reads 0 at the robot's first turn, 1.5 at the move, 3 at the robot's next turn,
    4.5 at the next move and 6 at the robot's turn after it; then a clock that went back to 2 s."""
    session = PlaySession(player="p", timer=ticking(1.5), record=tmp_path)
    session.play("wait")
    session.play("wait")
    assert session.response_times == [1.5, 1.5]
    session.timer = lambda: 2.0  # shown at 6 s, answered "at 2 s"
    session.play("wait")
    assert session.response_times[-1] == 0.0
    path = session.close()
    assert path is not None
    steps = [json.loads(line) for line in path.read_text().splitlines() if '"step"' in line]
    assert [s["response_time"] for s in steps] == [1.5, 1.5, 0.0]


def test_a_played_game_counts_its_tasks_rewards_handovers_and_experts() -> None:
    """Played to two tasks by the scripted person against the planner: each solved task is one
    reward and one clock reading; the handovers counted are the person's gives and takes."""
    session = PlaySession(player="p", seed=0, timer=ticking())
    gave = took = 0
    solved_moves = 0
    while session.tasks_solved < 2:
        name = person_choice([c.name for c in session.choices()])
        before = session.tasks_solved
        session.play(name)
        solved_moves += session.just_solved
        assert session.just_solved == session.tasks_solved - before
        if not session.raw.infos["human"]["failed"]:
            gave += name.startswith("give(")
            took += name.startswith("take(")
    assert session.rewards == session.tasks_solved == solved_moves == len(session.solved_at)
    assert session.solved_at == sorted(session.solved_at) and session.solved_at[-1] <= session.clock
    summary = session.summary()
    assert summary["handovers"]["you_gave"] == gave and summary["handovers"]["you_took"] == took
    assert list(summary["handovers"]) == ["you_gave", "robot_took", "robot_gave", "you_took"]
    assert sum(summary["experts"].values()) == session.cycle + 1  # the robot moves first, once per cycle
    assert summary["trace"] is None
    text = session.summary_text()
    n, clock = session.tasks_solved, session.clock
    assert f"{n} tasks solved in {clock:.1f} simulated seconds ({clock / n:.1f} s a task)" in text


def test_the_summary_text_names_one_move_one_task_and_the_experts_sorted() -> None:
    session = PlaySession(player="p", seed=0, timer=ticking())
    while session.tasks_solved < 1:
        session.play(person_choice([c.name for c in session.choices()]))
    session.experts.clear()
    session.experts.update({"planner": 2, "habit": 1})
    session.response_times[:] = [2.0]
    text = session.summary_text()
    assert "p played 1 move with the robot planner" in text
    assert ": 1 task solved in " in text
    assert "were chosen by: habit 1, planner 2." in text
    assert text.endswith(" Your mean response time: 2.0 s.")
    session.experts.clear()
    assert "were chosen by: nobody." in session.summary_text()


def test_closing_twice_writes_one_end_line(tmp_path: Path) -> None:
    session = PlaySession(player="p", record=tmp_path, timer=ticking())
    session.play("wait")
    first = session.close()
    assert session.close() == first and session.closed
    assert first is not None
    ends = [line for line in first.read_text().splitlines() if '"end"' in line]
    assert len(ends) == 1


class Recorded:
    """An actor whose last decision is the given record."""

    def __init__(self, decision: Decision) -> None:
        self.last_decision = decision


def test_the_robots_move_shows_finite_numbers_only_and_the_expected_move_when_it_is_one() -> None:
    world = World("paper2015")
    n_h = world.n_actions(Agent.HUMAN)
    stats: Any = (("vpi", 0.5), ("count", 3), ("flag", True), ("cost", math.inf), ("nan", math.nan), ("name", "x"))
    decision = Decision(
        expert="habit",
        action=0,
        decision_time=0.25,
        stats=stats,
        weight_amplitude=2.0,
        expected_human_action=n_h - 1,
    )
    move = robot_move(Recorded(decision), world, 0, failed=True)
    assert move.weights == {"vpi": 0.5, "count": 3.0}
    assert move.weight_amplitude == 2.0 and move.expert == "habit" and move.failed
    assert move.expects == world.action_names[Agent.HUMAN][n_h - 1]
    assert move.name == world.action_names[Agent.ROBOT][0] and move.decision_time == 0.25
    for expected in (-1, n_h):
        out = robot_move(
            Recorded(Decision(expert="planner", action=0, expected_human_action=expected)), world, 0, False
        )
        assert out.expects == ""
    first = robot_move(Recorded(Decision(expert="planner", action=0, expected_human_action=0)), world, 0, False)
    assert first.expects == world.action_names[Agent.HUMAN][0]


def test_a_robot_without_a_habit_shows_no_weight_amplitude() -> None:
    world = World("paper2015")
    planner = Decision(expert="planner", action=0, weight_amplitude=3.0)
    assert robot_move(Recorded(planner), world, 0, False).weight_amplitude is None
    proposed = Decision(expert="planner", action=0, habit_action=2, weight_amplitude=3.0)
    assert robot_move(Recorded(proposed), world, 0, False).weight_amplitude == 3.0
    unknown = Decision(expert="habit", action=0, weight_amplitude=math.nan)
    assert robot_move(Recorded(unknown), world, 0, False).weight_amplitude is None


def test_the_robots_decision_time_is_charged_to_the_clock_only_when_positive(monkeypatch: pytest.MonkeyPatch) -> None:
    charged: list[float] = []
    session = PlaySession(player="p", robot="random", timer=ticking())
    monkeypatch.setattr(session.raw, "charge_time", lambda seconds: charged.append(seconds))
    for seconds in (0.0, -0.5):  # as the runner: only a positive decision time is charged
        record = Decision(expert="random", action=0, decision_time=seconds)
        monkeypatch.setattr(session_module, "decision_of", lambda robot, record=record: record)
        session.play("wait")
    assert charged == []
    some = Decision(expert="random", action=0, decision_time=0.5)
    monkeypatch.setattr(session_module, "decision_of", lambda robot: some)
    session.play("wait")
    assert charged == [0.5]
