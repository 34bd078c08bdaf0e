"""The ``replay`` human (``agents/humans/replay.py``), pinned for the mutation gate.

The traces are written by hand here (the format of ``agents/humans/trace.py``: a header
line, then one step line per turn), two episodes of ``paper2015`` in the human's seat
that tell each other apart by their actions: episode 0 plays ``pick(tape3)`` (2) then
``wait`` (30), episode 1 plays ``throw(tape1)`` (3). Every step records the facts of
``State((0, 1, 4), 0)``; a turn at another state shows a divergence.
"""

from __future__ import annotations

import json
import logging
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.humans.replay import ReplayHuman
from hg_marl.agents.humans.trace import FORMAT, VERSION
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn

PAPER = World("paper2015")
RECORDED = State((0, 1, 4), 0)
EPISODES = ([2, 30], [3])


def write_trace(path: Path, episodes: tuple[list[int], ...] = EPISODES) -> Path:
    facts = [int(v) for v in PAPER.facts(RECORDED)]
    mask = [int(v) for v in PAPER.mask(RECORDED, Agent.HUMAN)]
    lines = []
    for actions in episodes:
        lines.append(
            {
                "type": "header",
                "format": FORMAT,
                "version": VERSION,
                "scenario": "paper2015",
                "seed": 0,
                "seat": "human",
                "fact_names": list(PAPER.fact_names),
                "action_names": list(PAPER.action_names[Agent.HUMAN]),
            }
        )
        for step, action in enumerate(actions):
            lines.append({"type": "step", "step": step, "action": action, "facts": facts, "mask": mask, "clock": 0.0})
    path.write_text("".join(json.dumps(line) + "\n" for line in lines))
    return path


def turn(state: State = RECORDED) -> Turn:
    obs = {"observation": PAPER.facts(state), "action_mask": PAPER.mask(state, Agent.HUMAN)}
    return Turn(PAPER, state, Agent.HUMAN, obs)


def start(human: ReplayHuman, world: World = PAPER, agent: Agent = Agent.HUMAN) -> None:
    human.reset(world, agent, np.random.default_rng(0))


def runtime(text: str) -> str:
    """``text`` as a string built at run time, as one read from a command line or a file is (not interned)."""
    return "".join(list(text))


def test_each_reset_plays_the_next_episode_from_its_first_step(tmp_path: Path) -> None:
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"))
    start(human)
    assert [human.act(turn()), human.act(turn())] == [2, 30]
    assert human.last_decision == {"human": "replay", "action": "wait", "step": 1}
    start(human)
    assert human.act(turn()) == 3


def test_without_loop_a_reset_past_the_last_episode_is_refused(tmp_path: Path) -> None:
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"))
    start(human)
    start(human)
    with pytest.raises(ValueError, match=r"only 2 episode\(s\) recorded; pass loop=True"):
        start(human)


def test_with_loop_the_replay_starts_again_at_the_first_episode(tmp_path: Path) -> None:
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"), loop=True)
    played = []
    for _ in range(5):
        start(human)
        played.append(human.act(turn()))
    assert played == [2, 3, 2, 3, 2]


def test_a_trace_of_other_actions_is_refused_at_reset(tmp_path: Path) -> None:
    """paper2015's human actions are neither asymmetric_advantages' human's nor paper2015's robot's."""
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"), loop=True)
    with pytest.raises(ValueError, match="its actions do not match 'asymmetric_advantages' as 'human'"):
        start(human, World("asymmetric_advantages"))
    with pytest.raises(ValueError, match="do not match 'paper2015' as 'robot'"):
        start(human, PAPER, Agent.ROBOT)


def test_once_the_steps_run_out_the_replay_waits_by_default(tmp_path: Path) -> None:
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl", ([2],)))
    start(human)
    assert [human.act(turn()) for _ in range(3)] == [2, 30, 30]


def test_once_the_steps_run_out_on_end_error_raises(tmp_path: Path) -> None:
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl", ([2],)), on_end=runtime("error"))
    start(human)
    assert human.act(turn()) == 2
    with pytest.raises(ValueError, match="episode 0 has only 1 steps"):
        human.act(turn())


@pytest.mark.parametrize(
    "live",
    [State((0, 1, 4), 1), State((0, 1, 4), 3)],
    ids=["facts_above", "facts_below"],
)
def test_a_divergence_raises_by_default_whichever_way_the_facts_differ(tmp_path: Path, live: State) -> None:
    """The robot at ``table_left`` reaches tape1 and tape2 (facts 0 and 1 set, above the recorded
    ones, which start 0, 0, 0, 1 with the robot at the bin); at ``human_side`` it reaches
    nothing (all four 0, below them)."""
    assert PAPER.facts(live).tolist() != PAPER.facts(RECORDED).tolist()
    for on_mismatch in ("error", runtime("error")):
        human = ReplayHuman(write_trace(tmp_path / "t.jsonl"), on_mismatch=on_mismatch)
        start(human)
        with pytest.raises(ValueError, match="the run diverged from the recording"):
            human.act(turn(live))


def test_a_divergence_is_warned_once_per_episode_and_played_through(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"), on_mismatch=runtime("warn"))
    moved = State((0, 1, 4), 1)  # the robot at table_left, not at the bin
    with caplog.at_level(logging.WARNING, logger="hg_marl.agents.humans.replay"):
        start(human)
        assert [human.act(turn(moved)), human.act(turn(moved))] == [2, 30]
        assert len(caplog.records) == 1 and "episode 0 step 0" in caplog.records[0].getMessage()
        start(human)
        assert human.act(turn(moved)) == 3
    assert len(caplog.records) == 2 and "episode 1 step 0" in caplog.records[1].getMessage()


def test_ignore_plays_the_recording_whatever_the_live_facts(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"), on_mismatch="ignore")
    with caplog.at_level(logging.WARNING):
        start(human)
        assert [human.act(turn(State((0, 1, 4), 1))), human.act(turn(State((0, 1, 4), 3)))] == [2, 30]
    assert caplog.records == []


def test_bad_settings_are_refused(tmp_path: Path) -> None:
    path = write_trace(tmp_path / "t.jsonl")
    with pytest.raises(ValueError, match="replay needs path"):
        ReplayHuman()
    with pytest.raises(ValueError, match="on_mismatch must be one of"):
        ReplayHuman(path, on_mismatch="shout")
    with pytest.raises(ValueError, match="on_end must be one of"):
        ReplayHuman(path, on_end="stop")
    assert ReplayHuman(path).loop is False


def test_a_long_trace_is_refused_one_reset_past_its_last_episode(tmp_path: Path) -> None:
    """300 one-step episodes (more than Python's cached small integers): the 301st reset is refused."""
    human = ReplayHuman(write_trace(tmp_path / "long.jsonl", tuple([2] for _ in range(300))))
    for _ in range(300):
        start(human)
    assert human.episode == 299
    with pytest.raises(ValueError, match=r"only 300 episode\(s\) recorded"):
        start(human)
