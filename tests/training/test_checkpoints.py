"""Training you cannot lose: checkpoint frequency, exact restore, stop on signals, kill and resume."""

from __future__ import annotations

import json
import os
import signal
from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("stable_baselines3")
pytest.importorskip("sb3_contrib")

import torch
from stable_baselines3.common.callbacks import BaseCallback

from hg_marl.agents.model_file import build_sb3, load_model_file
from hg_marl.training.baselines.callbacks import save_checkpoint
from hg_marl.training.baselines.hyperparams import Hyperparams
from hg_marl.training.baselines.train import TrainConfig, checkpoint_every, train

torch.set_num_threads(1)

SMALL = ("n_envs=1", "n_steps=64", "batch_size=32", "n_epochs=2")
ROLLOUT = 64


def config(tmp_path: Path, steps: int = 256, **kw: Any) -> TrainConfig:
    base: dict[str, Any] = {
        "algo": "maskable_ppo",
        "steps": steps,
        "seed": 0,
        "out": tmp_path,
        "hp_overrides": SMALL,
        "eval_freq": 0,
        "tensorboard": False,
    }
    base.update(kw)
    return TrainConfig(**base)


@pytest.mark.parametrize(
    ("algo", "kwargs", "n_envs", "total", "given", "expected"),
    [
        # a tenth of 100000 is 10000, rounded up to whole rollouts of 256 x 4 = 1024: 10 rollouts
        ("ppo", {"n_steps": 256}, 4, 100_000, None, 10_240),
        # DQN collects train_freq=4 steps per rollout: a tenth of 1000 is 25 rollouts
        ("dqn", {"train_freq": 4}, 1, 1_000, None, 100),
        # a given frequency is rounded up to whole rollouts too
        ("ppo", {"n_steps": 256}, 4, 100_000, 1_000, 1_024),
        ("ppo", {"n_steps": 256}, 4, 100_000, 0, 0),
        # a budget shorter than a rollout still checkpoints once per rollout
        ("a2c", {"n_steps": 5}, 2, 30, None, 10),
    ],
)
def test_checkpoint_frequency(algo: str, kwargs: dict, n_envs: int, total: int, given: Any, expected: int) -> None:
    hp = Hyperparams(algo, n_envs=n_envs, kwargs=kwargs)
    cfg = TrainConfig(algo=algo, checkpoint_freq=given)
    assert checkpoint_every(cfg, hp, total) == expected


def test_checkpoint_restores_weights_optimizer_and_counters(tmp_path: Path) -> None:
    result = train(config(tmp_path / "a", steps=192, checkpoint_freq=0))
    model = result.model
    path = save_checkpoint(model, tmp_path / "ck.json", {**_fields(result)}, "facts")
    again = build_sb3(load_model_file(path))
    for key, tensor in model.policy.state_dict().items():
        assert torch.equal(tensor, again.policy.state_dict()[key]), key
    saved, loaded = model.policy.optimizer.state_dict(), again.policy.optimizer.state_dict()
    assert saved["param_groups"][0]["lr"] == loaded["param_groups"][0]["lr"]
    assert len(saved["state"]) == len(loaded["state"]) > 0
    for index, entries in saved["state"].items():
        for name, value in entries.items():
            assert torch.equal(torch.as_tensor(value), torch.as_tensor(loaded["state"][index][name])), (index, name)
    assert (again.num_timesteps, again._n_updates) == (model.num_timesteps, model._n_updates) == (192, 6)


def _fields(result: Any) -> dict[str, Any]:
    header = load_model_file(result.path).header
    keys = ("seat", "scenario", "scenario_name", "fact_names", "action_names", "train")
    return {k: header[k] for k in keys}


class Killer(BaseCallback):
    """Sends ``signum`` to this process when ``num_timesteps`` reaches ``at``."""

    def __init__(self, at: int, signum: int) -> None:
        super().__init__()
        self.at, self.signum, self.sent = at, signum, False

    def _on_step(self) -> bool:
        if not self.sent and self.num_timesteps >= self.at:
            self.sent = True
            os.kill(os.getpid(), self.signum)
        return True


def _kill_and_resume(tmp_path: Path, at: int, signum: int) -> None:
    handler_before = signal.getsignal(signum)
    first = train(config(tmp_path / "a", checkpoint_freq=0), callbacks=[Killer(at, signum)])
    assert first.interrupted and first.checkpoints, "a stop must write a checkpoint"
    header = json.loads(first.path.read_text())
    steps = header["counters"]["num_timesteps"]
    # Wound back to the start of the interrupted rollout: every counted step was trained on.
    assert steps % ROLLOUT == 0 and at - ROLLOUT < steps <= at, (at, steps)
    assert first.path.name == f"ckpt_{steps}_steps.json"
    resumed = train(config(tmp_path / "b", resume=first.path, checkpoint_freq=0))
    assert not resumed.interrupted and resumed.num_timesteps == 256 and resumed.session_steps == 256 - steps
    assert signal.getsignal(signum) is handler_before  # the handlers are only installed during learn


@pytest.mark.parametrize("at", [int(x) for x in np.random.default_rng(10).integers(1, 250, size=2)])
def test_sigterm_at_a_random_step_saves_and_resumes(tmp_path: Path, at: int) -> None:
    _kill_and_resume(tmp_path, at, signal.SIGTERM)


def test_ctrl_c_saves_and_resumes(tmp_path: Path) -> None:
    _kill_and_resume(tmp_path, 150, signal.SIGINT)


@pytest.mark.slow
@pytest.mark.parametrize("at", [int(x) for x in np.random.default_rng(11).integers(1, 250, size=8)])
def test_kill_at_more_random_steps(tmp_path: Path, at: int) -> None:
    _kill_and_resume(tmp_path, at, signal.SIGTERM)


def test_dqn_stop_keeps_buffer_and_step_count_in_step(tmp_path: Path) -> None:
    cfg = config(
        tmp_path,
        steps=300,
        algo="dqn",
        hp_overrides=("learning_starts=50", "buffer_size=1000"),
        checkpoint_freq=0,
    )
    result = train(cfg, callbacks=[Killer(123, signal.SIGTERM)])
    header = json.loads(result.path.read_text())
    # The stop is seen one step after the signal, whose transition is not yet stored: 123 steps, 123 transitions.
    assert header["counters"]["num_timesteps"] == 123 == header["replay_buffer"]["pos"]
    assert (result.path.parent / header["replay_buffer"]["file"]).is_file()
