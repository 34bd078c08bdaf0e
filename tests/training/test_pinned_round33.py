"""Round 33 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated by hand or from the documented rule, not computed with the
code under test.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from typer.testing import CliRunner

from hg_marl.core import Agent, World
from hg_marl.core.errors import ModelFileError
from hg_marl.core.types import Event
from hg_marl.training.cli import app


def test_an_episode_of_one_cycle_is_accepted_and_zero_refused() -> None:
    """``max_cycles`` must be positive: 1 is, 0 is not."""
    from hg_marl.training.baselines.envs import EnvSpec

    assert EnvSpec(max_cycles=1).max_cycles == 1
    with pytest.raises(ValueError, match="max_cycles must be positive"):
        EnvSpec(max_cycles=0)


def test_convert_algo_option_overrides_the_old_metadata(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``--algo`` overrides what the old JSON beside the zip says (the docstring's "override or supply")."""
    from hg_marl.training.baselines import convert

    zip_path = tmp_path / "model.zip"
    zip_path.write_bytes(b"not really a zip")
    (tmp_path / "model.json").write_text('{"format": "hg_marl.sb3", "algo": "PPO"}', encoding="utf-8")
    asked: list[str] = []

    class Loader:
        @staticmethod
        def load(path: Path, device: str) -> None:
            raise ValueError("stop here")

    def fake_algo_class(name: str) -> type[Loader]:
        asked.append(name)
        return Loader

    monkeypatch.setattr(convert, "algo_class", fake_algo_class)
    with pytest.raises(ModelFileError, match="SB3 could not load it"):
        convert.convert_zip(zip_path, trust=True, algo="DQN")
    assert asked == ["DQN"]
    asked.clear()
    with pytest.raises(ModelFileError):
        convert.convert_zip(zip_path, trust=True)  # no option: the metadata supplies it
    assert asked == ["PPO"]


def test_an_event_without_an_object_still_names_its_place() -> None:
    """``str(event)`` reads as a sentence: agent, kind, object if any, place if any."""
    assert str(Event("moved", "robot", "", "table_left")) == "robot moved table_left"
    assert str(Event("completed", "robot", "", "task")) == "robot completed task"
    assert str(Event("took", "human", "tape1")) == "human took tape1"
    assert str(Event("threw", "robot", "tape1", "trashbin")) == "robot threw tape1 trashbin"


def test_the_recorder_keeps_exactly_max_frames(monkeypatch: pytest.MonkeyPatch) -> None:
    """``max_frames`` frames at most: with 2, three captures keep 2 and drop 1."""
    from hg_marl.training import video

    monkeypatch.setattr(video, "caption_of", lambda *args: "")
    monkeypatch.setattr(video, "render_rgb", lambda world, state, caption: np.zeros((2, 2, 3), np.uint8))
    recorder = video.FrameRecorder(SimpleNamespace(name="r"), max_frames=2)
    turn = SimpleNamespace(world=None, state=None, clock=0.0, tasks_solved=0, last_actions=(0, 0))
    for _ in range(3):
        recorder.capture(turn)
    assert len(recorder.frames) == 2
    assert recorder.dropped == 1


def test_compare_command_evaluates_on_the_configs_seeds(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``--eval-seeds 2`` means the seeds 100 and 101, CompareConfig's documented default."""
    from hg_marl.training.baselines import compare as compare_module

    seen: list = []

    class Stop(Exception):
        pass

    def fake_compare(config, on_cell=None):
        seen.append(config)
        raise Stop

    monkeypatch.setattr(compare_module, "compare", fake_compare)
    result = CliRunner().invoke(
        app, ["compare", "--algos", "ppo", "--humans", "cooperative", "--eval-seeds", "2", "--out", str(tmp_path / "c")]
    )
    assert isinstance(result.exception, Stop), result.output
    assert seen[0].eval_seeds == (100, 101)


def test_replay_command_compares_a_recording_with_zero_rewards(monkeypatch: pytest.MonkeyPatch) -> None:
    """A recorded end line with rewards 0 is compared too (only a missing one is not)."""
    from hg_marl.training.play import replay

    def fake_replay(trace, episode=0, robot=None, video=None):
        return replay.ReplayResult("paper2015", 3, "planner", "ann", 4, 0, 0.0, 12.0, 11.5, 0.0)

    monkeypatch.setattr(replay, "replay_trace", fake_replay)
    result = CliRunner().invoke(app, ["replay", "trace.jsonl"])
    assert result.exit_code == 0, result.output
    assert "same as the recording (rewards 0)" in result.output


def test_the_uniform_noise_human_draws_among_all_actions() -> None:
    """``feasible_only=False``: every action of the seat, each with probability 1/n."""
    from hg_marl.agents.humans.random_human import RandomHuman

    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    n = world.n_actions(Agent.HUMAN)
    dist = RandomHuman(feasible_only=False).distribution_for(world, state, Agent.HUMAN)
    assert [a for a, _ in dist] == list(range(n))
    assert all(p == pytest.approx(1.0 / n) for _, p in dist)
