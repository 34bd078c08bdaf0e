"""sb3-contrib's ``RecurrentPPO`` (an LSTM policy) on the batched table: the library baseline beside ``ppo_recurrent``.

Why. A researcher comparing against ``ppo_recurrent`` expects the off-the-shelf recurrent
learner on the same tables: ``RecurrentPPO("MlpLstmPolicy")`` trained through the SB3
``VecEnv`` adapter (:func:`hg_marl.wrappers.sb3.batched_vec_env`), on the same protocol
(continuing episodes of ``episode_seconds``, a partner drawn from ``humans`` per episode,
``history`` cycles of interaction history in the observation).

Masks. ``RecurrentPPO`` has no action masking. The policy is trained and played
unmasked, which is valid here because an infeasible action is legal input in this env:
it changes nothing (except that a pending offer by the partner lapses) and lasts the
``failed`` duration, so it costs time and therefore tasks, and the policy learns to
avoid it from the reward alone. :func:`greedy_play` counts how often it still picks one.

Model file. The model is saved in the project's safe format (kind ``sb3``, algorithm
``RecurrentPPO``; :func:`load` rebuilds it without unpickling). The ``sb3`` robot of
``run``/``evaluate``/``play`` refuses it: it does not carry the LSTM state from turn to
turn, nor rebuild the history observation. Play it with :func:`greedy_play`.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.core import Agent
from hg_marl.core.errors import ConfigError, check_int
from hg_marl.envs.history import MAX_HISTORY

HOUR = 3600.0


@dataclass(frozen=True)
class RecurrentSb3Config:
    """One ``RecurrentPPO`` run on the batched table."""

    humans: tuple[str, ...] = ("cooperative",)
    scenario: str = "paper2015"
    history: int = 4
    """Cycles of interaction history in the observation (0: facts only)."""
    steps: int = 200_000
    num_envs: int = 64
    n_steps: int = 32
    """Cycles per table per rollout (sb3-contrib's BPTT length)."""
    batch_size: int = 512
    n_epochs: int = 4
    lstm_hidden: int = 64
    learning_rate: float = 3e-4
    episode_seconds: float = 1800.0
    seed: int = 0
    threads: int = 1
    out: Path = Path("runs/recurrent_ppo_sb3")

    def check(self) -> RecurrentSb3Config:
        """Refuse bad values with one line naming the field."""
        for name in ("steps", "num_envs", "n_steps", "batch_size", "n_epochs", "threads"):
            check_int(getattr(self, name), name, minimum=1)
        check_int(self.lstm_hidden, "lstm_hidden", minimum=1, maximum=1024)
        check_int(self.history, "history", minimum=0, maximum=MAX_HISTORY)
        check_int(self.seed, "seed", minimum=0)
        for name in ("learning_rate", "episode_seconds"):
            value = getattr(self, name)
            if not (isinstance(value, int | float) and math.isfinite(value) and value > 0):
                raise ConfigError(f"{name}: expected a finite positive number, got {value!r}")
        if not self.humans:
            raise ConfigError("humans: at least one partner")
        return self


def make_vec(config: RecurrentSb3Config, num_envs: int) -> Any:
    """The robot's batched seat as an SB3 ``VecEnv`` on the run's protocol."""
    from hg_marl.wrappers.sb3 import batched_vec_env

    human: Any = config.humans[0] if len(config.humans) == 1 else list(config.humans)
    return batched_vec_env(
        num_envs,
        scenario=config.scenario,
        human=human,
        continuing=True,
        max_cycles=None,
        time_budget=config.episode_seconds,
        history=config.history,
    )


@dataclass
class Sb3RecurrentResult:
    """A finished run: the model (in memory and on disk) and its speed."""

    model: Any
    path: Path
    num_timesteps: int
    seconds: float

    @property
    def steps_per_second(self) -> float:
        return self.num_timesteps / self.seconds if self.seconds > 0 else float("nan")


def train(config: RecurrentSb3Config) -> Sb3RecurrentResult:
    """Train ``RecurrentPPO("MlpLstmPolicy")`` and save ``OUT/model.json`` (+ ``.npz``)."""
    import torch
    from sb3_contrib import RecurrentPPO

    from hg_marl.agents.model_file import save_sb3, world_fields
    from hg_marl.wrappers.sb3 import quiet_logger

    config = config.check()
    torch.set_num_threads(config.threads)
    venv = make_vec(config, config.num_envs)
    model = RecurrentPPO(
        "MlpLstmPolicy",
        venv,
        n_steps=config.n_steps,
        batch_size=config.batch_size,
        n_epochs=config.n_epochs,
        learning_rate=config.learning_rate,
        policy_kwargs={"lstm_hidden_size": config.lstm_hidden},
        seed=config.seed,
        device="cpu",
    )
    quiet_logger(model)
    began = time.perf_counter()
    model.learn(config.steps)
    seconds = time.perf_counter() - began
    fields = {
        **world_fields(venv.env.world, Agent.ROBOT, scenario=config.scenario),
        "trained_by": "sb3-contrib RecurrentPPO (MlpLstmPolicy), unmasked",
        "partners": list(config.humans),
        "history": config.history,
    }
    path = save_sb3(model, config.out / "model.json", fields, observation="facts")
    return Sb3RecurrentResult(model, path, int(model.num_timesteps), seconds)


def load(path: Path) -> Any:
    """The ``RecurrentPPO`` model of a safe model file (rebuilt from its header, nothing unpickled)."""
    from hg_marl.agents.model_file import build_sb3, load_model_file

    mf = load_model_file(path, what="--model", seat="robot")
    if mf.header.get("algo") != "RecurrentPPO":
        raise ConfigError(f"--model {path}: not a RecurrentPPO model (algo {mf.header.get('algo')!r})")
    return build_sb3(mf, optimizer=False)


@dataclass(frozen=True)
class Play:
    """What :func:`greedy_play` measured."""

    tasks_per_hour: float
    infeasible: float
    """Share of the policy's actions that were infeasible (unmasked policy, legal no-ops)."""


def greedy_play(model: Any, config: RecurrentSb3Config, num_envs: int, seconds: float, seed: int) -> Play:
    """Deterministic play, LSTM state carried per table and reset at each episode start."""
    env = make_vec(config, num_envs).env
    obs, _ = env.reset(seed=seed)
    state, starts = None, np.ones(num_envs, dtype=bool)
    played, tasks, clock, bad, acts = np.zeros(num_envs), 0.0, 0.0, 0, 0
    while played.min() < seconds:
        action, state = model.predict(obs, state=state, episode_start=starts, deterministic=True)
        action = np.asarray(action, dtype=np.int64)
        mask = env.action_masks()
        bad += int((~mask[np.arange(num_envs), action]).sum())
        acts += num_envs
        before = env.clock.copy()
        obs, reward, term, trunc, info = env.step(action)
        played += info["clock"] - before
        tasks += float(np.sum(reward))
        clock += float(np.sum(info["clock"] - before))
        starts = np.asarray(term) | np.asarray(trunc)
    return Play(tasks / clock * HOUR if clock > 0 else 0.0, bad / max(acts, 1))
