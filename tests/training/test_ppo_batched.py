"""``ppo_batched``: the batched masked PPO writes the project's model files and learns the task."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("sb3_contrib")

from hg_marl.agents.model_file import load_model_file
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, World
from hg_marl.training.baselines.ppo_batched import PPOBatchedConfig, train_ppo_batched


def test_smoke_run_writes_model_checkpoint_and_tensorboard_and_the_sb3_robot_plays_it(tmp_path: Path) -> None:
    config = PPOBatchedConfig(
        steps=2048, num_envs=32, n_steps=16, checkpoint_freq=1024, out=tmp_path, eval_seconds=200.0, eval_envs=8
    )
    result = train_ppo_batched(config)
    assert result.num_timesteps == 2048
    assert [p.name for p in result.checkpoints] == ["ckpt_1024_steps.json", "ckpt_2048_steps.json"]
    assert any((tmp_path / "tb").rglob("events.out.tfevents.*"))
    mf = load_model_file(result.path)
    assert mf.header["kind"] == "sb3" and mf.header["trained_by"] == "ppo_batched"
    robot = make_robot("sb3", path=str(result.path))
    world = World("paper2015")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    from hg_marl.policy import Turn

    state = world.initial_state(np.random.default_rng(0))
    turn = Turn(
        world, state, Agent.ROBOT, {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
    )
    assert 0 <= robot.act(turn) < world.n_actions(Agent.ROBOT)


@pytest.mark.slow
def test_reaches_095_of_the_oracle_against_the_cooperative_human(tmp_path: Path) -> None:
    result = train_ppo_batched(PPOBatchedConfig(steps=600_000, out=tmp_path, tensorboard=False, eval_seconds=1800.0))
    assert result.rate_per_hour >= 0.95 * oracle_rate("paper2015", "cooperative").rate_per_hour


def test_compare_names_ppo_batched_like_any_algorithm(tmp_path: Path) -> None:
    """A compare cell of ppo_batched: a learning curve from step 0 to the budget, on the runner protocol."""
    from hg_marl.training.baselines.compare import run_cell
    from hg_marl.training.baselines.comparison import CompareConfig

    config = CompareConfig(
        algos=("ppo_batched",),
        humans=("cooperative",),
        steps=8192,
        eval_every=8192,
        eval_seeds=(0,),
        duration=100.0,
        out=tmp_path,
    )
    record = run_cell(config, "ppo_batched", "cooperative", 0, tmp_path / "cell")
    assert [s for s, _ in record["curve"]] == [0, 8192]
    assert Path(record["model"]).exists() and record["algo"] == "ppo_batched"


@pytest.mark.parametrize("deterministic", [False, True])
def test_a_compare_cells_evaluations_play_as_the_config_says(
    deterministic: bool, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the runner evaluations of a cell sample the policy or play it greedily as the comparison's
    # ``deterministic`` says (the cell's training is replaced: it asks for one evaluation)
    from hg_marl.training.baselines import compare
    from hg_marl.training.baselines.comparison import CompareConfig

    asked: list[bool] = []
    monkeypatch.setattr(compare, "runner_rate", lambda *args, deterministic=True: asked.append(deterministic) or 1.0)
    monkeypatch.setattr(compare, "_run_batched_cell", lambda config, human, seed, directory, evaluate: evaluate(None))
    config = CompareConfig(algos=("ppo_batched",), humans=("cooperative",), deterministic=deterministic, out=tmp_path)
    compare.run_cell(config, "ppo_batched", "cooperative", 0, tmp_path / "cell")
    assert asked == [deterministic]
