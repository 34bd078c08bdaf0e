"""The play session, its trace and its replay; the terminal front end by scripted input."""

from __future__ import annotations

import io
import json
from itertools import count
from pathlib import Path

import pytest
from rich.console import Console

from hg_marl.agents.humans.trace import read_trace
from hg_marl.core import Agent
from hg_marl.core.errors import HgMarlError, HumanError, RobotError, SpecError
from hg_marl.training.play.replay import replay_run, replay_trace
from hg_marl.training.play.session import PlaySession, robot_move
from hg_marl.training.play.tui import play_terminal
from tests.play.reference import person_choice


def fake_timer(step: float = 1.5):
    """A wall clock that advances ``step`` seconds per reading."""
    ticks = count()
    return lambda: next(ticks) * step


def play_until(session: PlaySession, tasks: int, limit: int = 80) -> list[str]:
    moves = []
    while session.tasks_solved < tasks and len(moves) < limit:
        name = person_choice([c.name for c in session.choices()])
        session.play(name)
        moves.append(name)
    return moves


@pytest.mark.parametrize("robot", ["planner", "hybrid:criterion=entropy_and_cost", "habit"])
def test_recorded_game_replays_to_the_same_rewards(tmp_path: Path, robot: str) -> None:
    session = PlaySession(robot, seed=4, record=tmp_path, player="tester", timer=fake_timer())
    moves = play_until(session, 2, limit=40)
    path = session.close()
    assert path is not None
    (episode,) = read_trace(path)
    meta = episode.header["meta"]
    assert (meta["player"], meta["robot"], episode.header["seat"]) == ("tester", robot, "human")
    assert [s["action_name"] for s in episode.steps] == moves
    # the fake clock advances 1.5 s per reading: shown (robot's turn) then answered
    assert [s["response_time"] for s in episode.steps] == [1.5] * len(moves)
    assert episode.end["rewards"] == session.rewards == session.tasks_solved
    replay = replay_run(path)
    assert float(replay.log["reward"].sum()) == session.rewards
    assert list(replay.log["human_action_name"][: len(moves)]) == moves
    assert float(replay.log["time"].iloc[len(moves) - 1]) == pytest.approx(episode.end["clock"])


def test_planner_game_solves_tasks_with_a_handover(tmp_path: Path) -> None:
    session = PlaySession("planner", seed=0, record=tmp_path)
    moves = play_until(session, 1)
    assert session.tasks_solved == 1 and "give(tape3)" in moves
    assert session.last_robot is not None and session.last_robot.expert == "planner"
    path = session.close() or Path()
    result = replay_trace(path)
    assert (result.rewards, result.recorded_rewards, result.moves) == (1.0, 1.0, len(moves))
    # the reported clock is the recording's end, not the end of the replay's extra last cycle
    (episode,) = read_trace(path)
    assert result.recorded_clock == episode.end["clock"] < result.clock


def test_infeasible_and_unknown_actions_are_refused_without_effect() -> None:
    session = PlaySession("planner", seed=0)
    before = (session.state, session.clock)
    feasible = {c.index for c in session.choices()}
    infeasible = next(i for i in range(session.world.n_actions(Agent.HUMAN)) if i not in feasible)
    with pytest.raises(HumanError, match="not feasible now"):
        session.play(infeasible)
    with pytest.raises(HumanError, match="unknown action 'dance'"):
        session.play("dance")
    with pytest.raises(HumanError, match="not an index"):
        session.play(999)
    assert (session.state, session.clock) == before and session.response_times == []


def test_shortcuts_are_unique_and_wait_is_w() -> None:
    session = PlaySession("planner", seed=0)
    play_until(session, 0)
    for _ in range(6):
        keys = [c.key for c in session.choices()]
        assert len(set(keys)) == len(keys) and keys[-1] == "w"
        session.play(person_choice([c.name for c in session.choices()]))


def test_bad_robot_specs_name_the_problem() -> None:
    with pytest.raises(RobotError, match="unknown robot 'butler'"):
        PlaySession("butler")
    with pytest.raises(RobotError, match="no parameter 'speed'"):
        PlaySession("planner:speed=3")
    with pytest.raises(SpecError):
        PlaySession(":x=1")
    with pytest.raises(HgMarlError, match="--seed"):
        PlaySession("planner", seed=-1)


def test_robot_move_reads_the_typed_decision_record(paper) -> None:
    from hg_marl.policy import Decision

    class Typed:
        last_decision = Decision(
            expert="habit",
            action=17,
            decision_time=0.25,
            weight_amplitude=2.0,
            stats=(("vpi", 0.5), ("bad", float("nan"))),
        )

    class Nothing:
        name = "random"

    typed = robot_move(Typed(), paper, 17, True)
    # the non-finite stat is dropped; the habit acted, so its weight amplitude is kept
    assert (typed.expert, typed.decision_time, typed.failed) == ("habit", 0.25, True)
    assert dict(typed.weights) == {"vpi": 0.5} and typed.weight_amplitude == 2.0
    # an actor without a record is shown under its name
    assert robot_move(Nothing(), paper, 17, False).expert == "random"


def test_terminal_front_end_by_scripted_input(tmp_path: Path) -> None:
    session = PlaySession("planner", seed=0, record=tmp_path, frontend="terminal")
    keys = iter(["1", "w", "0", "w", "w", "1", "q"])  # pick(tape3), wait, (no such key), wait, wait, give(tape3)
    feasible_at_the_bad_key: list[str] = []

    def read() -> str:
        key = next(keys)
        if key == "0":  # what the rules allow now, read from the world's mask
            mask = session.world.mask(session.state, Agent.HUMAN)
            names = session.world.action_names[Agent.HUMAN]
            feasible_at_the_bad_key.extend(n for n, ok in zip(names, mask, strict=True) if ok)
        return key

    out = io.StringIO()
    summary = play_terminal(session, Console(file=out, width=200, force_terminal=True), read=read)
    text = out.getvalue()
    (episode,) = read_trace(Path(str(summary["trace"])))
    names = [s["action_name"] for s in episode.steps]
    assert names == ["pick(tape3)", "wait", "wait", "wait", "give(tape3)"]
    (answer,) = [line for line in text.splitlines() if "'0' is not a key here" in line]
    offered = [item.split(" ", 1)[1] for item in answer.split("your moves: ")[1].split("; q")[0].split(", ")]
    assert offered == feasible_at_the_bad_key and len(offered) < len(session.world.action_names[Agent.HUMAN])
    assert "robot: take(tape3), proposed by the planner" in text
    assert "\x1b[" in text, "redrawn in place (cursor control), not reprinted"
    assert episode.header["meta"]["frontend"] == "terminal" and summary["moves"] == 5
    assert "played 5 moves with the robot planner" in text
    assert json.loads(Path(str(summary["trace"])).read_text().splitlines()[-1])["type"] == "end"


def test_play_command_in_the_terminal_and_bad_robot(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from typer.testing import CliRunner

    from hg_marl.training.cli import app, main

    result = CliRunner().invoke(app, ["play", "--tui", "--record", str(tmp_path), "--player", "cli"], input="1q")
    assert result.exit_code == 0, result.output
    assert "1 moves, 0 tasks" in result.output
    (trace,) = tmp_path.glob("*.jsonl")
    (episode,) = read_trace(trace)
    assert [s["action_name"] for s in episode.steps] == ["pick(tape3)"] and episode.header["meta"]["player"] == "cli"
    monkeypatch.setattr("sys.argv", ["hg-marl", "play", "--tui", "--robot", "butler"])
    with pytest.raises(SystemExit) as stop:
        main()
    assert stop.value.code == 2


@pytest.mark.parametrize(
    "args,message",
    [
        (["--port", "-1"], "--port -1: expected 0 (a free port) to 65535"),
        (["--port", "70000"], "--port 70000: expected 0 (a free port) to 65535"),
        (["--record", "FILE"], "--record FILE: is a file; name a folder"),
        (["--tui", "--record", "FILE/sub"], "--record FILE/sub: FILE is a file, not a folder"),
    ],
)
def test_play_bad_port_or_record_is_one_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], args: list[str], message: str
) -> None:
    from hg_marl.training.cli import main

    pytest.importorskip("starlette")
    target = tmp_path / "taken.jsonl"
    target.write_text("keep")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(
        "sys.argv", ["hg-marl", "play", "--no-browser", *[a.replace("FILE", str(target)) for a in args]]
    )
    with pytest.raises(SystemExit) as stop:
        main()
    err = capsys.readouterr().err.strip()
    assert stop.value.code == 2 and err.count("\n") == 0 and message.replace("FILE", str(target)) in err
    assert target.read_text() == "keep" and not (tmp_path / "runs").exists()


def test_play_tui_takes_one_key_per_move_in_a_real_terminal(tmp_path: Path) -> None:
    """In a pseudo-terminal, keys without Enter play moves (the terminal is in cbreak mode)."""
    import os
    import pty
    import re
    import select
    import subprocess
    import sys
    import time

    main_fd, child_fd = pty.openpty()
    code = "from hg_marl.training.cli import main; main()"
    args = [sys.executable, "-c", code, "play", "--tui", "--record", str(tmp_path), "--player", "pty"]
    proc = subprocess.Popen(args, stdin=child_fd, stdout=child_fd, stderr=child_fd, close_fds=True)
    os.close(child_fd)
    seen = b""

    def wait_for(*texts: bytes, since: int = 0, timeout: float = 600.0) -> bytes:
        """Read the terminal until one of ``texts`` shows after byte ``since``; return the first shown.

        The timeout only stops a child that hangs: a wrong answer is told apart at once.
        """
        nonlocal seen
        end = time.monotonic() + timeout
        while not any(t in seen[since:] for t in texts):
            assert time.monotonic() < end, seen[-2000:]
            # the display marks a screen too tall for the terminal with a red "...": what is
            # waited for may be below it, so a cut screen fails at once
            assert not re.search(rb"\x1b\[1;31m *\.\.\. *\x1b\[0m", seen[since:]), seen[-2000:]
            if select.select([main_fd], [], [], 0.1)[0]:
                try:
                    seen += os.read(main_fd, 65536)
                except OSError:  # the child closed the terminal
                    assert any(t in seen[since:] for t in texts), seen[-2000:]
        return min((seen.index(t, since), t) for t in texts if t in seen[since:])[1]

    try:
        wait_for(b"finish and save")
        os.write(main_fd, b"1")  # pick(tape3): no Enter
        # The screen answers a key with the move played or with "not a key here": either ends the wait.
        assert wait_for(b"you:   ", b"is not a key here") == b"you:   ", seen[-2000:]
        start = seen.index(b"you:   ") + len(b"you:   ")
        wait_for(b"\r", b"\n", b"\x1b", since=start)  # the move's name is whole
        assert re.split(rb"[\r\n\x1b ]", seen[start:], maxsplit=1)[0] == b"pick(tape3)", seen[-2000:]
        os.write(main_fd, b"q")
        wait_for(b"trace saved")
        assert proc.wait(timeout=600) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
        os.close(main_fd)
    (trace,) = tmp_path.glob("*.jsonl")
    (episode,) = read_trace(trace)
    assert [s["action_name"] for s in episode.steps] == ["pick(tape3)"]
