"""Values that round 195's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import torch

from hg_marl.agents.humans.trace import read_trace
from hg_marl.agents.memory_policy import MemoryNet
from hg_marl.training.play.replay import MARGIN, replay_trace
from hg_marl.training.play.session import PlaySession
from tests.play.reference import person_choice
from tests.training.test_pinned_round96 import _RandomFeasible


def test_only_the_tables_whose_episode_starts_get_a_fresh_hidden_state() -> None:
    # Two tables carrying a hidden state of 0.5s; only table 0 starts its episode here. The
    # reference is the GRU cell itself: table 0's next state is the cell from zeros, table 1's
    # the cell from its carried state (so the two rows differ, although their inputs are equal).
    torch.manual_seed(0)
    net = MemoryNet(3, 2, hidden=4, recurrent=True)
    obs = torch.tensor([[1.0, 0.0, 1.0], [1.0, 0.0, 1.0]])
    h = torch.full((2, 4), 0.5)
    start = torch.tensor([True, False])
    with torch.no_grad():
        _, _, after = net.step(obs, h, start)
        assert net.gru is not None
        x = net.encoder(obs)
        fresh = net.gru(x[:1], torch.zeros(1, 4))
        carried = net.gru(x[1:], h[1:])
    assert not torch.allclose(fresh, carried), "the control: a carried state changes the step"
    assert torch.allclose(after[0], fresh[0], atol=1e-6)
    assert torch.allclose(after[1], carried[0], atol=1e-6)


def _game(folder: Path, seed: int, moves: int) -> Path:
    session = PlaySession("planner", seed=seed, record=folder, player="tester")
    for _ in range(moves):
        session.play(person_choice([c.name for c in session.choices()]))
    path = session.close()
    assert path is not None
    return path


def test_a_replay_of_the_second_episode_replays_that_episode(tmp_path: Path) -> None:
    # Two recorded games in one trace: 2 moves with seed 3, then 8 moves with seed 5. Episode 1's
    # replay runs the second game to its own end clock plus MARGIN and earns its own rewards (the
    # recording's end line); episode 0's game ended earlier, so its replay's clock would fall short.
    first, second = _game(tmp_path / "a", 3, 2), _game(tmp_path / "b", 5, 8)
    both = tmp_path / "both.jsonl"
    both.write_text(first.read_text() + second.read_text())
    episodes = read_trace(both)
    assert len(episodes) == 2
    recorded = float(episodes[1].end["clock"])
    assert float(episodes[0].end["clock"]) < recorded, "the control: the first game is the shorter"
    result = replay_trace(both, episode=1)
    assert (result.seed, result.moves) == (5, 8)
    assert result.recorded_clock == recorded
    assert recorded < result.clock <= recorded + 60.0
    assert result.rewards == pytest.approx(float(episodes[1].end["rewards"]))
    assert MARGIN > 0


def test_greedy_play_resets_the_tables_with_the_seed_it_was_given(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The config trains with seed 0; greedy play is asked for seed 7, so its one reset gets 7.
    pytest.importorskip("stable_baselines3")
    from hg_marl.training.baselines import recurrent_ppo_sb3
    from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config, greedy_play

    config = RecurrentSb3Config(
        humans=("cooperative",), scenario="forced_coordination", history=0, episode_seconds=600.0, out=tmp_path
    ).check()
    assert config.seed == 0
    model = _RandomFeasible()
    seeds: list[Any] = []
    make = recurrent_ppo_sb3.make_vec

    def spying(config: RecurrentSb3Config, num_envs: int) -> Any:
        venv = make(config, num_envs)
        env, reset = venv.env, venv.env.reset
        model.env = env

        def recorded(*args: Any, **kwargs: Any) -> Any:
            seeds.append(kwargs.get("seed"))
            return reset(*args, **kwargs)

        env.reset = recorded
        return venv

    monkeypatch.setattr(recurrent_ppo_sb3, "make_vec", spying)
    greedy_play(model, config, num_envs=2, seconds=30.0, seed=7)
    assert seeds == [7]
