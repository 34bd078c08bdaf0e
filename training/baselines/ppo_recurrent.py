"""``ppo_recurrent``: masked PPO with memory on the batched table (CleanRL-style, one file, torch).

Why. A policy on the current facts cannot tell two partners apart that reach the same
states; it needs what the partner has been doing. Two ways to give it that, both here:

- ``memory="gru"`` (default): a GRU cell over the (history) observation, CleanRL's
  ``ppo_atari_lstm`` recipe: the hidden state is carried across rollouts, reset per table
  when its episode starts (the autoreset), and trained by truncated back-propagation
  through time over each rollout (``n_steps`` cycles), the minibatches split by table so
  every sequence is kept whole.
- ``memory="mlp"``: a memoryless MLP on the history observation (``history`` cycles of
  interaction history, ``hg_marl/envs/history.py``), the frame-stacking variant.

Protocol. Each table plays an *episode* of ``episode_seconds`` simulated seconds
(continuing: re-drawn after each success, reward 1 per task) and draws a new partner
from the recipe (``training/baselines/recipes.py``) when the next one starts, so a policy
meets every partner from scratch, as at evaluation. The discount is per simulated second
(``gamma ** seconds``, as ``ppo_batched``); at a truncation the value of the final
observation is bootstrapped (``same_step`` autoreset gives it) and nothing crosses the
episode boundary. Actions are masked (infeasible logits at a large negative value).

Output (``OUT``): ``model.json`` + ``model.npz`` (kind ``memory``, the project's safe model
format; ``hg-marl run --robot memory --model OUT/model.json``), ``checkpoints/`` every
``checkpoint_freq`` steps, ``curve.csv`` (steps, tasks per simulated hour over the
rollout, env and learner seconds), and the compiled partners in ``partners/``.
Speed is reported as env steps/s (time inside ``env.step``) beside learner steps/s
(everything else: forward passes while acting and the updates).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from tqdm import tqdm

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, check_int
from hg_marl.envs.history import MAX_HISTORY
from hg_marl.training.baselines.recipes import check_recipe, recipe_partner
from hg_marl.training.runner import check_seconds

HOUR = 3600.0
MEMORIES = ("gru", "mlp")


@dataclass(frozen=True)
class RecurrentConfig:
    """Everything a ``ppo_recurrent`` run depends on."""

    humans: tuple[str, ...] = ("cooperative",)
    scenario: str = "paper2015"
    recipe: str = "members"
    """Population recipe (``training/baselines/recipes.py``): members, fcp, fcp_init, hsp, e3t or coverage."""
    memory: str = "gru"
    history: int = 4
    """Cycles of interaction history in the observation (0: facts only)."""
    hidden: int = 64
    steps: int = 2_000_000
    num_envs: int = 256
    n_steps: int = 32
    """Cycles per table per rollout (the BPTT length)."""
    episode_seconds: float = 1800.0
    learning_rate: float = 1e-3
    gamma: float = 0.995
    gae_lambda: float = 0.95
    clip: float = 0.2
    ent_coef: float = 0.01
    vf_coef: float = 0.5
    epochs: int = 4
    minibatches: int = 4
    max_grad_norm: float = 0.5
    seed: int = 0
    out: Path = Path("runs/ppo_recurrent")
    checkpoint_freq: int = 0
    eval_seconds: float = 1800.0
    eval_envs: int = 64
    threads: int = 1
    progress: bool = False

    def check(self) -> RecurrentConfig:
        """Refuse bad values with one line naming the option."""
        for name in ("steps", "num_envs", "n_steps", "epochs", "minibatches", "eval_envs", "hidden", "threads"):
            check_int(getattr(self, name), f"--{name.replace('_', '-')}", minimum=1)
        check_int(self.checkpoint_freq, "--checkpoint-freq", minimum=0)
        check_int(self.history, "--history", minimum=0, maximum=MAX_HISTORY)
        check_int(self.hidden, "--hidden", minimum=1, maximum=1024)
        check_recipe(self.recipe)
        if self.memory not in MEMORIES:
            raise ConfigError(f"--memory: expected one of {', '.join(MEMORIES)}, got {self.memory!r}")
        for name in ("learning_rate", "gamma", "gae_lambda", "clip", "ent_coef", "vf_coef", "max_grad_norm"):
            value = getattr(self, name)
            if not (isinstance(value, int | float) and math.isfinite(value) and value >= 0):
                raise ConfigError(f"--{name.replace('_', '-')}: expected a finite non-negative number, got {value!r}")
        for name in ("episode_seconds", "eval_seconds"):
            check_seconds(getattr(self, name), f"--{name.replace('_', '-')}")
        if not 0 < self.gamma <= 1 or not 0 <= self.gae_lambda <= 1:
            raise ConfigError("--gamma and --gae-lambda must lie in (0, 1] and [0, 1]")
        if self.num_envs % self.minibatches:
            raise ConfigError(f"--minibatches: {self.minibatches} does not divide num_envs {self.num_envs}")
        if not self.humans:
            raise ConfigError("--human: at least one partner")
        return self


@dataclass
class RecurrentResult:
    """A finished run."""

    path: Path
    num_timesteps: int
    seconds: float
    env_seconds: float
    """Wall time inside ``env.step`` (the rest of ``seconds`` is the learner's)."""
    rate_per_hour: float
    """Greedy tasks per simulated hour against the training partners (recipe noise included)."""
    checkpoints: list[Path] = field(default_factory=list)

    @property
    def env_steps_per_second(self) -> float:
        return self.num_timesteps / self.env_seconds if self.env_seconds > 0 else float("nan")

    @property
    def learner_steps_per_second(self) -> float:
        rest = self.seconds - self.env_seconds
        return self.num_timesteps / rest if rest > 0 else float("nan")

    @property
    def steps_per_second(self) -> float:
        return self.num_timesteps / self.seconds if self.seconds > 0 else float("nan")


def make_env(config: RecurrentConfig, num_envs: int, partner: Any = None) -> Any:
    """The training tables: continuing episodes of ``episode_seconds``, same-step autoreset, history appended."""
    from hg_marl.agents.views import robot_vector_env

    world = World(config.scenario)
    if partner is None:
        partner = recipe_partner(world, config.humans, config.recipe, config.out / "partners", config.progress)
    env = robot_vector_env(
        num_envs=num_envs,
        scenario=config.scenario,
        continuing=True,
        max_cycles=None,
        time_budget=config.episode_seconds,
        autoreset_mode="same_step",
        history=config.history,
        partner=partner,
    )
    attach = getattr(partner, "attach", None)
    if attach is not None:  # a partner that moves the table at reset (the coverage recipe)
        attach(getattr(env, "env", env))
        env.reset(seed=0)
    return env


def _save(net: Any, env: Any, path: Path, config: RecurrentConfig, steps: int) -> Path:
    from hg_marl.agents.memory_policy import save_memory
    from hg_marl.agents.model_file import world_fields

    fields = {
        **world_fields(env.world, Agent.ROBOT, config.scenario),
        "trained_by": f"ppo_recurrent ({config.memory})",
        "partners": list(config.humans),
        "recipe": config.recipe,
        "num_timesteps": steps,
    }
    return save_memory(net, path, fields, config.history)


def greedy_rate(net: Any, env: Any, seconds: float, seed: int) -> float:
    """Greedy (masked argmax) tasks per simulated hour over ``env``'s tables, each played for ``seconds``."""
    import torch

    obs, _ = env.reset(seed=seed)
    h, start = net.initial(env.num_envs), torch.ones(env.num_envs, dtype=torch.bool)
    tasks = clock = 0.0
    played = np.zeros(env.num_envs)
    with torch.no_grad():
        while played.min() < seconds:
            logits, _, h = net.step(torch.as_tensor(obs, dtype=torch.float32), h, start)
            act = net.masked(logits, torch.as_tensor(env.action_masks())).probs.argmax(1)
            before = env.clock.copy()
            obs, reward, term, trunc, info = env.step(act.numpy())
            played += info["clock"] - before
            tasks += float(np.sum(reward))
            clock += float(np.sum(info["clock"] - before))
            start = torch.as_tensor(term | trunc)
    return tasks / clock * HOUR if clock > 0 else 0.0


class Rollout:
    """The buffers of one rollout (``n_steps`` x ``num_envs``) and the acting state carried between rollouts."""

    def __init__(self, t_len: int, n: int, obs_size: int, n_act: int) -> None:
        import torch

        self.obs = torch.zeros((t_len, n, obs_size))
        self.start = torch.zeros((t_len, n), dtype=torch.bool)
        """Whether the table's episode begins at this step (its hidden state is reset before it)."""
        self.mask = torch.zeros((t_len, n, n_act), dtype=torch.bool)
        self.act = torch.zeros((t_len, n), dtype=torch.long)
        self.logp, self.val = torch.zeros((t_len, n)), torch.zeros((t_len, n))
        self.rew, self.disc = torch.zeros((t_len, n)), torch.zeros((t_len, n))
        self.h0: Any = None
        """Hidden state at the rollout's first step (where replays start)."""
        self.tasks = self.clock = self.env_seconds = 0.0


def collect(env: Any, net: Any, buf: Rollout, obs: Any, h: Any, start: Any, gamma: float) -> tuple[Any, Any, Any]:
    """Act for one rollout, filling ``buf``; returns the (obs, hidden, start) to carry on with."""
    import torch

    buf.h0 = h.clone()
    buf.tasks = buf.clock = 0.0
    for t in range(buf.obs.shape[0]):
        o = torch.as_tensor(obs, dtype=torch.float32)
        mask = torch.as_tensor(env.action_masks())
        with torch.no_grad():
            logits, value, h = net.step(o, h, start)
            dist = net.masked(logits, mask)
            action = dist.sample()
        buf.obs[t], buf.start[t], buf.mask[t], buf.act[t] = o, start, mask, action
        buf.logp[t], buf.val[t] = dist.log_prob(action), value
        before = env.clock.copy()
        tick = time.perf_counter()
        obs, reward, term, trunc, info = env.step(action.numpy())
        buf.env_seconds += time.perf_counter() - tick
        seconds = np.asarray(info["clock"]) - before  # the clock before any reset
        disc = torch.as_tensor(gamma**seconds, dtype=torch.float32)
        r = torch.as_tensor(reward, dtype=torch.float32)
        buf.tasks, buf.clock = buf.tasks + float(r.sum()), buf.clock + float(seconds.sum())
        if np.any(trunc):  # bootstrap from the final observation, with the hidden state that saw it
            rows = torch.as_tensor(np.flatnonzero(trunc))
            final = torch.as_tensor(np.asarray(info["final_obs"])[np.asarray(trunc)], dtype=torch.float32)
            with torch.no_grad():
                _, v_final, _ = net.step(final, h[rows])
            r[rows] += disc[rows] * v_final
        start = torch.as_tensor(np.asarray(term) | np.asarray(trunc))
        disc[start] = 0.0
        buf.rew[t], buf.disc[t] = r, disc
    return obs, h, start


def replay(net: Any, buf: Rollout, tables: Any) -> tuple[Any, Any]:
    """(logits, values) of ``tables`` over the rollout, recomputed from ``h0`` (truncated BPTT)."""
    import torch

    h, logits, values = buf.h0[tables], [], []
    for t in range(buf.obs.shape[0]):
        lg, v, h = net.step(buf.obs[t, tables], h, buf.start[t, tables])
        logits.append(lg)
        values.append(v)
    return torch.stack(logits), torch.stack(values)


def advantages(buf: Rollout, next_value: Any, lam: float) -> tuple[Any, Any]:
    """GAE(lambda) with the per-step discounts (0 across an episode's end); (advantages, returns)."""
    import torch

    t_len, n = buf.rew.shape
    adv, last = torch.zeros((t_len, n)), torch.zeros(n)
    for t in reversed(range(t_len)):
        nxt = next_value if t == t_len - 1 else buf.val[t + 1]
        last = buf.rew[t] + buf.disc[t] * nxt - buf.val[t] + buf.disc[t] * lam * last
        adv[t] = last
    return adv, adv + buf.val


def train_recurrent(
    config: RecurrentConfig,
    on_update: Callable[[int, Any], None] | None = None,
    partner: Any = None,
    env: Any = None,
) -> RecurrentResult:
    """Train; write ``OUT/model.json`` (+ checkpoints, ``curve.csv``); return the greedy rate and speeds.

    ``on_update(steps, net)`` is called after each update; ``partner`` replaces the
    recipe's (an ``ArrayPartner``), ``env`` the whole table (a toy with the same
    interface, for tests; it is also the evaluation env then).
    """
    import torch

    from hg_marl.agents.memory_policy import MemoryNet

    config = config.check()
    torch.set_num_threads(config.threads)
    torch.manual_seed(config.seed)
    given = env
    env = env if env is not None else make_env(config, config.num_envs, partner)
    n, t_len = config.num_envs, config.n_steps
    obs_size, n_act = env.single_observation_space.shape[0], env.single_action_space.n
    net = MemoryNet(obs_size, n_act, config.hidden, config.memory == "gru")
    opt = torch.optim.Adam(net.parameters(), lr=config.learning_rate, eps=1e-5)
    buf = Rollout(t_len, n, obs_size, n_act)
    obs, _ = env.reset(seed=config.seed)
    h, start = net.initial(n), torch.ones(n, dtype=torch.bool)
    steps, checkpoints, next_ckpt = 0, [], config.checkpoint_freq or None
    curve = ["steps,tasks_per_hour,env_seconds,learner_seconds"]
    bar = tqdm(total=config.steps, unit=" steps", disable=not config.progress, desc=f"ppo_recurrent {config.memory}")
    began = time.perf_counter()
    while steps < config.steps:
        obs, h, start = collect(env, net, buf, obs, h, start, config.gamma)
        with torch.no_grad():
            _, next_value, _ = net.step(torch.as_tensor(obs, dtype=torch.float32), h, start)
        adv, ret = advantages(buf, next_value, config.gae_lambda)
        per = n // config.minibatches
        for _ in range(config.epochs):
            order = torch.randperm(n)
            for k in range(config.minibatches):
                g = order[k * per : (k + 1) * per]
                logits, values = replay(net, buf, g)
                dist = net.masked(logits, buf.mask[:, g])
                logp, entropy = dist.log_prob(buf.act[:, g]), dist.entropy()
                a = adv[:, g]
                a = (a - a.mean()) / (a.std() + 1e-8)
                ratio = torch.exp(logp - buf.logp[:, g])
                pg = torch.max(-a * ratio, -a * torch.clamp(ratio, 1 - config.clip, 1 + config.clip)).mean()
                v_loss = 0.5 * ((values - ret[:, g]) ** 2).mean()
                loss = pg + config.vf_coef * v_loss - config.ent_coef * entropy.mean()
                opt.zero_grad()
                loss.backward()
                torch.nn.utils.clip_grad_norm_(net.parameters(), config.max_grad_norm)
                opt.step()
        steps += n * t_len
        bar.update(n * t_len)
        elapsed = time.perf_counter() - began
        rate = buf.tasks / max(buf.clock, 1e-9) * HOUR
        curve.append(f"{steps},{rate:.3f},{buf.env_seconds:.2f},{elapsed - buf.env_seconds:.2f}")
        if on_update is not None:  # its time (held-out evaluations) is kept out of the speeds
            tick = time.perf_counter()
            on_update(steps, net)
            began += time.perf_counter() - tick
        if next_ckpt is not None and steps >= next_ckpt:
            checkpoints.append(_save(net, env, config.out / "checkpoints" / f"ckpt_{steps}_steps.json", config, steps))
            next_ckpt = (steps // config.checkpoint_freq + 1) * config.checkpoint_freq
    seconds = time.perf_counter() - began
    bar.close()
    path = _save(net, env, config.out / "model.json", config, steps)
    from hg_marl.agents.model_file import atomic_write_bytes

    atomic_write_bytes(config.out / "curve.csv", ("\n".join(curve) + "\n").encode())
    eval_env = given if given is not None else make_env(config, config.eval_envs, partner)
    rate = greedy_rate(net, eval_env, config.eval_seconds, config.seed + 10_000)
    return RecurrentResult(path, steps, seconds, buf.env_seconds, rate, checkpoints)


def config_from_options(values: dict[str, Any], overrides: tuple[str, ...]) -> RecurrentConfig:
    """The CLI's options and ``--hp key=value`` overrides as a checked config."""
    base = RecurrentConfig()
    tunable = {k for k in base.__dataclass_fields__ if k not in values and k not in ("humans", "out")}
    values = dict(values)
    for item in overrides:
        key, sep, text = item.partition("=")
        if not sep or key not in tunable:
            raise ConfigError(f"--hp {item!r}: expected key=value with key one of {', '.join(sorted(tunable))}")
        kind = type(getattr(base, key))
        try:
            values[key] = kind(text) if kind is not bool else text.lower() in ("1", "true", "yes")
        except ValueError:
            raise ConfigError(f"--hp {item!r}: {key} must be a {kind.__name__}") from None
    return RecurrentConfig(**values).check()


def summary(result: RecurrentResult, config: RecurrentConfig) -> list[str]:
    """The lines the CLI prints after a run."""
    return [
        f"ppo_recurrent ({config.memory}, history {config.history}, recipe {config.recipe}) vs "
        f"{','.join(config.humans)} on {config.scenario}: {result.num_timesteps} steps in {result.seconds:.0f} s",
        f"  speed   {result.env_steps_per_second:,.0f} env steps/s | {result.learner_steps_per_second:,.0f} "
        f"learner steps/s | {result.steps_per_second:,.0f} overall",
        f"  greedy  {result.rate_per_hour:.1f} tasks/h against the training partners",
        f"  model   {result.path}",
        f"  use it  hg-marl run --robot memory --model {result.path} --human {config.humans[0]}",
    ]


def train_from_options(
    humans: tuple[str, ...],
    scenario: str,
    recipe: str,
    steps: int | None,
    seed: int,
    out: Path,
    checkpoint_freq: int | None,
    progress: bool,
    overrides: tuple[str, ...] = (),
    held_out: tuple[str, ...] = (),
) -> list[str]:
    """What ``hg-marl train --algo ppo_recurrent`` does (the command only parses): train, return the summary lines.

    With ``held_out`` partners and checkpoints, also the generalisation curve
    (``training/baselines/heldout_curve.py``): ``curve_heldout.csv`` and ``generalisation.png``.
    """
    values: dict[str, Any] = {
        "humans": humans,
        "scenario": scenario,
        "recipe": recipe,
        "seed": seed,
        "out": out,
        "progress": progress,
    }
    if steps is not None:
        values["steps"] = steps
    values["checkpoint_freq"] = (
        checkpoint_freq if checkpoint_freq is not None else values.get("steps", RecurrentConfig.steps) // 10
    )
    config = config_from_options(values, overrides)
    if not (held_out and config.checkpoint_freq):
        return summary(train_recurrent(config), config)
    from hg_marl.training.baselines.heldout_curve import HeldOutCurve, plot_generalisation

    curve = HeldOutCurve(config, held_out, config.checkpoint_freq)
    lines = summary(train_recurrent(config, on_update=curve), config)
    png = plot_generalisation(curve.write(), config.out / "generalisation.png", f"{config.scenario}, {config.recipe}")
    return [*lines, f"  curve   {curve.path} (train vs held-out partners), {png}"]
