"""Replaying a recorded game: which episode, how long, which robot, what is reported.

Pinned for the mutation gate. Expected values follow the module's documented rules,
checked on games recorded here with a scripted person: a replay runs the recorded episode
with its seed and robot (``planner`` when the trace names none) until the recording's end
clock plus :data:`MARGIN` (the end line's clock, else the last turn's, else 0); a table
that differs from the recording is one ``HumanError`` line naming the trace; the summary
reports the recording's own moves, seed, player, end clock and rewards (None without an
end line).
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest

from hg_marl.agents.humans.trace import Episode, read_trace
from hg_marl.core.errors import ConfigError, HumanError
from hg_marl.training.play.replay import MARGIN, ReplayResult, end_clock, load_episode, replay_run, replay_trace
from hg_marl.training.play.session import PlaySession
from tests.play.reference import person_choice


def _record(folder: Path, robot: str = "planner", seed: int = 0, moves: int = 6, player: str = "tester") -> Path:
    """A game of ``moves`` moves by the scripted person, recorded in ``folder``."""
    session = PlaySession(robot, seed=seed, record=folder, player=player)
    for _ in range(moves):
        session.play(person_choice([c.name for c in session.choices()]))
    path = session.close()
    assert path is not None
    return path


def _lines(path: Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


def _write(path: Path, records: list[dict]) -> Path:
    path.write_text("".join(json.dumps(r) + "\n" for r in records))
    return path


def test_a_missing_trace_and_an_episode_out_of_range_are_one_line_errors(tmp_path: Path) -> None:
    """A missing file is refused by the trace reader itself (one line naming it)."""
    with pytest.raises(HumanError, match=r"nothing\.jsonl: trace file not found$"):
        load_episode(tmp_path / "nothing.jsonl", 0)
    trace = _record(tmp_path / "a")
    assert load_episode(trace, 0).steps
    for episode in (-1, 1):
        with pytest.raises(ConfigError, match=rf"^--episode {episode}: .* holds episodes 0\.\.0$"):
            load_episode(trace, episode)


def test_a_malformed_trace_is_a_human_error(tmp_path: Path) -> None:
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"type": "step"}\n')
    with pytest.raises(HumanError):
        load_episode(bad, 0)


def test_the_end_clock_is_the_end_lines_else_the_last_turns_else_zero() -> None:
    steps = [{"clock": 1.5}, {"clock": 4.25}]
    assert end_clock(Episode({}, steps, {"clock": 9.0})) == 9.0
    assert end_clock(Episode({}, steps, {})) == 4.25
    assert end_clock(Episode({}, [], {})) == 0.0


def test_a_replay_reports_the_recording_and_runs_a_margin_past_its_end(tmp_path: Path) -> None:
    trace = _record(tmp_path / "a", seed=3, moves=6)
    (episode,) = read_trace(trace)
    result = replay_trace(trace)
    assert (result.scenario, result.seed, result.robot, result.player) == ("paper2015", 3, "planner", "tester")
    assert result.moves == 6 == len(episode.steps)
    assert result.recorded_clock == episode.end["clock"]
    assert result.recorded_rewards == episode.end["rewards"]
    assert result.recorded_clock < result.clock <= result.recorded_clock + 60.0
    assert result.video is None and result.frames == 0
    log = replay_run(trace).log
    assert float(log["time"].iloc[-1]) == result.clock
    assert float(log["reward"].sum()) == result.rewards
    assert int(log["reward"].sum()) == result.tasks_solved


def test_without_an_end_line_the_replay_stops_at_the_last_turn_and_reports_no_rewards(tmp_path: Path) -> None:
    """The last turn's clock plus MARGIN (1 ms) is before that cycle's end: the run ends with it."""
    trace = _record(tmp_path / "a", moves=5)
    cut = _write(tmp_path / "cut.jsonl", [r for r in _lines(trace) if r.get("type") != "end"])
    (episode,) = read_trace(cut)
    assert episode.end == {}
    result = replay_trace(cut)
    assert result.recorded_rewards is None
    assert result.recorded_clock == episode.steps[-1]["clock"]
    assert MARGIN == 1e-3
    log = replay_run(cut).log
    assert float(log["time"].iloc[-1]) < result.recorded_clock + 5.0


def test_the_replay_plays_the_episode_asked_for(tmp_path: Path) -> None:
    """Two games in one trace file: episode 1 replays the second game's moves, not the first's."""
    first = _record(tmp_path / "a", seed=0, moves=4)
    second = _record(tmp_path / "b", seed=5, moves=7)
    both = _write(tmp_path / "both.jsonl", _lines(first) + _lines(second))
    result = replay_trace(both, episode=1)
    assert (result.seed, result.moves) == (5, 7)
    (recorded,) = read_trace(second)
    log = replay_run(both, episode=1).log
    assert list(log["human_action_name"][:7]) == [s["action_name"] for s in recorded.steps]


def test_a_trace_without_a_robot_seed_or_player_is_replayed_with_the_planner_on_seed_0(tmp_path: Path) -> None:
    trace = _record(tmp_path / "a", robot="planner", seed=0, moves=4)
    records = _lines(trace)
    header = records[0]
    header["meta"].pop("robot", None)
    header["meta"].pop("player", None)
    header.pop("seed", None)
    bare = _write(tmp_path / "bare.jsonl", records)
    result = replay_trace(bare)
    assert (result.robot, result.seed, result.player, result.moves) == ("planner", 0, "", 4)


def test_a_replay_with_another_robot_than_recorded_diverges_in_one_line_naming_the_trace(tmp_path: Path) -> None:
    trace = _record(tmp_path / "a", robot="planner", moves=8)
    with pytest.raises(HumanError, match=rf"^replay of {trace}: "):
        replay_run(trace, robot="random")
    result = replay_trace(trace, robot="planner")
    assert result.robot == "planner"


def test_an_episode_past_the_last_of_three_is_refused_naming_the_range(tmp_path: Path) -> None:
    """Three games in one file: episodes 0 to 2 load, 3 and 5 are refused with "0..2"."""
    records = [r for name in "abc" for r in _lines(_record(tmp_path / name, moves=2))]
    three = _write(tmp_path / "three.jsonl", records)
    assert load_episode(three, 2).steps
    for episode in (3, 5):
        with pytest.raises(ConfigError, match=rf"^--episode {episode}: .* holds episodes 0\.\.2$"):
            load_episode(three, episode)


def test_a_replay_result_is_frozen_and_without_a_video_holds_no_frames(tmp_path: Path) -> None:
    result = replay_trace(_record(tmp_path / "a", moves=2))
    with pytest.raises(dataclasses.FrozenInstanceError):
        result.moves = 0
    bare = ReplayResult("paper2015", 0, "planner", "", 0, 0, 0.0, 0.0, 0.0, None)
    assert bare.video is None and bare.frames == 0
