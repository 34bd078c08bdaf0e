"""The single-agent views: Gymnasium and SB3 conformance for every human, rewards, infos."""

from __future__ import annotations

import warnings
from pathlib import Path

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import hg_marl  # noqa: F401  (registers the ids)
from hg_marl.agents.humans import TraceRecorder, available_humans, make_human, save_learned_policy
from hg_marl.agents.views import HumanView, RobotView
from hg_marl.core import Agent, World
from hg_marl.policy import Actor


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """A learned policy and a recorded trace for the humans that need a file."""
    root = tmp_path_factory.mktemp("humans")
    world = World("paper2015")
    w = np.random.default_rng(0).normal(size=(world.n_actions(Agent.HUMAN), world.n_facts))
    save_learned_policy(root / "policy", world, weights=w)
    recorder = TraceRecorder(make_human("cooperative"), root / "trace.jsonl")
    view = RobotView("paper2015", human=recorder, max_cycles=30)
    for episode in range(40):
        view.reset(seed=episode)
        done = False
        while not done:
            _, _, term, trunc, _ = view.step(view.action_space.n - 1)
            done = term or trunc
    recorder.close()
    return {"learned": root / "policy", "replay": root / "trace.jsonl"}


def human_for(name: str, files: dict[str, Path]) -> Actor:
    if name in files:
        kwargs = (
            {"path": str(files[name])}
            if name == "learned"
            else {"path": str(files[name]), "on_mismatch": "ignore", "loop": True}
        )
        return make_human(name, **kwargs)
    return make_human(name)


@pytest.mark.parametrize("name", sorted(available_humans()))
def test_gymnasium_and_sb3_check_env_for_every_human(name: str, files: dict[str, Path]) -> None:
    from stable_baselines3.common.env_checker import check_env as sb3_check_env

    view = RobotView("paper2015", human=human_for(name, files), max_cycles=30)
    check_env(view, skip_render_check=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # SB3 warns on anything it would handle badly
        sb3_check_env(view, warn=True)


@pytest.mark.parametrize("observation", ["facts", "flat", "dict"])
def test_observation_modes(observation: str) -> None:
    from stable_baselines3.common.env_checker import check_env as sb3_check_env

    view = RobotView("roboergosum", human="lazy", observation=observation, max_cycles=20)
    check_env(view, skip_render_check=True)
    sb3_check_env(view)
    obs, _ = view.reset(seed=0)
    assert view.observation_space.contains(obs)


def test_gymnasium_make_with_kwargs_and_masks() -> None:
    env = gymnasium.make(
        "hg_marl/RobotTableCleaning-v0",
        scenario="paper2015",
        human="no_handover",
        continuing=True,
        max_cycles=50,
        time_budget=1000.0,
    )
    env.reset(seed=1)
    view = env.unwrapped
    assert isinstance(view, RobotView) and view.env.continuing
    mask = view.action_masks()
    assert mask.dtype == bool and mask.shape == (18,) and mask[-1]
    _obs, _reward, _term, _trunc, info = env.step(int(np.flatnonzero(mask)[0]))
    assert {"human_action", "human_action_name", "events", "clock", "tasks_solved", "failed"} <= set(info)
    assert info["human_action_name"] == view.world.action_names[Agent.HUMAN][info["human_action"]]


def test_robot_reward_and_episode_end() -> None:
    from hg_marl.agents.robots import make_robot

    view = RobotView("paper2015", human="cooperative")
    view.reset(seed=0)
    robot = make_robot("planner")
    robot.reset(view.world, Agent.ROBOT, np.random.default_rng(0))
    rewards, done = [], False
    while not done:
        _, r, done, trunc, info = view.step(robot.act(view.env.turn("robot")))
        rewards.append(r)
        assert not trunc
    assert rewards[-1] == 1.0 and sum(rewards) == 1.0
    assert any("completed" in e for e in info["events"].split("; "))


def test_population_is_resampled_each_episode() -> None:
    view = RobotView("paper2015", human=["lazy", "adversarial", "random"], max_cycles=5)
    seen = {view.reset(seed=s)[1]["human"] for s in range(30)}
    assert seen == {"lazy", "adversarial", "random"}


def test_human_view_check_env_and_effort_reward() -> None:
    from stable_baselines3.common.env_checker import check_env as sb3_check_env

    view = HumanView("paper2015", robot="random", effort_weight=0.1, max_cycles=30)
    check_env(view, skip_render_check=True)
    sb3_check_env(view)
    env = gymnasium.make("hg_marl/HumanTableCleaning-v0", robot="planner", effort_weight=0.1)
    env.reset(seed=0)
    world = env.unwrapped.world
    pick = world.action_names[Agent.HUMAN].index("pick(tape1)")
    mask = env.unwrapped.action_masks()
    action = pick if mask[pick] else int(np.flatnonzero(mask)[0])
    _, reward, _, _, info = env.step(action)
    assert reward == pytest.approx(info["task_reward"] - 0.1 * info["work"])
    assert "robot_action" in info and "robot_action_name" in info


def test_human_view_episode_ends_when_the_robot_completes() -> None:
    view = HumanView("paper2015", robot="planner")
    view.reset(seed=3)
    coop = make_human("cooperative")
    coop.reset(view.world, Agent.HUMAN, np.random.default_rng(0))
    total, done, steps = 0.0, False, 0
    while not done:
        _, r, done, trunc, _ = view.step(coop.act(view.env.turn("human")))
        total += r
        steps += 1
        assert not trunc
    assert total == 1.0 and steps < 30


def test_bad_arguments_are_clear() -> None:
    with pytest.raises(ValueError, match="observation must be one of"):
        RobotView(observation="pixels")
    with pytest.raises(ValueError, match="unknown human"):
        RobotView(human="grumpy")
    with pytest.raises(ValueError, match="effort_weight"):
        HumanView(effort_weight=-1.0)


@pytest.mark.parametrize("weight", [float("nan"), float("inf"), -0.0 - 1e-9])
def test_an_effort_weight_that_is_not_a_finite_number_at_least_zero_is_refused(weight: float) -> None:
    """A NaN weight would make every reward of the human's seat NaN (NaN < 0 is false)."""
    from hg_marl.core.errors import ConfigError
    from hg_marl.envs.batched import BatchedTable

    with pytest.raises(ConfigError, match="effort_weight"):
        HumanView(effort_weight=weight)
    with pytest.raises(ConfigError, match="effort_weight"):
        BatchedTable("planner", 1, "paper2015", effort_weight=weight)


@pytest.mark.slow
def test_maskable_ppo_learns_briefly() -> None:
    from sb3_contrib import MaskablePPO

    from hg_marl.wrappers.sb3 import quiet_logger

    view = RobotView("paper2015", human="cooperative", max_cycles=50)
    model = quiet_logger(MaskablePPO("MlpPolicy", view, n_steps=64, batch_size=32, n_epochs=1, seed=0, device="cpu"))
    model.learn(128)
    obs, _ = view.reset(seed=0)
    action, _ = model.predict(obs, action_masks=view.action_masks())
    assert view.action_masks()[int(action)]
