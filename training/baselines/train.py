"""Train an SB3 algorithm in either seat of the table, against one partner or a population.

The script reads top to bottom, CleanRL style: resolve hyperparameters, build the
vectorised views, build (or resume) the model, attach the callbacks, learn, save.

Output directory layout (``TrainConfig.out``)::

    model.zip, model.json      the final model and its sidecar (loads as ``make_robot("sb3", path=OUT)``)
    policy.json                human seat only: the header that makes OUT a ``make_human("learned", path=OUT)``
    checkpoints/ckpt_<N>_steps.zip (+ .json, + _replay_buffer.pkl for DQN)
    eval/evaluations.npz, eval/best_model.zip (+ .json)   periodic evaluation on the training view
    tb/                        TensorBoard logs

Steps. ``steps`` is the run's *total* budget in environment steps (one step = one
cycle of the view). Resuming from a checkpoint continues its step count up to that
total, so re-running the same command with ``resume=<last checkpoint>`` finishes an
interrupted run. Resumed runs are seeded (``seed + steps done``) and reproducible, but
not bit-identical to an uninterrupted run (the environments restart on fresh tables).
A resumed model keeps the hyperparameters stored in its checkpoint.

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

from hg_marl.agents.robots.sb3 import algo_class, model_paths, read_sidecar, write_sidecar
from hg_marl.core import Agent, World
from hg_marl.training.baselines.callbacks import Checkpoints, ProgressBar, replay_buffer_path, save_checkpoint
from hg_marl.training.baselines.envs import DEFAULT_MAX_CYCLES, EnvSpec, make_vec_env
from hg_marl.training.baselines.hyperparams import Hyperparams, check_algo, load_hyperparams, model_kwargs

log = logging.getLogger(__name__)

EVAL_SEED_OFFSET = 10_000
"""The evaluation environments are seeded ``seed + EVAL_SEED_OFFSET``: never the training tables' seeds."""


@dataclass(frozen=True)
class TrainConfig:
    """One training run."""

    algo: str = "maskable_ppo"
    """``ppo``, ``a2c``, ``dqn`` or ``maskable_ppo``."""
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
    checkpoint_freq: int = 25_000
    """Steps between checkpoints (0: none)."""
    resume: Path | None = None
    """A checkpoint (zip) to continue from."""
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
        if self.steps is not None and self.steps < 1:
            raise ValueError(f"steps must be positive, got {self.steps}")
        if self.eval_freq < 0 or self.checkpoint_freq < 0:
            raise ValueError("eval_freq and checkpoint_freq must be >= 0")


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

    @property
    def steps_per_second(self) -> float:
        """Training throughput of this call (environment steps per wall second)."""
        return self.session_steps / self.seconds if self.seconds > 0 else float("nan")


def sidecar_writer(config: TrainConfig, hp: Hyperparams, world: World) -> Any:
    """A function writing this run's sidecar next to a given zip."""
    seat = Agent.ROBOT if config.env.seat == "robot" else Agent.HUMAN
    extra = {"train": {**asdict(config.env), "seed": config.seed, "hyperparams": hp.as_dict()}}

    def write(path: Path) -> Path:
        return write_sidecar(
            path,
            algo=hp.class_name,
            world=world,
            scenario=config.env.scenario,
            observation=config.env.observation,
            seat=seat,
            extra=extra,
        )

    return write


def _load(config: TrainConfig, hp: Hyperparams, env: Any) -> Any:
    """Resume: load the checkpoint (and its replay buffer), check it is the same algorithm."""
    assert config.resume is not None
    zip_path, side = model_paths(config.resume)
    if side.is_file():
        saved = read_sidecar(zip_path)["algo"]
        if saved != hp.class_name:
            raise ValueError(f"{zip_path} was trained with {saved}, not {hp.class_name} (--algo {config.algo})")
    if not zip_path.is_file():
        raise FileNotFoundError(f"no checkpoint at {zip_path}")
    tb = str(config.out / "tb") if config.tensorboard else None
    model = algo_class(hp.class_name).load(zip_path, env=env, device="cpu", tensorboard_log=tb)
    buffer = replay_buffer_path(zip_path)
    if getattr(model, "replay_buffer", None) is not None and buffer.is_file():
        model.load_replay_buffer(buffer)
    model.set_random_seed(config.seed + int(model.num_timesteps))
    return model


def _eval_callback(config: TrainConfig, hp: Hyperparams, write: Any) -> Any:
    """SB3's periodic evaluation on a separate, differently seeded view (masks respected)."""
    from stable_baselines3.common.callbacks import BaseCallback, EvalCallback

    cls: Any = EvalCallback
    if hp.class_name.startswith("Maskable"):
        from sb3_contrib.common.maskable.callbacks import MaskableEvalCallback

        cls = MaskableEvalCallback
    eval_env = make_vec_env(config.env, 1, config.seed + EVAL_SEED_OFFSET)
    directory = config.out / "eval"

    class SidecarOnBest(BaseCallback):
        """Writes the sidecar of ``best_model.zip`` whenever EvalCallback saves one."""

        def _on_step(self) -> bool:
            write(directory / "best_model.zip")
            return True

    return cls(
        eval_env,
        callback_on_new_best=SidecarOnBest(),
        n_eval_episodes=config.eval_episodes,
        eval_freq=max(1, config.eval_freq // hp.n_envs),
        log_path=str(directory),
        best_model_save_path=str(directory),
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
        ValueError: a bad partner, scenario, or a checkpoint of another algorithm.
    """
    import torch
    from stable_baselines3.common.callbacks import CallbackList

    torch.set_num_threads(config.torch_threads)
    hp = load_hyperparams(config.algo, config.env.scenario, config.hp_overrides, config.hyperparams_file)
    total = config.steps or hp.n_timesteps
    env = make_vec_env(config.env, hp.n_envs, config.seed)
    world: World = env.envs[0].unwrapped.world
    write = sidecar_writer(config, hp, world)
    config.out.mkdir(parents=True, exist_ok=True)

    if config.resume is not None:
        model = _load(config, hp, env)
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
    start_steps = int(model.num_timesteps)

    checkpoints = (
        Checkpoints(config.checkpoint_freq, config.out / "checkpoints", write) if config.checkpoint_freq else None
    )
    chain: list[Any] = [c for c in (checkpoints,) if c is not None]
    if config.eval_freq:
        chain.append(_eval_callback(config, hp, write))
    if config.progress_bar:
        chain.append(ProgressBar(total))
    chain.extend(callbacks)

    t0 = time.perf_counter()
    remaining = total - start_steps
    if remaining > 0:
        model.learn(
            remaining,
            callback=CallbackList(chain),
            reset_num_timesteps=config.resume is None,
            tb_log_name=f"{config.algo}_seed{config.seed}",
        )
    else:
        log.warning("checkpoint already has %d >= %d steps: nothing to train", start_steps, total)
    seconds = time.perf_counter() - t0

    path = save_checkpoint(model, config.out / "model.zip", write)
    if config.env.seat == "human":
        from hg_marl.agents.humans.learned import save_sb3_policy

        save_sb3_policy(config.out, model, world, observation=config.env.observation, seat=Agent.HUMAN)
    env.close()
    return TrainResult(
        model,
        path,
        hp,
        int(model.num_timesteps),
        int(model.num_timesteps) - start_steps,
        seconds,
        list(checkpoints.saved) if checkpoints else [],
    )


__all__ = ["DEFAULT_MAX_CYCLES", "EnvSpec", "TrainConfig", "TrainResult", "train"]
