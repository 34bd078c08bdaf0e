"""Play -> learned human: cloning recorded play, and the statistics of recorded play."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.trace import read_trace
from hg_marl.core import Agent
from hg_marl.training.cli import app
from hg_marl.training.play.session import PlaySession
from hg_marl.training.play.stats import episode_stats
from tests.play.reference import person_choice


def record_games(directory: Path, seeds: list[int], robot: str = "planner", tasks: int = 1) -> None:
    for seed in seeds:
        session = PlaySession(robot, seed=seed, record=directory, player="tester")
        while session.tasks_solved < tasks:
            session.play(person_choice([c.name for c in session.choices()]))
        session.close()


def test_bc_on_a_play_directory_gives_a_learned_human_that_plays_like_the_person(tmp_path: Path) -> None:
    record_games(tmp_path / "play", [0, 1])
    out = tmp_path / "policy"
    result = CliRunner().invoke(app, ["train", "--algo", "bc", "--traces", str(tmp_path / "play"), "--out", str(out)])
    assert result.exit_code == 0, result.output
    human = make_human("learned", path=str(out), deterministic=True)
    steps = [s for f in sorted((tmp_path / "play").glob("*.jsonl")) for e in read_trace(f) for s in e.steps]
    from hg_marl.core import World

    world = World("paper2015")
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    # the person's policy is deterministic in the facts, so the table reproduces every move
    for step in steps:
        p = human.probabilities(np.array(step["facts"], dtype=np.int8), np.array(step["mask"], dtype=bool))
        assert int(np.argmax(p)) == step["action"]


def test_episode_stats_by_hand(tmp_path: Path) -> None:
    record_games(tmp_path, [0])
    (episode,) = read_trace(next(tmp_path.glob("*.jsonl")))
    names = [s["action_name"] for s in episode.steps]
    stats = episode_stats(episode)
    # hand count: the cooperative person's game on seed 0 (see test_session): pick, 3 waits, give, 7 waits
    assert names == ["pick(tape3)", "wait", "wait", "wait", "give(tape3)"] + ["wait"] * 7
    assert (stats.moves, stats.tasks, stats.moves_per_task) == (12, 1, 12.0)
    assert stats.shares["wait"] == pytest.approx(10 / 12) and stats.shares["give"] == pytest.approx(1 / 12)
    assert stats.handover_acceptance is None  # the planner never offered to the person
    assert stats.who == "tester" and stats.robot == "planner" and len(stats.response_times) == 12


def test_traces_command_names_the_closest_scripted_human(tmp_path: Path) -> None:
    record_games(tmp_path, [0, 2])
    result = CliRunner().invoke(app, ["traces", str(tmp_path)])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0] == "2 session(s) by tester against planner"
    assert [line.split()[0] for line in lines[2:9]] == [
        "recorded", "cooperative", "lazy", "no_handover", "adversarial", "random", "noisy",
    ]  # fmt: skip
    # the person hands tape3 over at once and otherwise waits: that is the cooperative human
    assert lines[-1].startswith("closest scripted human: cooperative")
