"""sb3-contrib's RecurrentPPO on the batched table: unmasked play is valid, train/save/reload, run refuses it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("sb3_contrib")

from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.agents.sb3_limits import check_policy_kwargs
from hg_marl.core import Agent
from hg_marl.core.errors import HgMarlError
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.training.baselines.envs import EnvSpec
from hg_marl.training.baselines.recurrent_ppo_sb3 import (
    RecurrentSb3Config,
    greedy_play,
    load,
    make_vec,
    train,
)
from hg_marl.training.baselines.train import TrainConfig
from hg_marl.training.baselines.train import train as train_sb3


def _config(out: Path, **kw: object) -> RecurrentSb3Config:
    base = {
        "humans": ("preference", "cooperative"),
        "scenario": "forced_coordination",
        "history": 2,
        "steps": 256,
        "num_envs": 8,
        "n_steps": 16,
        "batch_size": 64,
        "n_epochs": 1,
        "lstm_hidden": 16,
        "out": out,
    }
    base.update(kw)
    return RecurrentSb3Config(**base)


def test_an_infeasible_action_is_a_no_op_that_costs_the_failed_duration(tmp_path: Path) -> None:
    """Why the unmasked policy is valid: an action outside the mask leaves the table as it was, minus time."""
    env = make_vec(_config(tmp_path, history=0), 4).env
    env.reset(seed=3)
    mask = env.action_masks()
    assert (~mask).any(axis=1).all(), "every table has an infeasible action to try"
    action = np.argmin(mask, axis=1)  # the first infeasible action of each table
    clock = env.clock.copy()
    _, reward, term, _, info = env.step(action)
    assert np.all(reward == 0) and not np.any(term)
    failed = env.world.durations.failed
    # The robot's failed action lasts `failed`; the partner's cycle may add its own time, never less.
    assert np.all(np.asarray(info["clock"]) - clock >= failed - 1e-9)


def test_train_save_reload_plays_the_same(tmp_path: Path) -> None:
    config = _config(tmp_path)
    result = train(config)
    assert result.num_timesteps >= config.steps
    assert result.path == tmp_path / "model.json" and (tmp_path / "model.npz").exists()
    again = load(result.path)
    assert type(again).__name__ == "RecurrentPPO"
    # Same weights, same LSTM: the two models act alike on a played sequence, state carried.
    env = make_vec(config, 4).env
    obs, _ = env.reset(seed=5)
    s1 = s2 = None
    starts = np.ones(4, dtype=bool)
    for _ in range(20):
        a1, s1 = result.model.predict(obs, state=s1, episode_start=starts, deterministic=True)
        a2, s2 = again.predict(obs, state=s2, episode_start=starts, deterministic=True)
        np.testing.assert_array_equal(a1, a2)
        np.testing.assert_allclose(s1[0], s2[0], atol=1e-6)
        obs, _, term, trunc, _ = env.step(np.asarray(a1))
        starts = np.asarray(term) | np.asarray(trunc)
    play = greedy_play(again, config, num_envs=4, seconds=60.0, seed=1)
    assert 0.0 <= play.infeasible <= 1.0 and play.tasks_per_hour >= 0.0


def test_the_sb3_robot_refuses_a_model_trained_with_history(tmp_path: Path) -> None:
    result = train(_config(tmp_path, steps=128, num_envs=4))
    with pytest.raises(HgMarlError, match="history"):
        make_robot("sb3", path=str(result.path))
    with pytest.raises(HgMarlError, match="RecurrentPPO"):
        make_human("learned", path=str(result.path))


def test_train_sb3_recurrent_ppo_plays_in_run_with_its_lstm_state_carried(tmp_path: Path) -> None:
    """``hg-marl train sb3 --algo recurrent_ppo``: the sb3 robot acts as SB3's own predict with the state carried."""
    config = TrainConfig(
        algo="recurrent_ppo",
        env=EnvSpec(scenario="forced_coordination", partners=("preference",)),
        steps=256,
        out=tmp_path,
        hp_overrides=("n_steps=64", "n_envs=2", "batch_size=64", "n_epochs=1", "policy_kwargs.lstm_hidden_size=16"),
        eval_freq=0,
        tensorboard=False,
    )
    result = train_sb3(config)
    robot = make_robot("sb3", path=str(result.path))
    reference = result.model  # the in-memory model: SB3's predict is the reference
    env = raw_env(scenario="forced_coordination", continuing=True, max_cycles=40)
    human = make_human("preference")
    actions, expected = [], []
    for episode in range(2):  # the second episode checks the reset: same start, same actions
        env.reset(seed=0)
        robot.reset(env.world, Agent.ROBOT, np.random.default_rng(0))
        human.reset(env.world, Agent.HUMAN, np.random.default_rng(1))
        state, start = None, np.ones(1, dtype=bool)
        for _ in range(15):
            turn = env.turn("robot")
            facts = np.asarray(turn.observation["observation"])
            want, state = reference.predict(facts, state=state, episode_start=start, deterministic=True)
            start = np.zeros(1, dtype=bool)
            got = robot.act(turn)
            actions.append((episode, got))
            expected.append((episode, int(want)))
            env.step(got)
            env.step(human.act(env.turn("human")))
    assert actions == expected
    assert [a for e, a in actions if e == 0] == [a for e, a in actions if e == 1]


def test_a_header_asking_for_a_huge_lstm_is_refused() -> None:
    for bad in ({"lstm_hidden_size": 10**6}, {"n_lstm_layers": 0}, {"lstm_hidden_size": True}):
        with pytest.raises(HgMarlError, match="lstm"):
            check_policy_kwargs(bad, "policy_kwargs", HgMarlError)
    check_policy_kwargs({"lstm_hidden_size": 64, "n_lstm_layers": 1}, "policy_kwargs", HgMarlError)


def test_bad_config_names_the_field(tmp_path: Path) -> None:
    with pytest.raises(HgMarlError, match="lstm_hidden"):
        train(_config(tmp_path, lstm_hidden=0))
    with pytest.raises(HgMarlError, match="learning_rate"):
        train(_config(tmp_path, learning_rate=float("nan")))


def test_recurrent_ppo_trains_the_robot_seat_only() -> None:
    with pytest.raises(HgMarlError, match="robot seat only"):
        TrainConfig(algo="recurrent_ppo", env=EnvSpec(seat="human", partners=("planner",)))
