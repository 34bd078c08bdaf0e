"""Train an SB3 algorithm in either seat of the table, against one partner or a population.

The script reads top to bottom, CleanRL style: resolve hyperparameters, build the
vectorised views, build (or resume) the model, attach the callbacks, learn, save.

Output directory layout (``TrainConfig.out``)::

    model.json, model.npz      the final model (loads as ``make_robot("sb3", path=OUT)``, or in
                               the human seat as ``make_human("learned", path=OUT)``)
    checkpoints/ckpt_<N>_steps.json (+ .npz, + _replay_buffer.npz for DQN)
    eval/evaluations.npz, eval/best_model.json (+ .npz)   periodic evaluation on the training view
    tb/                        TensorBoard logs

Every model file is the safe format of :mod:`hg_marl.agents.model_file` (nothing in it
can run code when loaded).

Steps. ``steps`` is the run's *total* budget in environment steps (one step = one
cycle of the view). Resuming from a checkpoint restores its step count, optimizer state
and counters and continues up to that total, so re-running the same command with
``resume=<last checkpoint>`` finishes an interrupted run. Resumed runs are seeded
(``seed + steps done``) and reproducible, but not bit-identical to an uninterrupted run
(the environments restart on fresh tables). A resumed model keeps the hyperparameters
stored in its checkpoint.

Checkpoints. By default every tenth of the budget, rounded up to whole rollouts
(``n_steps x n_envs`` for PPO/A2C, ``train_freq x n_envs`` for DQN), written at a
rollout's start. Ctrl-C or SIGTERM stops at the next step and writes a final checkpoint
(a second signal aborts).

Imports. SB3 and torch are imported inside :func:`train` only, so the command line can
read :class:`TrainConfig`'s defaults without them.

Threads. Small MLPs gain nothing from intra-op parallelism, and several trainings may
share a 2-core machine, so ``torch_threads`` (default 1) is applied with
``torch.set_num_threads`` before the model is built.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from hg_marl.agents.model_file import (
    ModelFile,
    algo_class,
    build_sb3,
    load_model_file,
    load_replay_buffer,
    world_fields,
)
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, ModelFileError, check_int
from hg_marl.training.baselines.envs import DEFAULT_MAX_CYCLES, EnvSpec, make_vec_env
from hg_marl.training.baselines.hyperparams import (
    OWN_KEYS,
    Hyperparams,
    accepted_keys,
    check_algo,
    load_hyperparams,
    model_kwargs,
)

log = logging.getLogger(__name__)

MAX_STEPS = 10**9
"""Largest ``--steps`` accepted."""

EVAL_SEED_OFFSET = 10_000
"""The evaluation environments are seeded ``seed + EVAL_SEED_OFFSET``: never the training tables' seeds."""


@dataclass(frozen=True)
class TrainConfig:
    """One training run."""

    algo: str = "maskable_ppo"
    """``ppo``, ``a2c``, ``dqn``, ``maskable_ppo`` or ``recurrent_ppo``."""
    env: EnvSpec = field(default_factory=EnvSpec)
    """Seat, partner(s), scenario, observation, episode length, effort weight."""
    steps: int | None = None
    """Total environment steps (None: the YAML's ``n_timesteps``)."""
    seed: int = 0
    """Seeds the model (torch, numpy), the action space and the training environments."""
    out: Path = Path("runs/train")
    """Output directory (see the module docstring)."""
    hp_overrides: tuple[str, ...] = ()
    """``key=value`` hyperparameter overrides."""
    hyperparams_file: Path | None = None
    """Another YAML file instead of the packaged one."""
    eval_freq: int = 10_000
    """Steps between evaluations on the training view (0: none)."""
    eval_episodes: int = 10
    """Episodes per evaluation."""
    checkpoint_freq: int | None = None
    """Steps between checkpoints (None: a tenth of the budget, in whole rollouts; 0: none)."""
    resume: Path | None = None
    """A checkpoint (its ``.json`` header) to continue from."""
    tensorboard: bool = True
    """Write TensorBoard logs under ``out/tb``."""
    progress_bar: bool = False
    """Show a tqdm bar (command line only)."""
    torch_threads: int = 1
    """``torch.set_num_threads`` for this process."""
    verbose: int = 0
    """SB3 verbosity."""

    def __post_init__(self) -> None:
        check_algo(self.algo)
        if self.algo == "recurrent_ppo" and self.env.seat != "robot":
            raise ConfigError("--algo recurrent_ppo: robot seat only (a partner with memory is not a stationary human)")
        if self.steps is not None:
            check_int(self.steps, "--steps", minimum=1, maximum=MAX_STEPS)
        check_int(self.eval_freq, "--eval-freq", minimum=0)
        check_int(self.eval_episodes, "--eval-episodes", minimum=1)
        check_int(self.seed, "--seed", minimum=0)
        if self.checkpoint_freq is not None:
            check_int(self.checkpoint_freq, "--checkpoint-freq", minimum=0)


@dataclass
class TrainResult:
    """A finished (or resumed and finished) training run."""

    model: Any
    """The trained SB3 model (in memory)."""
    path: Path
    """The final model's zip."""
    hyperparams: Hyperparams
    """What it was trained with (for a resumed run: the YAML's, the checkpoint's own prevail)."""
    num_timesteps: int
    """Total environment steps, resumed ones included."""
    session_steps: int
    """Steps taken in this call."""
    seconds: float
    """Wall time of this call's ``learn``."""
    checkpoints: list[Path] = field(default_factory=list)
    """Checkpoints written in this call."""
    interrupted: bool = False
    """Stopped by Ctrl-C or SIGTERM (the last checkpoint resumes it)."""

    @property
    def steps_per_second(self) -> float:
        """Training throughput of this call (environment steps per wall second)."""
        return self.session_steps / self.seconds if self.seconds > 0 else float("nan")


def header_fields(config: TrainConfig, hp: Hyperparams, world: World) -> dict[str, Any]:
    """What a model file of this run records besides the weights: world, seat, training configuration."""
    seat = Agent.ROBOT if config.env.seat == "robot" else Agent.HUMAN
    train_info = {**asdict(config.env), "seed": config.seed, "hyperparams": hp.as_dict()}
    return {**world_fields(world, seat, scenario=config.env.scenario), "train": train_info}


def rollout_steps(hp: Hyperparams) -> int:
    """Environment steps per rollout: ``n_steps`` (on-policy) or ``train_freq`` (DQN), times ``n_envs``."""
    per_env = hp.kwargs.get("n_steps", hp.kwargs.get("train_freq", 2048 if hp.algo != "dqn" else 4))
    if isinstance(per_env, list | tuple):  # DQN's (frequency, unit)
        per_env = per_env[0]
    return max(1, int(per_env)) * hp.n_envs


def checkpoint_every(config: TrainConfig, hp: Hyperparams, total: int) -> int:
    """The checkpoint frequency: as given, or a tenth of the budget; rounded up to whole rollouts."""
    rollout = rollout_steps(hp)
    freq = config.checkpoint_freq if config.checkpoint_freq is not None else max(1, total // 10)
    if freq == 0:
        return 0
    return -(-freq // rollout) * rollout


def _resume_hyperparams(mf: ModelFile, config: TrainConfig) -> Hyperparams:
    """The hyperparameters stored in a checkpoint, checked against the algorithm's constructor."""
    train_info = mf.header.get("train")
    stored = train_info.get("hyperparams") if isinstance(train_info, dict) else None
    if not isinstance(stored, dict):
        raise ModelFileError(f"{mf.path}: no 'train.hyperparams' (not a checkpoint written by hg-marl train)")
    saved_algo = stored.get("algo")
    if saved_algo != config.algo:
        raise ConfigError(f"--resume {mf.path} was trained with --algo {saved_algo}, not --algo {config.algo}")
    kwargs = {k: v for k, v in stored.items() if k not in (*OWN_KEYS, "algo")}
    unknown = sorted(set(kwargs) - set(accepted_keys(config.algo)))
    if unknown:
        raise ModelFileError(f"{mf.path}: field 'train.hyperparams': unknown key(s) {', '.join(unknown)}")
    n_envs, n_timesteps = stored.get("n_envs", 1), stored.get("n_timesteps", 1)
    check_int(n_envs, f"{mf.path}: field 'train.hyperparams.n_envs'", minimum=1, maximum=256, error=ModelFileError)
    check_int(n_timesteps, f"{mf.path}: field 'train.hyperparams.n_timesteps'", minimum=1, error=ModelFileError)
    return Hyperparams(config.algo, str(stored.get("policy", "MlpPolicy")), int(n_envs), int(n_timesteps), kwargs)


def _load(config: TrainConfig, mf: ModelFile, hp: Hyperparams, env: Any) -> Any:
    """Resume: rebuild the model from the checkpoint (weights, optimizer, counters, replay buffer)."""
    tb = str(config.out / "tb") if config.tensorboard else None
    kwargs = {k: v for k, v in model_kwargs(hp).items() if k != "policy_kwargs"}
    model = build_sb3(mf, env, tensorboard_log=tb, verbose=config.verbose, **kwargs)
    if getattr(model, "replay_buffer", None) is not None and "replay_buffer" in mf.header:
        load_replay_buffer(model.replay_buffer, mf.path, mf.header["replay_buffer"])
    model.set_random_seed(config.seed + int(model.num_timesteps))
    return model


def _eval_callback(config: TrainConfig, hp: Hyperparams, save: Any) -> Any:
    """SB3's periodic evaluation on a separate, differently seeded view (masks respected)."""
    from stable_baselines3.common.callbacks import BaseCallback, EvalCallback

    cls: Any = EvalCallback
    if hp.class_name.startswith("Maskable"):
        from sb3_contrib.common.maskable.callbacks import MaskableEvalCallback

        cls = MaskableEvalCallback
    eval_env = make_vec_env(config.env, 1, config.seed + EVAL_SEED_OFFSET)
    directory = config.out / "eval"

    class SaveBest(BaseCallback):
        """Writes ``best_model.json`` (+ ``.npz``) whenever EvalCallback finds a new best (never SB3's zip)."""

        def _on_step(self) -> bool:
            save(self.model, directory / "best_model.json")
            return True

    return cls(
        eval_env,
        callback_on_new_best=SaveBest(),
        n_eval_episodes=config.eval_episodes,
        eval_freq=max(1, config.eval_freq // hp.n_envs),
        log_path=str(directory),
        best_model_save_path=None,
        deterministic=True,
        verbose=config.verbose,
    )


def train(config: TrainConfig, callbacks: Sequence[Any] = ()) -> TrainResult:
    """Train (or resume) and save; see the module docstring for the outputs.

    Args:
        config: what to train.
        callbacks: extra SB3 callbacks (e.g. :class:`~hg_marl.training.baselines.callbacks.RateCurve`).

    Raises:
        HyperparamError: unknown algorithm or hyperparameter.
        HgMarlError: a bad partner, scenario, or checkpoint (another algorithm, unsafe or corrupt file).
    """
    # The hyperparameters are checked first: their limits hold without importing torch.
    resume = load_model_file(config.resume, what="--resume") if config.resume is not None else None
    if resume is None:
        hp = load_hyperparams(config.algo, config.env.scenario, config.hp_overrides, config.hyperparams_file)

    import torch
    from stable_baselines3.common.callbacks import CallbackList

    from hg_marl.training.baselines.callbacks import Checkpoints, ProgressBar, StopOnSignal, save_checkpoint
    from hg_marl.wrappers.sb3 import quiet_logger

    torch.set_num_threads(config.torch_threads)
    if resume is not None:
        hp = _resume_hyperparams(resume, config)
    total = config.steps or hp.n_timesteps
    env = make_vec_env(config.env, hp.n_envs, config.seed)
    world: World = env.envs[0].unwrapped.world
    fields = header_fields(config, hp, world)

    def save(model: Any, path: Path) -> Path:
        return save_checkpoint(model, path, fields, config.env.observation)

    config.out.mkdir(parents=True, exist_ok=True)

    if resume is not None:
        model = _load(config, resume, hp, env)
    else:
        tb = str(config.out / "tb") if config.tensorboard else None
        model = algo_class(hp.class_name)(
            hp.policy,
            env,
            seed=config.seed,
            device="cpu",
            tensorboard_log=tb,
            verbose=config.verbose,
            **model_kwargs(hp),
        )
    if not config.tensorboard:
        quiet_logger(model, config.verbose)
    start_steps = int(model.num_timesteps)

    freq = checkpoint_every(config, hp, total)
    checkpoints = Checkpoints(freq, config.out / "checkpoints", save) if freq else None
    stop = StopOnSignal()
    chain: list[Any] = [c for c in (checkpoints, stop) if c is not None]
    if config.eval_freq:
        chain.append(_eval_callback(config, hp, save))
    if config.progress_bar:
        chain.append(ProgressBar(total))
    chain.extend(callbacks)

    t0 = time.perf_counter()
    remaining = total - start_steps
    if remaining > 0:
        with stop.catching():
            model.learn(
                remaining,
                callback=CallbackList(chain),
                reset_num_timesteps=resume is None,
                tb_log_name=f"{config.algo}_seed{config.seed}",
            )
    else:
        log.warning("checkpoint already has %d >= %d steps: nothing to train", start_steps, total)
    seconds = time.perf_counter() - t0

    saved = list(checkpoints.saved) if checkpoints else []
    if stop.stopped:
        path = save(model, (config.out / "checkpoints") / f"ckpt_{int(model.num_timesteps)}_steps.json")
        saved.append(path)
    else:
        path = save(model, config.out / "model.json")
    env.close()
    return TrainResult(
        model,
        path,
        hp,
        int(model.num_timesteps),
        int(model.num_timesteps) - start_steps,
        seconds,
        saved,
        interrupted=stop.stopped,
    )


__all__ = ["DEFAULT_MAX_CYCLES", "EnvSpec", "TrainConfig", "TrainResult", "train"]
