"""Trace files: the edges of the line checks, the lines errors name, and the recorder's record,
pinned for the mutation gate.

Expected values from the module's documented rules: a scenario name of 1 to 1,024
characters; a response time of at most one day (86,400 s); ``tasks_solved`` optional on a
step (0 when left out) and growing by at most 2 from one line to the next; each step checked
against its own episode's header; no turn more than the longest action (3 s on paper2015)
plus 60 s after the one before, the late line named ``path:line``; a file of at most 64 MiB;
a trace of the seat a command reads.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.trace import MAX_TRACE_BYTES, Episode, TraceRecorder, check_episode, read_trace
from hg_marl.core import Agent, State, World
from hg_marl.core.errors import ModelFileError
from hg_marl.policy import Turn

PAPER = World("paper2015")
ROBO = World("roboergosum")


def header(world: World = PAPER, **change: Any) -> dict[str, Any]:
    record = {
        "type": "header",
        "format": "hg_marl.trace",
        "version": 1,
        "episode": 0,
        "scenario": world.scenario.name,
        "seed": 0,
        "seat": "human",
        "actor": "test",
        "fact_names": list(world.fact_names),
        "action_names": list(world.action_names[Agent.HUMAN]),
        "meta": {},
    }
    record.update(change)
    return record


def step(world: World = PAPER, **change: Any) -> dict[str, Any]:
    n_actions = world.n_actions(Agent.HUMAN)
    record = {
        "type": "step",
        "step": 0,
        "clock": 0.0,
        "tasks_solved": 0,
        "facts": [0] * world.n_facts,
        "mask": [1] * n_actions,
        "action": n_actions - 1,
    }
    record.update(change)
    return record


def write(tmp_path: Path, *records: dict[str, Any]) -> Path:
    path = tmp_path / "t.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in records))
    return path


@pytest.mark.parametrize("size", [1, 1024])
def test_a_scenario_name_of_1_to_1024_characters_is_read(tmp_path: Path, size: int) -> None:
    (episode,) = read_trace(write(tmp_path, header(scenario="s" * size), step()))
    assert len(episode.header["scenario"]) == size


@pytest.mark.parametrize("size", [0, 1025])
def test_an_empty_scenario_name_or_one_of_1025_characters_is_refused(tmp_path: Path, size: int) -> None:
    with pytest.raises(ModelFileError, match="field 'scenario'"):
        read_trace(write(tmp_path, header(scenario="s" * size), step()))


def test_a_response_time_of_exactly_one_day_is_read_and_a_longer_one_refused(tmp_path: Path) -> None:
    (episode,) = read_trace(write(tmp_path, header(), step(response_time=86_400.0)))
    assert episode.steps[0]["response_time"] == 86_400.0
    with pytest.raises(ModelFileError, match="'response_time'"):
        read_trace(write(tmp_path, header(), step(response_time=86_400.5)))


def test_a_step_without_its_task_count_counts_as_none_solved(tmp_path: Path) -> None:
    """The first step leaves ``tasks_solved`` out (0); the next says 2: two tasks in a cycle, read.
    Three would be one too many."""
    first = {k: v for k, v in step().items() if k != "tasks_solved"}
    (episode,) = read_trace(write(tmp_path, header(), first, step(step=1, clock=3.0, tasks_solved=2)))
    assert [s.get("tasks_solved") for s in episode.steps] == [None, 2]
    with pytest.raises(ModelFileError, match="'tasks_solved'"):
        read_trace(write(tmp_path, header(), first, step(step=1, clock=3.0, tasks_solved=3)))


def test_the_first_step_may_already_count_two_tasks_and_no_more(tmp_path: Path) -> None:
    """Before the first step nothing is solved: its count may be 0 to 2 (one cycle's worth)."""
    (episode,) = read_trace(write(tmp_path, header(), step(tasks_solved=2)))
    assert episode.steps[0]["tasks_solved"] == 2
    with pytest.raises(ModelFileError, match="'tasks_solved': 3 after 0"):
        read_trace(write(tmp_path, header(), step(tasks_solved=3)))


def test_the_end_line_is_checked_against_the_last_step(tmp_path: Path) -> None:
    """Steps at 0, 2 and 4 tasks (two per cycle at most), an end line at 4: read (against the
    episode's start, 0 tasks, 4 would be a jump of more than two); an end at 3 loses a task."""
    steps = [step(step=k, clock=3.0 * k, tasks_solved=2 * k) for k in range(3)]
    end = {"type": "end", "clock": 9.0, "tasks_solved": 4, "rewards": 4.0}
    (episode,) = read_trace(write(tmp_path, header(), *steps, end))
    assert episode.end["tasks_solved"] == 4 and episode.lines == [1, 2, 3, 4, 5]
    with pytest.raises(ModelFileError, match="'tasks_solved': 3 after 4"):
        read_trace(write(tmp_path, header(), *steps, {**end, "tasks_solved": 3}))


def test_an_episode_of_no_steps_may_still_end(tmp_path: Path) -> None:
    """A header then its end line (a session closed before the first move): read, the end's
    counts checked against an episode's start."""
    end = {"type": "end", "clock": 0.0, "tasks_solved": 0, "rewards": 0.0}
    (episode,) = read_trace(write(tmp_path, header(), end))
    assert episode.steps == [] and episode.end == end


def test_a_file_not_utf8_from_its_first_line_names_line_1(tmp_path: Path) -> None:
    path = tmp_path / "t.jsonl"
    path.write_bytes(b"\xff\xfe" + json.dumps(header()).encode() + b"\n")
    with pytest.raises(ModelFileError, match=rf"^{re.escape(str(path))}:1: not UTF-8 text$"):
        read_trace(path)


@pytest.mark.parametrize(
    ("end", "bad_line", "lines"), [(b"\n", 2, 2), (b"\n", 301, 401), (b"\r\n", 301, 401), (b"\r", 7, 9)]
)
def test_a_byte_that_is_not_utf8_is_named_by_its_own_line(
    tmp_path: Path, end: bytes, bad_line: int, lines: int
) -> None:
    """Lines counted as text mode ends them (``\\n``, ``\\r\\n`` or a lone ``\\r``): the header,
    then blank lines, one of them (``bad_line``) holding two bytes no UTF-8 text has. The
    reader decodes a chunk ahead of the line it reads, so the line is not the reader's count."""
    rows = [json.dumps(header()).encode()] + [b""] * (lines - 1)
    rows[bad_line - 1] = b"\xff\xfe"
    path = tmp_path / "t.jsonl"
    path.write_bytes(end.join(rows) + end)
    with pytest.raises(ModelFileError, match=rf"^{re.escape(str(path))}:{bad_line}: not UTF-8 text$"):
        read_trace(path)


def test_blank_lines_are_skipped_and_the_lines_after_them_read(tmp_path: Path) -> None:
    """A blank line (or one of spaces) between a header and its steps is no line of the
    trace: the steps after it are read, each with its own line number in the file."""
    path = tmp_path / "t.jsonl"
    rows = [header(), step(), step(step=1, clock=3.0)]
    path.write_text(json.dumps(rows[0]) + "\n\n   \n" + json.dumps(rows[1]) + "\n\n" + json.dumps(rows[2]) + "\n")
    (episode,) = read_trace(path)
    assert [s["step"] for s in episode.steps] == [0, 1]
    assert episode.lines == [1, 4, 6]


def test_each_step_is_checked_against_its_own_episodes_header(tmp_path: Path) -> None:
    """A paper2015 episode (31 human actions) then a roboergosum one (67): the second episode's
    action 66 and its 47 facts fit its own header, not the first one's."""
    path = write(tmp_path, header(), step(), header(ROBO, episode=1), step(ROBO))
    first, second = read_trace(path)
    assert first.actions == [30] and second.actions == [66]
    assert len(second.steps[0]["facts"]) == ROBO.n_facts == 47


def test_a_turn_too_long_after_the_one_before_names_its_own_line(tmp_path: Path) -> None:
    """Header on line 1, steps at 0 s (line 2), 63 s (line 3: exactly the longest action, 3 s,
    plus 60 s of robot decision: read) and 127 s (line 4: 64 s after, refused)."""
    path = write(tmp_path, header(), step(), step(step=1, clock=63.0), step(step=2, clock=127.0))
    (episode,) = read_trace(path)
    with pytest.raises(ModelFileError, match=rf"^{re.escape(str(path))}:4: field 'clock': 127 is 64 s after") as info:
        check_episode(episode, path)
    assert "(63 s: the longest action plus 60 s of robot decision)" in str(info.value)
    (fits,) = read_trace(write(tmp_path, header(), step(), step(step=1, clock=63.0)))
    assert check_episode(fits, path).scenario.name == "paper2015"


def test_a_late_turn_past_the_line_numbers_an_episode_knows_names_line_question_mark() -> None:
    """An episode built in memory that knows the line numbers of its header and first step
    only: the late second step's line cannot be named."""
    episode = Episode(header(), [step(), step(step=1, clock=100.0)], lines=[1, 2])
    with pytest.raises(ModelFileError, match=r"^t\.jsonl:\?: field 'clock': 100 is 100 s after"):
        check_episode(episode, "t.jsonl")


def test_a_trace_of_the_human_seat_is_refused_where_the_robots_is_read(tmp_path: Path) -> None:
    path = write(tmp_path, header(), step())
    (episode,) = read_trace(path)
    with pytest.raises(ModelFileError, match="field 'seat': 'human'; this command reads traces of the robot seat"):
        check_episode(episode, path, seat="robot")
    assert check_episode(episode, path, seat="human").scenario.name == "paper2015"


def test_a_trace_of_the_robot_seat_is_checked_against_the_robots_action_names(tmp_path: Path) -> None:
    """A robot-seat header names the robot's 18 actions on paper2015: read and checked for
    the robot seat (the seat's value read from the file compares equal to ``"robot"``)."""
    n = PAPER.n_actions(Agent.ROBOT)
    robot_header = header(seat="robot", action_names=list(PAPER.action_names[Agent.ROBOT]))
    path = write(tmp_path, robot_header, step(mask=[1] * n, action=n - 1))
    (episode,) = read_trace(path)
    assert check_episode(episode, path, seat="robot").scenario.name == "paper2015"


def test_each_end_line_closes_its_own_episode(tmp_path: Path) -> None:
    """Two episodes, each ended: the second end line is its own episode's first (not a
    second end of the first), and each episode's line numbers are its own lines."""
    end = {"type": "end", "clock": 0.0, "tasks_solved": 0, "rewards": 0.0}
    path = write(tmp_path, header(), step(), end, header(episode=1), step(), end)
    first, second = read_trace(path)
    assert (first.lines, second.lines) == ([1, 2, 3], [4, 5, 6])
    assert first.end == second.end == end


def test_an_episode_refused_by_its_header_names_the_headers_own_line(tmp_path: Path) -> None:
    """The second episode's header is line 3 of the file: a refusal of it names line 3."""
    path = write(tmp_path, header(seat="robot"), step(), header(episode=1), step())
    _, second = read_trace(path)
    with pytest.raises(ModelFileError, match=rf"^{re.escape(str(path))}:3: field 'seat': 'human'"):
        check_episode(second, path, seat="robot")


def test_a_late_second_step_names_its_own_line(tmp_path: Path) -> None:
    """Header on line 1, steps at 0 s (line 2) and 64 s (line 3): the late step is the
    episode's second record, named by its own line, 3."""
    path = write(tmp_path, header(), step(), step(step=1, clock=64.0))
    (episode,) = read_trace(path)
    with pytest.raises(ModelFileError, match=rf"^{re.escape(str(path))}:3: field 'clock': 64 is 64 s after"):
        check_episode(episode, path)


def test_a_trace_file_over_64_mib_is_refused_unread(tmp_path: Path) -> None:
    """A sparse file one byte over the limit (no disk written): refused on its size alone."""
    path = write(tmp_path, header(), step())
    with path.open("r+b") as fh:
        fh.truncate(MAX_TRACE_BYTES + 1)
    assert MAX_TRACE_BYTES == 64 << 20
    with pytest.raises(ModelFileError, match=rf"^{re.escape(str(path))}: larger than 67108864 bytes$"):
        read_trace(path)


def test_a_trace_file_of_exactly_64_mib_is_read(tmp_path: Path) -> None:
    """At the limit the file is read: this one (sparse, its tail a line of NUL bytes) is then
    refused for that line's content, not for its size."""
    path = write(tmp_path, header(), step())
    with path.open("r+b") as fh:
        fh.truncate(MAX_TRACE_BYTES)
    with pytest.raises(ModelFileError, match=rf"^{re.escape(str(path))}:3: not a JSON line"):
        read_trace(path)


def test_each_episodes_steps_are_ordered_after_its_own_previous_step(tmp_path: Path) -> None:
    """A first episode ending at step 5, 100 s, 2 tasks; the second starts again from step
    0 at 0 s: its second step is checked against its own first one, not the first episode's."""
    first = [step(step=k, clock=20.0 * k, tasks_solved=min(k, 2)) for k in range(6)]
    path = write(tmp_path, header(), *first, header(episode=1), step(), step(step=1, clock=3.0))
    one, two = read_trace(path)
    assert [s["step"] for s in one.steps] == [0, 1, 2, 3, 4, 5] and [s["step"] for s in two.steps] == [0, 1]


class _Recorded:
    """An actor that keeps a record of its last decision, as the package's humans do."""

    name = "recorded"

    def __init__(self) -> None:
        self.last_decision: dict[str, object] = {}

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.last_decision = {}

    def act(self, turn: Turn) -> int:
        self.last_decision = {"expert": "recorded", "action": 30}
        return 30


def test_a_recorder_reports_the_wrapped_actors_last_decision_as_a_record(tmp_path: Path) -> None:
    actor = _Recorded()
    recorder = TraceRecorder(actor, tmp_path / "t.jsonl")
    recorder.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    assert recorder.last_decision == {}
    state = State((0, 4, 2), 0)
    obs = {"observation": PAPER.facts(state), "action_mask": PAPER.mask(state, Agent.HUMAN)}
    assert recorder.act(Turn(PAPER, state, Agent.HUMAN, obs)) == 30
    recorder.close()
    assert recorder.last_decision == {"expert": "recorded", "action": 30}
    assert recorder.last_decision is not actor.last_decision  # a copy: the wrapped record stays the actor's
