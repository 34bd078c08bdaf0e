"""The SB3 trainer's settings, rollouts, resume, evaluation and checkpoints, pinned for the mutation gate.

Expected values are worked by hand from the module's documented rules: the defaults and
limits of :class:`TrainConfig`; a rollout is ``n_steps`` (2048 by default) or DQN's
``train_freq`` (4 by default) times ``n_envs``; a resumed model keeps its checkpoint's
hyperparameters and is seeded ``seed + steps done``; the evaluation runs every
``eval_freq`` steps (``eval_freq // n_envs`` calls) on a view seeded ``seed + 10000``;
checkpoints go to ``OUT/checkpoints``. The trainings here are tiny (64-step rollouts,
at most 128 steps); the SB3 model is replaced by a stand-in where only the wiring is
checked. Nothing is timed.
"""

from __future__ import annotations

import dataclasses
import logging
import math
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, HgMarlError, ModelFileError
from hg_marl.training.baselines import train as train_module
from hg_marl.training.baselines.envs import EnvSpec
from hg_marl.training.baselines.hyperparams import Hyperparams, accepted_keys
from hg_marl.training.baselines.train import (
    EVAL_SEED_OFFSET,
    MAX_STEPS,
    TrainConfig,
    TrainResult,
    _eval_callback,
    _load,
    _resume_hyperparams,
    header_fields,
    rollout_steps,
    train,
)

SMALL = ("n_envs=1", "n_steps=64", "batch_size=32", "n_epochs=1", "policy_kwargs.net_arch=[8]")


def test_the_defaults_are_the_documented_ones() -> None:
    config = TrainConfig()
    assert (config.algo, config.env, config.steps, config.seed) == ("maskable_ppo", EnvSpec(), None, 0)
    assert (config.out, config.hp_overrides, config.hyperparams_file) == (Path("runs/train"), (), None)
    assert (config.eval_freq, config.eval_episodes, config.checkpoint_freq, config.resume) == (10_000, 10, None, None)
    assert (config.tensorboard, config.progress_bar, config.torch_threads, config.verbose) == (True, False, 1, 0)
    assert (MAX_STEPS, EVAL_SEED_OFFSET) == (10**9, 10_000)


def test_a_configuration_is_frozen() -> None:
    with pytest.raises(dataclasses.FrozenInstanceError):
        TrainConfig().seed = 1


def test_the_bounds_accepted() -> None:
    config = TrainConfig(steps=MAX_STEPS, eval_freq=0, eval_episodes=1, seed=0, checkpoint_freq=0)
    assert (config.steps, config.eval_freq, config.checkpoint_freq) == (10**9, 0, 0)
    assert TrainConfig(steps=1).steps == 1


@pytest.mark.parametrize(
    ("changes", "match"),
    [
        ({"algo": "sac"}, "unknown algorithm 'sac'"),
        ({"algo": "recurrent_ppo", "env": EnvSpec(seat="human", partners=("planner",))}, "robot seat only"),
        ({"steps": 0}, r"--steps: expected an integer >= 1"),
        ({"steps": 10**9 + 1}, r"--steps: expected an integer <= 1000000000"),
        ({"eval_freq": -1}, r"--eval-freq: expected an integer >= 0"),
        ({"eval_episodes": 0}, r"--eval-episodes: expected an integer >= 1"),
        ({"seed": -1}, r"--seed: expected an integer >= 0"),
        ({"checkpoint_freq": -1}, r"--checkpoint-freq: expected an integer >= 0"),
    ],
)
def test_settings_out_of_range_are_refused_by_their_option(changes: dict[str, Any], match: str) -> None:
    with pytest.raises(HgMarlError, match=match):
        TrainConfig(**changes)


def test_throughput_is_this_calls_steps_over_its_seconds() -> None:
    """90 steps taken in this call (of 500 in all) over 4 s: 22.5 per second; no time, no figure."""
    result = TrainResult(None, Path("m.json"), Hyperparams("ppo"), 500, 90, 4.0)
    assert result.steps_per_second == 22.5
    assert math.isnan(TrainResult(None, Path("m.json"), Hyperparams("ppo"), 500, 90, 0.0).steps_per_second)
    assert (result.checkpoints, result.interrupted) == ([], False)


def test_a_rollout_is_the_per_environment_steps_times_the_environments() -> None:
    assert rollout_steps(Hyperparams("ppo", n_envs=3)) == 2048 * 3  # PPO's default n_steps
    assert rollout_steps(Hyperparams("dqn", n_envs=2)) == 4 * 2  # DQN's default train_freq
    assert rollout_steps(Hyperparams("a2c", n_envs=2, kwargs={"n_steps": 5})) == 10
    assert rollout_steps(Hyperparams("dqn", kwargs={"train_freq": [8, "step"]})) == 8
    assert rollout_steps(Hyperparams("dqn", kwargs={"train_freq": (3, "step")}, n_envs=2)) == 6
    assert rollout_steps(Hyperparams("dqn", kwargs={"train_freq": 0})) == 1  # at least one step


def test_the_header_records_the_world_seat_and_training() -> None:
    config = TrainConfig(algo="a2c", seed=7, env=EnvSpec(seat="human", partners=("planner",), max_cycles=9))
    hp = Hyperparams("a2c", n_envs=2, kwargs={"gamma": 0.5})
    world = World("paper2015")
    fields = header_fields(config, hp, world)
    assert fields["seat"] == "human" and fields["action_names"] == list(world.action_names[Agent.HUMAN])
    assert fields["scenario"] == "paper2015" and fields["fact_names"] == list(world.fact_names)
    assert fields["train"] == {
        "seat": "human",
        "partners": ("planner",),
        "scenario": "paper2015",
        "observation": "facts",
        "max_cycles": 9,
        "effort_weight": 0.0,
        "seed": 7,
        "hyperparams": {"algo": "a2c", "policy": "MlpPolicy", "n_envs": 2, "n_timesteps": 100_000, "gamma": 0.5},
    }
    robot = header_fields(TrainConfig(), Hyperparams("maskable_ppo"), world)
    assert robot["seat"] == "robot" and robot["action_names"] == list(world.action_names[Agent.ROBOT])


def _checkpoint(hyperparams: Any, path: str = "ck.json") -> Any:
    return SimpleNamespace(path=Path(path), header={"train": {"hyperparams": hyperparams}})


def test_a_checkpoints_own_hyperparameters_are_resumed() -> None:
    algo = "a2c"
    stored = {"algo": algo, "policy": "MlpPolicy", "n_envs": 3, "n_timesteps": 900, "gamma": 0.5, "n_steps": 7}
    hp = _resume_hyperparams(_checkpoint(stored), TrainConfig(algo=algo))
    assert hp == Hyperparams("a2c", "MlpPolicy", 3, 900, {"gamma": 0.5, "n_steps": 7})
    json_algo = "".join(["a2", "c"])  # as read from a file: equal, not the same object
    bare = _resume_hyperparams(_checkpoint({"algo": json_algo}), TrainConfig(algo="a2c"))
    assert (bare.policy, bare.n_envs, bare.n_timesteps, dict(bare.kwargs)) == ("MlpPolicy", 1, 1, {})


@pytest.mark.parametrize(
    ("header", "error", "match"),
    [
        ({}, ModelFileError, r"ck\.json: no 'train.hyperparams' \(not a checkpoint written by hg-marl train\)"),
        ({"train": "x"}, ModelFileError, "no 'train.hyperparams'"),
        ({"train": {"hyperparams": [1]}}, ModelFileError, "no 'train.hyperparams'"),
        ({"train": {"hyperparams": {"algo": "dqn"}}}, ConfigError, r"was trained with --algo dqn, not --algo a2c"),
        (
            {"train": {"hyperparams": {"algo": "a2c", "zeta": 1, "alpha": 2}}},
            ModelFileError,
            r"field 'train.hyperparams': unknown key\(s\) alpha, zeta$",
        ),
        ({"train": {"hyperparams": {"algo": "a2c", "n_envs": 257}}}, ModelFileError, r"n_envs'.*<= 256"),
        ({"train": {"hyperparams": {"algo": "a2c", "n_envs": 0}}}, ModelFileError, r"n_envs'.*>= 1"),
        ({"train": {"hyperparams": {"algo": "a2c", "n_timesteps": 0}}}, ModelFileError, r"n_timesteps'.*>= 1"),
    ],
)
def test_a_checkpoint_that_cannot_be_resumed_is_refused(header: dict[str, Any], error: type, match: str) -> None:
    with pytest.raises(error, match=match):
        _resume_hyperparams(SimpleNamespace(path=Path("ck.json"), header=header), TrainConfig(algo="a2c"))


def test_the_algorithms_own_keys_are_all_resumable() -> None:
    stored = {"algo": "a2c", **{key: None for key in accepted_keys("a2c")}}
    assert set(_resume_hyperparams(_checkpoint(stored), TrainConfig(algo="a2c")).kwargs) == set(accepted_keys("a2c"))


class _Built:
    def __init__(self, steps: int, buffer: Any) -> None:
        self.num_timesteps = steps
        self.replay_buffer = buffer
        self.seeds: list[int] = []

    def set_random_seed(self, seed: int) -> None:
        self.seeds.append(seed)


def test_a_resumed_model_is_rebuilt_with_its_buffer_and_seeded_after_its_steps(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Seed 5 resumed at 64 steps: seeded 69; TensorBoard under OUT/tb; the network's shape left to the file."""
    built: list[tuple[Any, Any, dict[str, Any]]] = []
    buffers: list[tuple[Any, Path, Any]] = []
    model = _Built(64, "buffer")

    def fake_build(mf: Any, env: Any, **kwargs: Any) -> _Built:
        built.append((mf, env, kwargs))
        return model

    monkeypatch.setattr(train_module, "build_sb3", fake_build)
    monkeypatch.setattr(train_module, "load_replay_buffer", lambda b, p, e: buffers.append((b, p, e)))
    mf = SimpleNamespace(path=tmp_path / "ck.json", header={"replay_buffer": {"file": "x"}})
    read_key = "".join(["policy_", "kwargs"])  # as read from a checkpoint: equal, not the same object
    hp = Hyperparams("dqn", kwargs={"gamma": 0.5, read_key: {"net_arch": [4]}})
    config = TrainConfig(algo="dqn", seed=5, out=tmp_path / "out", verbose=2)
    assert _load(config, mf, hp, "env") is model
    assert built == [(mf, "env", {"tensorboard_log": str(tmp_path / "out" / "tb"), "verbose": 2, "gamma": 0.5})]
    assert buffers == [("buffer", tmp_path / "ck.json", {"file": "x"})]
    assert model.seeds == [69]
    quiet = _load(TrainConfig(algo="dqn", tensorboard=False), SimpleNamespace(path=mf.path, header={}), hp, "env")
    assert built[-1][2]["tensorboard_log"] is None and len(buffers) == 1 and quiet.seeds == [69, 64]


def test_the_evaluation_is_masked_greedy_and_on_its_own_seeds(tmp_path: Path) -> None:
    """MaskablePPO: sb3-contrib's masked callback; 1000 steps over 4 environments is a call every 250."""
    from sb3_contrib.common.maskable.callbacks import MaskableEvalCallback
    from stable_baselines3.common.callbacks import EvalCallback

    saved: list[tuple[Any, Path]] = []
    config = TrainConfig(seed=3, eval_freq=1000, eval_episodes=2, out=tmp_path, env=EnvSpec(max_cycles=5))
    callback = _eval_callback(config, Hyperparams("maskable_ppo", n_envs=4), lambda m, p: saved.append((m, p)))
    assert isinstance(callback, MaskableEvalCallback)
    assert (callback.eval_freq, callback.n_eval_episodes, callback.deterministic) == (250, 2, True)
    assert callback.log_path is not None and Path(callback.log_path).parent == tmp_path / "eval"
    assert callback.best_model_save_path is None
    obs: Any = callback.eval_env.reset()
    alone, _ = EnvSpec(max_cycles=5).make().reset(seed=3 + 10_000)
    assert np.array_equal(obs[0], alone)
    best: Any = callback.callback_on_new_best
    model = SimpleNamespace(num_timesteps=5)
    best.init_callback(model)
    assert best.on_step() is True
    assert saved == [(model, tmp_path / "eval" / "best_model.json")]
    plain = _eval_callback(TrainConfig(algo="ppo", eval_freq=3, out=tmp_path), Hyperparams("ppo", n_envs=4), print)
    assert type(plain) is EvalCallback and plain.eval_freq == 1  # 3 // 4 is 0: at least every call


def test_a_small_training_writes_its_checkpoints_under_out(tmp_path: Path) -> None:
    """128 steps in rollouts of 64, a checkpoint every 64: the rollout starting at 64 writes ``ckpt_64_steps``."""
    result = train(
        TrainConfig(
            algo="maskable_ppo",
            steps=128,
            out=tmp_path,
            hp_overrides=SMALL,
            eval_freq=0,
            checkpoint_freq=64,
            tensorboard=False,
        )
    )
    assert [p.relative_to(tmp_path) for p in result.checkpoints] == [Path("checkpoints/ckpt_64_steps.json")]
    assert result.path == tmp_path / "model.json" and (result.num_timesteps, result.session_steps) == (128, 128)


def test_a_checkpoint_already_at_the_budget_trains_nothing(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    first = train(
        TrainConfig(steps=64, out=tmp_path / "a", hp_overrides=SMALL, eval_freq=0, checkpoint_freq=0, tensorboard=False)
    )
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.baselines.train"):
        again = train(
            TrainConfig(
                steps=64, out=tmp_path / "b", resume=first.path, eval_freq=0, checkpoint_freq=0, tensorboard=False
            )
        )
    assert "checkpoint already has 64 >= 64 steps: nothing to train" in caplog.text
    assert (again.num_timesteps, again.session_steps) == (64, 0)
