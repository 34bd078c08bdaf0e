"""The batched PPO's settings, options, population members and a tiny run's schedule, pinned for the gate.

Expected values are the module's documented rules, worked by hand: each count option is
at least 1 (the checkpoint period at least 0), each rate a finite non-negative number,
``gamma`` in (0, 1] and ``gae_lambda`` in [0, 1], the minibatches dividing a rollout of
``num_envs x n_steps``; the checkpoint period defaults to a tenth of the steps; a run of
32 steps in rollouts of 4 tables x 4 cycles updates at 16 and 32, checkpointing at each
multiple of 16 it reaches. The tiny run takes a second or two; nothing is timed.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.model_file import load_model_file
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.training.baselines.ppo_batched import (
    HOUR,
    PPOBatchedConfig,
    PPOBatchedResult,
    config_from_options,
    population_members,
    train_ppo_batched,
)


def test_the_defaults_are_the_documented_ones() -> None:
    config = PPOBatchedConfig()
    assert (config.humans, config.scenario, config.steps, config.num_envs, config.n_steps) == (
        ("cooperative",),
        "paper2015",
        600_000,
        256,
        32,
    )
    assert (config.learning_rate, config.gamma, config.gae_lambda, config.clip) == (2.5e-3, 0.995, 0.95, 0.2)
    assert (config.ent_coef, config.vf_coef, config.epochs, config.minibatches, config.max_grad_norm) == (
        0.01,
        0.5,
        4,
        4,
        0.5,
    )
    assert (config.seed, config.out, config.checkpoint_freq, config.tensorboard) == (
        0,
        Path("runs/ppo_batched"),
        0,
        True,
    )
    assert (config.eval_seconds, config.eval_envs, config.progress, config.net_arch) == (3600.0, 64, False, (64, 64))
    assert HOUR == 3600.0
    assert config.check() is config


def test_a_configuration_is_frozen() -> None:
    with pytest.raises(dataclasses.FrozenInstanceError):
        PPOBatchedConfig().steps = 1


def test_the_smallest_settings_are_accepted() -> None:
    """Counts of 1, a period of 0, rates of 0, lambda 0 and 1, gamma 1, an evaluation of 0.01 s: at their bounds."""
    config = PPOBatchedConfig(
        steps=1,
        num_envs=1,
        n_steps=1,
        epochs=1,
        minibatches=1,
        eval_envs=1,
        checkpoint_freq=0,
        learning_rate=0,
        clip=0.0,
        ent_coef=0.0,
        vf_coef=0.0,
        max_grad_norm=0.0,
        eval_seconds=0.01,  # above 0: an evaluation of 0 s would report 0 tasks / 0 s
        gae_lambda=0.0,
        gamma=1,
    )
    assert config.check() is config
    assert PPOBatchedConfig(gae_lambda=1.0).check().gae_lambda == 1.0


@pytest.mark.parametrize(
    ("changes", "match"),
    [
        ({"steps": 0}, r"^--steps: expected an integer >= 1"),
        ({"num_envs": 0}, r"^--num-envs: expected an integer >= 1"),
        ({"n_steps": 0}, r"^--n-steps: expected an integer >= 1"),
        ({"epochs": 0}, r"^--epochs: expected an integer >= 1"),
        ({"minibatches": 0}, r"^--minibatches: expected an integer >= 1"),
        ({"eval_envs": 0}, r"^--eval-envs: expected an integer >= 1"),
        ({"checkpoint_freq": -1}, r"^--checkpoint-freq: expected an integer >= 0"),
        ({"learning_rate": -0.1}, r"^--learning-rate: expected a finite non-negative number, got -0.1$"),
        ({"vf_coef": math.inf}, r"^--vf-coef: expected a finite non-negative number, got inf$"),
        ({"max_grad_norm": math.nan}, r"^--max-grad-norm: expected a finite non-negative number"),
        ({"eval_seconds": "10"}, r"^--eval-seconds: expected a positive number of seconds, got '10'$"),
        ({"clip": -1.0}, r"^--clip: "),
        ({"ent_coef": -1.0}, r"^--ent-coef: "),
        ({"gae_lambda": 1.5}, r"^--gamma and --gae-lambda must lie in \(0, 1\] and \[0, 1\]$"),
        ({"gamma": 0.0}, r"^--gamma and --gae-lambda"),
        ({"num_envs": 3, "n_steps": 5, "minibatches": 2}, r"^--minibatches: 2 does not divide num_envs x n_steps$"),
        ({"humans": ()}, r"^--human: at least one partner$"),
    ],
)
def test_each_bad_setting_is_one_line_naming_its_option(changes: dict[str, Any], match: str) -> None:
    with pytest.raises(ConfigError, match=match):
        PPOBatchedConfig(**changes).check()


def test_the_minibatches_may_divide_the_rollout_exactly() -> None:
    """3 tables x 4 cycles is 12: 4 and 6 minibatches divide it, 5 does not."""
    assert PPOBatchedConfig(num_envs=3, n_steps=4, minibatches=6).check().minibatches == 6
    with pytest.raises(ConfigError, match="does not divide"):
        PPOBatchedConfig(num_envs=3, n_steps=4, minibatches=5).check()


def test_throughput_is_steps_over_seconds() -> None:
    assert PPOBatchedResult(Path("m.json"), 300, 4.0, 1.0).steps_per_second == 75.0
    assert math.isnan(PPOBatchedResult(Path("m.json"), 300, 0.0, 1.0).steps_per_second)
    assert PPOBatchedResult(Path("m.json"), 300, 4.0, 1.0).checkpoints == []


def _options(tmp_path: Path, steps: int | None = 1000, checkpoint: int | None = None, hp: tuple[str, ...] = ()) -> Any:
    return config_from_options(("lazy",), "paper2015", steps, 3, tmp_path, checkpoint, False, True, hp)


def test_options_become_the_config_with_typed_overrides(tmp_path: Path) -> None:
    config = _options(tmp_path, hp=("gamma=0.9", "num_envs=8", "checkpoint_freq=7", "eval_seconds=60"))
    assert (config.humans, config.scenario, config.steps, config.seed, config.out) == (
        ("lazy",),
        "paper2015",
        1000,
        3,
        tmp_path,
    )
    assert (config.tensorboard, config.progress) == (False, True)
    assert (config.gamma, config.num_envs, config.checkpoint_freq, config.eval_seconds) == (0.9, 8, 7, 60.0)
    assert type(config.num_envs) is int and type(config.eval_seconds) is float
    assert _options(tmp_path, checkpoint=40).checkpoint_freq == 40
    assert _options(tmp_path, steps=None).checkpoint_freq == 60_000 and _options(tmp_path, steps=None).steps == 600_000


@pytest.mark.parametrize(
    ("item", "match"),
    [
        ("gamma", r"--hp 'gamma': expected key=value with key one of "),
        ("colour=red", r"--hp 'colour=red': expected key=value"),
        ("seed=4", r"--hp 'seed=4': expected key=value"),  # an option of its own, not an --hp
        ("net_arch=[8]", r"--hp 'net_arch=\[8\]': expected key=value"),
        ("num_envs=many", r"^--hp 'num_envs=many': num_envs must be a int$"),
        ("gamma=0", r"--gamma and --gae-lambda"),
    ],
)
def test_bad_overrides_are_refused(tmp_path: Path, item: str, match: str) -> None:
    with pytest.raises(ConfigError, match=match):
        _options(tmp_path, hp=(item,))


def test_the_tunable_keys_are_listed_sorted_without_the_options(tmp_path: Path) -> None:
    with pytest.raises(ConfigError) as info:
        _options(tmp_path, hp=("x=1",))
    listed = str(info.value).split("key one of ")[1].split(", ")
    assert listed == sorted(listed)
    assert "checkpoint_freq" in listed and "gamma" in listed
    for option in ("humans", "scenario", "seed", "out", "tensorboard", "progress", "steps", "net_arch"):
        assert option not in listed


def test_population_members_are_the_train_split_specs() -> None:
    """``populations/paper2015.toml``: the members marked ``split = "train"``, in file order, as specs."""
    import tomllib

    path = Path(__file__).parents[2] / "populations" / "paper2015.toml"
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    expected = tuple(m["spec"] for m in data["members"] if m["split"] == "train")
    assert expected and population_members(path) == expected


def test_a_tiny_run_updates_checkpoints_and_saves_on_its_schedule(tmp_path: Path) -> None:
    """4 tables x 4 cycles = 16 steps an update: updates at 16 and 32; checkpoints every 16; the final model file."""
    seen: list[int] = []
    config = PPOBatchedConfig(
        steps=32,
        num_envs=4,
        n_steps=4,
        epochs=1,
        minibatches=2,
        checkpoint_freq=16,
        out=tmp_path,
        tensorboard=False,
        eval_seconds=30.0,
        eval_envs=2,
        net_arch=(8,),
        humans=("lazy", "cooperative"),
    )
    result = train_ppo_batched(config, lambda steps, model: seen.append(steps))
    assert seen == [0, 16, 32]
    assert result.num_timesteps == 32 and result.path == tmp_path / "model.json"
    assert [p.relative_to(tmp_path) for p in result.checkpoints] == [
        Path("checkpoints/ckpt_16_steps.json"),
        Path("checkpoints/ckpt_32_steps.json"),
    ]
    header = load_model_file(result.path).header
    world = World("paper2015")
    assert header["trained_by"] == "ppo_batched" and header["partners"] == ["lazy", "cooperative"]
    assert header["seat"] == "robot" and header["action_names"] == list(world.action_names[Agent.ROBOT])
    assert header["observation"] == "facts" and header["counters"]["num_timesteps"] == 32
    assert load_model_file(result.checkpoints[0]).header["counters"]["num_timesteps"] == 16
    assert result.rate_per_hour >= 0.0 and math.isfinite(result.rate_per_hour)


def test_a_checkpoint_period_not_dividing_the_updates_writes_at_the_first_update_past_each_multiple(
    tmp_path: Path,
) -> None:
    """Updates every 16 steps, a period of 20: the updates at 32 (past 20) and 48 (past 40)."""
    config = PPOBatchedConfig(
        steps=48,
        num_envs=4,
        n_steps=4,
        epochs=1,
        minibatches=1,
        checkpoint_freq=20,
        out=tmp_path,
        tensorboard=False,
        eval_seconds=10.0,
        eval_envs=1,
        net_arch=(4,),
    )
    result = train_ppo_batched(config)
    assert [p.name for p in result.checkpoints] == ["ckpt_32_steps.json", "ckpt_48_steps.json"]


def test_the_tables_are_continuing_and_a_population_is_passed_whole(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """One human is passed as its spec, several as the list (drawn per table); never truncated; cached in OUT."""
    from hg_marl.agents import views
    from hg_marl.training.baselines import ppo_batched

    asked: list[dict[str, Any]] = []

    def fake_vector_env(**kwargs: Any) -> str:
        asked.append(kwargs)
        return "env"

    monkeypatch.setattr(views, "robot_vector_env", fake_vector_env)
    config = PPOBatchedConfig(humans=("lazy", "cooperative"), scenario="roboergosum", out=tmp_path, progress=True)
    assert ppo_batched._env(config, 3) == "env"
    assert asked[-1] == {
        "num_envs": 3,
        "scenario": "roboergosum",
        "human": ["lazy", "cooperative"],
        "continuing": True,
        "max_cycles": None,
        "progress": True,
        "cache": tmp_path / "partners",
    }
    ppo_batched._env(PPOBatchedConfig(humans=("lazy",), out=tmp_path), 1)
    assert asked[-1]["human"] == "lazy"


class _FakeTables:
    """Two tables whose clocks advance 10 s and 20 s a cycle; the first solves a task every cycle."""

    def __init__(self) -> None:
        self.clock = np.zeros(2)
        self.tasks_solved = np.zeros(2)
        self.seeds: list[Any] = []

    def reset(self, seed: Any = None) -> tuple[Any, dict[str, Any]]:
        self.seeds.append(seed)
        return np.zeros((2, 3)), {}

    def action_masks(self) -> Any:
        return np.ones((2, 4), bool)

    def step(self, actions: Any) -> tuple[Any, ...]:
        self.clock += [10.0, 20.0]
        self.tasks_solved += [1.0, 0.0]
        return np.zeros((2, 3)), np.zeros(2), None, None, {}


def test_the_greedy_evaluation_runs_every_table_past_the_duration_on_its_own_seeds(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Seed 3: tables reset with 10003. Until the slower clock passes 30 s: 3 cycles, clocks 30 and 60 s,
    3 tasks in 90 table-seconds: 3 / 90 x 3600 = 120 tasks per hour; every action the policy's greedy one."""
    from hg_marl.training.baselines import ppo_batched

    tables = _FakeTables()
    greedy: list[bool] = []

    def policy(obs: Any, deterministic: bool, masks: Any) -> Any:
        import torch

        greedy.append(deterministic)
        return torch.zeros(2, dtype=torch.long), None, None

    monkeypatch.setattr(ppo_batched, "_env", lambda config, n: tables)
    model = type("Model", (), {"policy": staticmethod(policy)})()
    rate = ppo_batched.evaluate_rate(model, PPOBatchedConfig(seed=3, eval_seconds=30.0))
    assert tables.seeds == [10_003]
    assert greedy == [True, True, True]
    assert rate == pytest.approx(120.0)


def _reference_update(config: PPOBatchedConfig) -> dict[str, Any]:
    """One rollout and update of the documented algorithm, written out plainly, on the module's tables and network.

    The same seeds, so the same tables and the same sampled actions; GAE(lambda) per table
    with the semi-MDP discount ``gamma ** seconds`` of each cycle, bootstrapped from the
    value after the last cycle; per minibatch, normalised advantages, the clipped
    surrogate, half the squared value error and the entropy bonus, the gradient clipped.
    """
    import torch

    from hg_marl.training.baselines import ppo_batched

    torch.manual_seed(config.seed)
    env = ppo_batched._env(config, config.num_envs)
    model = ppo_batched._policy(env, config)
    policy, opt = model.policy, model.policy.optimizer
    obs, _ = env.reset(seed=config.seed)
    rows: list[dict[str, Any]] = []
    for _ in range(config.n_steps):
        o = torch.as_tensor(obs, dtype=torch.float32)
        mask = env.action_masks()
        with torch.no_grad():
            actions, values, logp = policy(o, False, mask)
        before = env.clock.copy()
        obs, reward, _, _, _ = env.step(actions.numpy())
        seconds = env.clock - before
        rows.append(
            {
                "obs": o,
                "mask": torch.as_tensor(mask),
                "act": actions,
                "logp": logp,
                "value": values.flatten(),
                "reward": torch.as_tensor(reward, dtype=torch.float32),
                "disc": torch.as_tensor(config.gamma**seconds, dtype=torch.float32),
            }
        )
    with torch.no_grad():
        bootstrap = policy.predict_values(torch.as_tensor(obs, dtype=torch.float32)).flatten()
    n, t_len = config.num_envs, config.n_steps
    adv = torch.zeros((t_len, n))
    for e in range(n):
        running = 0.0
        for t in reversed(range(t_len)):
            following = bootstrap[e] if t == t_len - 1 else rows[t + 1]["value"][e]
            delta = rows[t]["reward"][e] + rows[t]["disc"][e] * following - rows[t]["value"][e]
            running = delta + rows[t]["disc"][e] * config.gae_lambda * running
            adv[t, e] = running
    ret = adv + torch.stack([r["value"] for r in rows])
    flat = {k: torch.stack([r[k] for r in rows]).reshape(t_len * n, -1) for k in ("obs", "mask")}
    b_act = torch.stack([r["act"] for r in rows]).reshape(-1)
    b_logp = torch.stack([r["logp"] for r in rows]).reshape(-1)
    b_adv, b_ret = adv.reshape(-1), ret.reshape(-1)
    size = t_len * n
    per = size // config.minibatches
    for _ in range(config.epochs):
        order = torch.randperm(size)
        for k in range(config.minibatches):
            idx = order[k * per : k * per + per]
            values, logp, entropy = policy.evaluate_actions(flat["obs"][idx], b_act[idx], flat["mask"][idx].numpy())
            a = (b_adv[idx] - b_adv[idx].mean()) / (b_adv[idx].std() + 1e-8)
            ratio = torch.exp(logp - b_logp[idx])
            clipped = torch.clamp(ratio, 1 - config.clip, 1 + config.clip)
            surrogate = -torch.min(a * ratio, a * clipped).mean()
            value_loss = 0.5 * ((values.flatten() - b_ret[idx]) ** 2).mean()
            loss = surrogate + config.vf_coef * value_loss - config.ent_coef * entropy.mean()
            opt.zero_grad()
            loss.backward()
            torch.nn.utils.clip_grad_norm_(policy.parameters(), config.max_grad_norm)
            opt.step()
    return {k: v.detach().clone() for k, v in policy.state_dict().items()}


def test_the_first_update_is_the_documented_ppo_update(tmp_path: Path) -> None:
    """The network after the first update equals the plain reference's: rollout, discounts, GAE, losses, minibatches."""
    import copy

    import torch

    config = PPOBatchedConfig(
        steps=12,
        num_envs=3,
        n_steps=4,
        epochs=2,
        minibatches=2,
        out=tmp_path / "run",
        tensorboard=False,
        eval_seconds=1.0,
        eval_envs=1,
        net_arch=(8,),
        ent_coef=0.05,
        vf_coef=0.7,
        clip=0.001,  # so that after the first minibatch's step ratios leave the clip range
        learning_rate=0.05,
        gamma=0.9,
        gae_lambda=0.8,
        seed=2,
    )
    after: dict[str, Any] = {}

    def keep(steps: int, model: Any) -> None:
        if steps == 12:
            after.update(copy.deepcopy(model.policy.state_dict()))

    train_ppo_batched(config, keep)
    expected = _reference_update(dataclasses.replace(config, out=tmp_path / "ref"))
    assert set(after) == set(expected)
    for key, tensor in expected.items():
        assert torch.allclose(after[key], tensor, rtol=1e-4, atol=1e-6), key
