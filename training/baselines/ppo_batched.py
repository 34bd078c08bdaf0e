"""``ppo_batched``: a masked PPO written for the batched table (CleanRL-style, one file, torch).

Why its own loop. SB3 steps ``num_envs`` tables through per-env Python lists; this loop
reads the batched table's arrays directly (observations, ``action_masks()``, rewards,
the clock) and updates on a whole rollout of ``num_envs x n_steps`` cycles at once.

Protocol. The paper's: continuing tables (re-drawn after each success, never truncated),
reward 1 per task. The semi-MDP discount ``gamma ** seconds`` of each cycle (the clock's
advance) makes the learner minimise simulated seconds per task, which is what the
oracle's rate measures, rather than cycles. GAE(lambda), clipped surrogate, value loss,
entropy bonus, masked categorical (invalid logits at -inf); one parameter set.

The network is sb3-contrib's ``MaskableActorCriticPolicy`` (``MlpPolicy``), so the model
file is the project's ``sb3`` kind (``agents/model_file.py``): ``hg-marl run --robot sb3
--model OUT/model.json`` plays it and ``hg-marl evaluate`` scores it like any other.
Checkpoints (``OUT/checkpoints/ckpt_<steps>_steps.json``) and TensorBoard scalars
(``OUT/tb``) are written as by the SB3 algorithms; the compiled partners are cached in
``OUT/partners`` (a second run in the same folder loads them). Against a population (a comma list
of humans, or the ``train`` members of a population file) each table draws a member
at reset, the Fictitious Co-Play protocol of training against a fixed pool.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from tqdm import tqdm

from hg_marl.core import Agent
from hg_marl.core.errors import ConfigError, check_int
from hg_marl.training.runner import check_seconds

HOUR = 3600.0


@dataclass(frozen=True)
class PPOBatchedConfig:
    """Everything a ``ppo_batched`` run depends on."""

    humans: tuple[str, ...] = ("cooperative",)
    """The partner(s): one human spec, or a population's members (drawn per table at reset)."""
    scenario: str = "paper2015"
    steps: int = 600_000
    """Total environment steps (cycles over all tables)."""
    num_envs: int = 256
    n_steps: int = 32
    """Cycles per table per rollout."""
    learning_rate: float = 2.5e-3
    gamma: float = 0.995
    """Discount per simulated second."""
    gae_lambda: float = 0.95
    clip: float = 0.2
    ent_coef: float = 0.01
    vf_coef: float = 0.5
    epochs: int = 4
    minibatches: int = 4
    max_grad_norm: float = 0.5
    seed: int = 0
    out: Path = Path("runs/ppo_batched")
    checkpoint_freq: int = 0
    """Steps between checkpoints (0: none)."""
    tensorboard: bool = True
    eval_seconds: float = 3600.0
    """Simulated seconds per table of the final greedy evaluation."""
    eval_envs: int = 64
    progress: bool = False
    net_arch: tuple[int, ...] = field(default=(64, 64))

    def check(self) -> PPOBatchedConfig:
        """Refuse bad values with one line naming the option."""
        for name in ("steps", "num_envs", "n_steps", "epochs", "minibatches", "eval_envs"):
            check_int(getattr(self, name), f"--{name.replace('_', '-')}", minimum=1)
        check_int(self.checkpoint_freq, "--checkpoint-freq", minimum=0)
        for name in (
            "learning_rate",
            "gamma",
            "gae_lambda",
            "clip",
            "ent_coef",
            "vf_coef",
            "max_grad_norm",
        ):
            value = getattr(self, name)
            if not (isinstance(value, int | float) and math.isfinite(value) and value >= 0):
                raise ConfigError(f"--{name.replace('_', '-')}: expected a finite non-negative number, got {value!r}")
        check_seconds(self.eval_seconds, "--eval-seconds")  # 0 would divide 0 tasks by 0 s
        if not 0 < self.gamma <= 1 or not 0 <= self.gae_lambda <= 1:
            raise ConfigError("--gamma and --gae-lambda must lie in (0, 1] and [0, 1]")
        if (self.num_envs * self.n_steps) % self.minibatches:
            raise ConfigError(f"--minibatches: {self.minibatches} does not divide num_envs x n_steps")
        if not self.humans:
            raise ConfigError("--human: at least one partner")
        return self


@dataclass
class PPOBatchedResult:
    """A finished run."""

    path: Path
    """The final model file (``model.json``)."""
    num_timesteps: int
    seconds: float
    """Wall time of training (the evaluation excluded)."""
    rate_per_hour: float
    """Greedy tasks per simulated hour against the training partner(s)."""
    checkpoints: list[Path] = field(default_factory=list)

    @property
    def steps_per_second(self) -> float:
        return self.num_timesteps / self.seconds if self.seconds > 0 else float("nan")


def _env(config: PPOBatchedConfig, num_envs: int) -> Any:
    from hg_marl.agents.views import robot_vector_env

    humans = list(config.humans)
    return robot_vector_env(
        num_envs=num_envs,
        scenario=config.scenario,
        human=humans if len(humans) > 1 else humans[0],
        continuing=True,
        max_cycles=None,
        progress=config.progress,
        cache=config.out / "partners",
    )


def _policy(env: Any, config: PPOBatchedConfig) -> Any:
    """sb3-contrib's MaskablePPO shell around the policy we train (built on the spaces only)."""
    import torch
    from sb3_contrib import MaskablePPO

    from hg_marl.agents.model_file import _SpacesOnly

    shell = _SpacesOnly(env.single_observation_space, env.single_action_space)
    model = MaskablePPO(
        "MlpPolicy",
        shell,
        learning_rate=config.learning_rate,
        seed=config.seed,
        device="cpu",
        policy_kwargs={"net_arch": list(config.net_arch)},
    )
    model.policy.optimizer = torch.optim.Adam(model.policy.parameters(), lr=config.learning_rate, eps=1e-5)
    return model


def _save(model: Any, env: Any, path: Path, config: PPOBatchedConfig, steps: int) -> Path:
    from hg_marl.agents.model_file import save_sb3, world_fields

    model.num_timesteps = steps
    fields = {
        **world_fields(env.world, Agent.ROBOT, config.scenario),
        "trained_by": "ppo_batched",
        "partners": list(config.humans),
    }
    return save_sb3(model, path, fields, observation="facts")


def evaluate_rate(model: Any, config: PPOBatchedConfig) -> float:
    """Greedy (masked argmax) tasks per simulated hour over ``eval_envs`` continuing tables."""
    import torch

    env = _env(config, config.eval_envs)
    obs, _ = env.reset(seed=config.seed + 10_000)
    policy = model.policy
    with torch.no_grad():
        while env.clock.min() < config.eval_seconds:
            actions, _, _ = policy(torch.as_tensor(obs, dtype=torch.float32), True, env.action_masks())
            obs, *_ = env.step(actions.numpy())
    return float(env.tasks_solved.sum() / env.clock.sum() * HOUR)


def train_ppo_batched(
    config: PPOBatchedConfig, on_update: Callable[[int, Any], None] | None = None
) -> PPOBatchedResult:
    """Train; write ``OUT/model.json`` (+ checkpoints, TensorBoard); return the greedy rate.

    ``on_update(steps, model)`` is called before the first update and after each one
    (``hg-marl compare`` draws its learning curve with it; ``model`` is the MaskablePPO
    shell whose policy is being trained, what ``runner_rate`` evaluates).
    """
    import torch

    config = config.check()
    torch.manual_seed(config.seed)
    env = _env(config, config.num_envs)
    model = _policy(env, config)
    policy, opt = model.policy, model.policy.optimizer
    n, t_len = config.num_envs, config.n_steps
    n_act = env.single_action_space.n
    writer = None
    if config.tensorboard:
        from torch.utils.tensorboard import SummaryWriter

        writer = SummaryWriter(str(config.out / "tb" / "ppo_batched"))
    obs_buf = torch.zeros((t_len, n, env.single_observation_space.shape[0]))
    mask_buf = torch.zeros((t_len, n, n_act), dtype=torch.bool)
    act_buf = torch.zeros((t_len, n), dtype=torch.long)
    logp_buf, val_buf = torch.zeros((t_len, n)), torch.zeros((t_len, n))
    rew_buf, disc_buf = torch.zeros((t_len, n)), torch.zeros((t_len, n))
    obs, _ = env.reset(seed=config.seed)
    steps, checkpoints, next_ckpt = 0, [], config.checkpoint_freq or None
    bar = tqdm(total=config.steps, unit=" steps", disable=not config.progress, desc="ppo_batched")
    start = time.perf_counter()
    if on_update is not None:
        on_update(0, model)
    while steps < config.steps:
        for t in range(t_len):
            o = torch.as_tensor(obs, dtype=torch.float32)
            mask = env.action_masks()
            with torch.no_grad():
                actions, values, logp = policy(o, False, mask)
            before = env.clock.copy()
            obs, reward, _, _, _ = env.step(actions.numpy())
            obs_buf[t], mask_buf[t], act_buf[t] = o, torch.as_tensor(mask), actions
            logp_buf[t], val_buf[t] = logp, values.flatten()
            rew_buf[t] = torch.as_tensor(reward, dtype=torch.float32)
            disc_buf[t] = torch.as_tensor(config.gamma ** (env.clock - before), dtype=torch.float32)
        with torch.no_grad():
            next_value = policy.predict_values(torch.as_tensor(obs, dtype=torch.float32)).flatten()
        adv = torch.zeros((t_len, n))
        last = torch.zeros(n)
        for t in reversed(range(t_len)):
            nxt = next_value if t == t_len - 1 else val_buf[t + 1]
            delta = rew_buf[t] + disc_buf[t] * nxt - val_buf[t]
            last = delta + disc_buf[t] * config.gae_lambda * last
            adv[t] = last
        ret = adv + val_buf
        b_obs, b_mask = obs_buf.reshape(t_len * n, -1), mask_buf.reshape(t_len * n, -1)
        b_act, b_logp, b_adv, b_ret = act_buf.reshape(-1), logp_buf.reshape(-1), adv.reshape(-1), ret.reshape(-1)
        size = t_len * n
        mb = size // config.minibatches
        for _ in range(config.epochs):
            order = torch.randperm(size)
            for k in range(config.minibatches):
                idx = order[k * mb : (k + 1) * mb]
                values, logp, entropy = policy.evaluate_actions(b_obs[idx], b_act[idx], b_mask[idx].numpy())
                a = b_adv[idx]
                a = (a - a.mean()) / (a.std() + 1e-8)
                ratio = torch.exp(logp - b_logp[idx])
                pg = torch.max(-a * ratio, -a * torch.clamp(ratio, 1 - config.clip, 1 + config.clip)).mean()
                v_loss = 0.5 * ((values.flatten() - b_ret[idx]) ** 2).mean()
                loss = pg + config.vf_coef * v_loss - config.ent_coef * entropy.mean()
                opt.zero_grad()
                loss.backward()
                torch.nn.utils.clip_grad_norm_(policy.parameters(), config.max_grad_norm)
                opt.step()
        steps += size
        bar.update(size)
        if on_update is not None:
            on_update(steps, model)
        if writer is not None:
            rate = float(env.tasks_solved.sum() / max(env.clock.sum(), 1e-9) * HOUR)
            writer.add_scalar("rollout/tasks_per_hour_so_far", rate, steps)
            writer.add_scalar("train/policy_loss", float(pg.detach()), steps)
            writer.add_scalar("train/value_loss", float(v_loss.detach()), steps)
            writer.add_scalar("train/entropy", float(entropy.mean().detach()), steps)
        if next_ckpt is not None and steps >= next_ckpt:
            checkpoints.append(
                _save(model, env, config.out / "checkpoints" / f"ckpt_{steps}_steps.json", config, steps)
            )
            next_ckpt = (steps // config.checkpoint_freq + 1) * config.checkpoint_freq
    seconds = time.perf_counter() - start
    bar.close()
    if writer is not None:
        writer.close()
    path = _save(model, env, config.out / "model.json", config, steps)
    return PPOBatchedResult(path, steps, seconds, evaluate_rate(model, config), checkpoints)


def population_members(path: Path) -> tuple[str, ...]:
    """The ``train`` members' specs of a population file (``agents/humans/population.py``)."""
    try:
        from hg_marl.agents.humans.population import load_population
    except ImportError:
        raise ConfigError(
            f"--population {path}: population files need hg_marl.agents.humans.population; pass --human a,b instead"
        ) from None
    return tuple(str(m.spec) for m in load_population(path).train)


def config_from_options(
    humans: tuple[str, ...],
    scenario: str,
    steps: int | None,
    seed: int,
    out: Path,
    checkpoint_freq: int | None,
    tensorboard: bool,
    progress: bool,
    overrides: tuple[str, ...],
) -> PPOBatchedConfig:
    """The CLI's options and ``--hp key=value`` overrides as a checked config."""
    base = PPOBatchedConfig()
    values: dict[str, Any] = {
        "humans": humans,
        "scenario": scenario,
        "seed": seed,
        "out": out,
        "tensorboard": tensorboard,
        "progress": progress,
    }
    if steps is not None:
        values["steps"] = steps
    values["checkpoint_freq"] = (
        checkpoint_freq if checkpoint_freq is not None else (values.get("steps", base.steps) // 10)
    )
    tunable = {k for k in base.__dataclass_fields__ if k not in values and k != "net_arch"} | {"checkpoint_freq"}
    for item in overrides:
        key, sep, text = item.partition("=")
        if not sep or key not in tunable:
            raise ConfigError(f"--hp {item!r}: expected key=value with key one of {', '.join(sorted(tunable))}")
        kind = type(getattr(base, key))
        try:
            values[key] = kind(text)
        except ValueError:
            raise ConfigError(f"--hp {item!r}: {key} must be a {kind.__name__}") from None
    return PPOBatchedConfig(**values).check()
