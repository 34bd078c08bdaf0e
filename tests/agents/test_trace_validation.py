"""Trace files are checked line by line: each bad line is refused with ``path:line``."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.trace import Episode, behaviour_table, read_trace
from hg_marl.core import Agent, World
from hg_marl.core.errors import HgMarlError, ModelFileError

WORLD = World("paper2015")
N_F, N_A = WORLD.n_facts, WORLD.n_actions(Agent.HUMAN)


def header() -> dict:
    return {
        "type": "header",
        "format": "hg_marl.trace",
        "version": 1,
        "episode": 0,
        "scenario": "paper2015",
        "seed": 0,
        "seat": "human",
        "actor": "test",
        "fact_names": list(WORLD.fact_names),
        "action_names": list(WORLD.action_names[Agent.HUMAN]),
        "meta": {},
    }


def step(**change: object) -> dict:
    record = {
        "type": "step",
        "step": 0,
        "clock": 0.0,
        "tasks_solved": 0,
        "facts": [0] * N_F,
        "mask": [1] * N_A,
        "action": N_A - 1,
        "action_name": WORLD.action_names[Agent.HUMAN][N_A - 1],
    }
    record.update(change)
    return record


def write(tmp_path: Path, *lines: object) -> Path:
    path = tmp_path / "t.jsonl"
    path.write_text("".join((line if isinstance(line, str) else json.dumps(line)) + "\n" for line in lines))
    return path


@pytest.mark.parametrize(
    ("bad", "field"),
    [
        ("[1, 2, 3]", "expected a JSON object"),
        ('"text"', "expected a JSON object"),
        ("{not json", "not a JSON line"),
        (step(action=3.0), "'action'"),
        (step(action=True), "'action'"),
        (step(action=N_A), "'action'"),
        (step(action=-1), "'action'"),
        (step(action=0), "'action_name'"),
        (step(facts=[0] * (N_F - 1)), "'facts'"),
        (step(facts=[2] + [0] * (N_F - 1)), "'facts'"),
        (step(mask=[0.5] * N_A), "'mask'"),
        (step(step=-1), "'step'"),
        ('{"type": "step", "step": 0, "clock": NaN}', "not a JSON line"),
        (step(clock=-1.0), "'clock'"),
        ({"type": "bogus"}, "unknown line type"),
    ],
)
def test_bad_step_line_is_refused_with_path_line(tmp_path: Path, bad: object, field: str) -> None:
    path = write(tmp_path, header(), step(), bad)
    with pytest.raises(ModelFileError, match=re.escape(f"{path}:3")) as info:
        read_trace(path)
    assert field in str(info.value)


def test_valid_trace_round_trips(tmp_path: Path) -> None:
    path = write(tmp_path, header(), step(), step(step=1, clock=1.5))
    episodes = read_trace(path)
    assert len(episodes) == 1 and episodes[0].actions == [N_A - 1, N_A - 1]


def test_bad_header_and_encoding(tmp_path: Path) -> None:
    path = write(tmp_path, {**header(), "seat": "alice"})
    with pytest.raises(ModelFileError, match=re.escape(f"{path}:1") + ".*'seat'"):
        read_trace(path)
    path.write_bytes(json.dumps(header()).encode() + b"\n\xff\xfe\n")
    with pytest.raises(ModelFileError, match="not UTF-8"):
        read_trace(path)
    with pytest.raises(HgMarlError, match="trace file not found"):
        make_human("replay", path=str(tmp_path / "missing.jsonl"))


def test_the_behaviour_table_takes_the_most_frequent_action_and_the_lowest_index_on_a_tie() -> None:
    # facts (1, 0): actions 5, 2, 5, 2 (a tie: the lowest index, 2); facts (0, 1): 7, 3, 7 (7)
    steps = [{"facts": [1, 0], "action": a} for a in (5, 2, 5, 2)] + [{"facts": [0, 1], "action": a} for a in (7, 3, 7)]
    table = behaviour_table([Episode({}, steps[:3]), Episode({}, steps[3:])])
    assert table == {bytes([1, 0]): 2, bytes([0, 1]): 7}
