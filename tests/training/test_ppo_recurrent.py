"""ppo_recurrent: hidden state reset per table, a memory toy, model files, and a short run on the table."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
import torch
from gymnasium import spaces

from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.memory_numpy import NumpyMemoryPolicy
from hg_marl.agents.memory_policy import MemoryNet, load_memory, save_memory
from hg_marl.agents.model_file import world_fields
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.training.baselines.ppo_recurrent import (
    RecurrentConfig,
    Rollout,
    collect,
    make_env,
    replay,
    train_recurrent,
)


class Cue:
    """A two-member toy: the partner's kind shows in the first observation only, and is asked at the third.

    Each episode lasts 3 steps of 1 s. Step 0 shows ``one_hot(kind)``; step 1 shows
    nothing; step 2 shows "decide" and rewards 1 for the action equal to the kind. The
    observation at the decision is the same for both kinds, so a memoryless policy wins
    half the episodes at best; one that remembers the first step wins them all.
    """

    def __init__(self, num_envs: int) -> None:
        self.num_envs = num_envs
        self.single_observation_space = spaces.Box(0, 1, (3,), np.int8)
        self.single_action_space = spaces.Discrete(2)
        self.world = World("paper2015")  # only for the model header's names
        self.rng = np.random.default_rng(0)
        self.clock = np.zeros(num_envs)

    def _obs(self) -> np.ndarray:
        obs = np.zeros((self.num_envs, 3), dtype=np.int8)
        first = self.t == 0
        obs[first, self.kind[first]] = 1
        obs[self.t == 2, 2] = 1
        return obs

    def action_masks(self) -> np.ndarray:
        return np.ones((self.num_envs, 2), dtype=bool)

    def reset(self, *, seed: int | None = None, options: Any = None) -> tuple[np.ndarray, dict[str, Any]]:
        self.rng = np.random.default_rng(seed)
        self.kind = self.rng.integers(2, size=self.num_envs)
        self.t = np.zeros(self.num_envs, dtype=np.int64)
        self.clock[:] = 0
        return self._obs(), {}

    def step(self, actions: np.ndarray) -> tuple[Any, Any, Any, Any, dict[str, Any]]:
        reward = ((self.t == 2) & (actions == self.kind)).astype(float)
        term = self.t == 2
        self.t += 1
        self.clock += 1.0
        info = {"clock": self.clock.copy()}
        rows = np.flatnonzero(term)
        self.kind[rows] = self.rng.integers(2, size=len(rows))
        self.t[rows], self.clock[rows] = 0, 0.0
        return self._obs(), reward, term, np.zeros(self.num_envs, dtype=bool), info


def toy_config(memory: str, tmp_path: Path, updates: int) -> RecurrentConfig:
    return RecurrentConfig(
        memory=memory,
        history=0,
        hidden=16,
        num_envs=64,
        n_steps=12,
        steps=64 * 12 * updates,
        learning_rate=3e-3,
        gamma=0.99,
        ent_coef=0.01,
        epochs=4,
        minibatches=1,
        eval_seconds=30.0,
        out=tmp_path,
    )


class Paid(Cue):
    """The toy with a task solved on every table at every step of 1 s: 3600 tasks per simulated hour."""

    def step(self, actions: np.ndarray) -> tuple[Any, Any, Any, Any, dict[str, Any]]:
        obs, _, term, trunc, info = super().step(actions)
        return obs, np.ones(self.num_envs), term, trunc, info


def test_the_curve_reports_tasks_per_simulated_hour(tmp_path: Path) -> None:
    train_recurrent(toy_config("mlp", tmp_path, 2), env=Paid(64))
    rows = (tmp_path / "curve.csv").read_text().splitlines()
    assert rows[0] == "steps,tasks_per_hour,env_seconds,learner_seconds"
    assert [(int(r.split(",")[0]), float(r.split(",")[1])) for r in rows[1:]] == [(768, 3600.0), (1536, 3600.0)]


def test_gru_solves_the_cue_toy_where_a_memoryless_policy_cannot(tmp_path: Path) -> None:
    """Greedy wins: every episode with memory (rate 1200/h at 3 s each), half (600/h) without."""
    per_hour = 3600 / 3
    gru = train_recurrent(toy_config("gru", tmp_path / "gru", 20), env=Cue(64))  # 15 updates sufficed on 3 seeds
    mlp = train_recurrent(toy_config("mlp", tmp_path / "mlp", 8), env=Cue(64))
    assert gru.rate_per_hour >= 0.95 * per_hour
    assert mlp.rate_per_hour <= 0.6 * per_hour  # expected exactly 0.5: the decision's observation is shared


def test_hidden_state_is_reset_when_a_tables_episode_starts() -> None:
    """Each table's logits from the step its episode starts on equal those of a fresh hidden state.

    The toy's episodes last 3 steps, so a 12-step rollout holds several starts per table;
    the stored log-probabilities (computed while acting, with the carried state) must equal
    a replay of each episode alone from zeros, and the replay from ``h0`` must agree too.
    """
    torch.manual_seed(0)
    env, net = Cue(8), MemoryNet(3, 2, 8, recurrent=True)
    buf = Rollout(12, 8, 3, 2)
    obs, _ = env.reset(seed=1)
    h, start = net.initial(8), torch.ones(8, dtype=torch.bool)
    obs, h, start = collect(env, net, buf, obs, h, start, 0.99)
    obs, h, start = collect(env, net, buf, obs, h + 5.0, start, 0.99)  # a carried state that must not leak
    starts = 0
    for i in range(8):
        for t0 in (int(x) for x in np.flatnonzero(buf.start[:, i].numpy())):
            starts += 1
            hi = net.initial(1)
            with torch.no_grad():
                for t in range(t0, min(t0 + 3, 12)):
                    logits, _, hi = net.step(buf.obs[t, i : i + 1], hi)
                    expect = net.masked(logits, buf.mask[t, i : i + 1]).log_prob(buf.act[t, i : i + 1])
                    assert torch.allclose(expect, buf.logp[t, i : i + 1], atol=1e-6), (i, t0, t)
    assert starts >= 8 * 3
    with torch.no_grad():
        logits, _ = replay(net, buf, torch.arange(8))
    assert torch.allclose(net.masked(logits, buf.mask).log_prob(buf.act), buf.logp, atol=1e-6)


@pytest.mark.parametrize("recurrent", [True, False])
def test_model_file_round_trips_and_refuses_tampering(tmp_path: Path, recurrent: bool) -> None:
    world = World("paper2015")
    from hg_marl.envs.history import history_size

    obs_size = world.n_facts + history_size(2)
    net = MemoryNet(obs_size, world.n_actions(Agent.ROBOT), 12, recurrent)
    path = save_memory(net, tmp_path / "model.json", world_fields(world, Agent.ROBOT), history=2)
    loaded, mf = load_memory(path)
    x = torch.rand((5, obs_size))
    with torch.no_grad():
        a, va, ha = net.step(x, net.initial(5))
        b, vb, hb = loaded.step(x, loaded.initial(5))
    assert torch.equal(a, b) and torch.equal(va, vb) and torch.equal(ha, hb)
    # the robot's numpy player computes the same logits and hidden state, two steps running
    player = NumpyMemoryPolicy(mf)
    logits, h = player.step(x.numpy().astype(np.float64), player.initial(5))
    logits, h = player.step(x.numpy().astype(np.float64), h)
    with torch.no_grad():
        a, _, ha = net.step(x, ha)
    assert np.allclose(logits, a.numpy(), atol=1e-5) and np.allclose(h, ha.numpy(), atol=1e-5)
    assert mf.header["kind"] == "memory" and mf.header["history"] == 2
    text = path.read_text().replace('"hidden": 12', '"hidden": 13')
    path.write_text(text)
    with pytest.raises(ModelFileError, match="architecture"):
        load_memory(path)
    path.write_text(text.replace('"hidden": 13', '"hidden": 100000'))
    with pytest.raises(ModelFileError, match="hidden"):
        load_memory(path)


def test_short_training_run_on_the_table_plays_as_a_robot(tmp_path: Path) -> None:
    """Two rollouts on forced_coordination against two members; the file plays in the AEC env with its history."""
    config = RecurrentConfig(
        humans=("preference", "preference:handover=1.0,shared=-0.5"),
        scenario="forced_coordination",
        recipe="e3t",
        history=3,
        num_envs=32,
        n_steps=8,
        steps=512,
        eval_envs=4,
        eval_seconds=60.0,
        checkpoint_freq=256,
        out=tmp_path,
    )
    result = train_recurrent(config)
    assert result.num_timesteps == 512 and len(result.checkpoints) == 2
    assert (tmp_path / "curve.csv").read_text().count("\n") == 3
    robot = make_robot("memory", path=str(result.path))
    env = raw_env(scenario="forced_coordination", continuing=True, max_cycles=60, history=3)
    env.reset(seed=0)
    robot.reset(env.world, Agent.ROBOT, np.random.default_rng(0))
    human = make_human("preference")
    human.reset(env.world, Agent.HUMAN, np.random.default_rng(1))
    for _ in range(60):
        turn = env.turn("robot")
        action = robot.act(turn)
        # the robot rebuilt the observation the env gives with history=3
        assert np.array_equal(robot.last_obs, env.observe("robot")["observation"])
        assert turn.mask[action]
        env.step(action)
        env.step(human.act(env.turn("human")))
        if env.truncations["robot"]:
            break


def test_bad_options_are_one_line_errors() -> None:
    for bad, match in (
        ({"recipe": "pbt"}, "--recipe"),
        ({"memory": "lstm"}, "--memory"),
        ({"history": -1}, "--history"),
        ({"episode_seconds": float("nan")}, "--episode-seconds"),
        ({"num_envs": 10, "minibatches": 4}, "--minibatches"),
    ):
        with pytest.raises(ConfigError, match=match):
            RecurrentConfig(**bad).check()


def test_coverage_recipe_starts_tables_away_from_the_initial_draw(tmp_path: Path) -> None:
    """Random starting states: some tables start with an object moved (never from a clean table)."""
    config = RecurrentConfig(humans=("preference",), scenario="forced_coordination", recipe="coverage", out=tmp_path)
    env = make_env(config, 64)
    env.reset(seed=3)
    plain = make_env(RecurrentConfig(humans=("preference",), scenario="forced_coordination", out=tmp_path), 64)
    plain.reset(seed=3)
    # the same seed draws the same layouts; the coverage recipe then moves most of them on
    moved = (env.state.where != plain.state.where).any(axis=1) | (env.state.robot_at != plain.state.robot_at)
    assert moved.mean() > 0.5
    assert not env.rules.is_clean(env.state).any()


def test_train_command_runs_a_recipe_and_refuses_a_bad_one_in_one_line(tmp_path: Path) -> None:
    from tests.cli_helpers import error_lines, run_main

    common = ["train", "--algo", "ppo_recurrent", "--human", "preference", "--scenario", "forced_coordination"]
    small = ["--hp", "num_envs=16", "--hp", "n_steps=8", "--hp", "eval_envs=2", "--hp", "eval_seconds=30"]
    code, out, err = run_main([*common, "--recipe", "fcp", "--steps", "128", *small, "--out", str(tmp_path)])
    assert code == 0, err
    assert "env steps/s" in out and "learner steps/s" in out
    assert (tmp_path / "model.json").is_file()
    model = str(tmp_path / "model.json")
    play = ["--scenario", "forced_coordination", "--human", "preference", "--duration", "60"]
    code, out, err = run_main(["run", "--robot", "memory", "--model", model, *play])
    assert code == 0 and "robot actions" in out, err
    code, out, err = run_main([*common, "--recipe", "pbt", "--out", str(tmp_path / "bad")])
    assert code == 2 and len(error_lines(err)) == 1 and "--recipe" in err


def test_docs_page_python_blocks_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every python block of docs/learned-robots.md runs as written."""
    import re

    monkeypatch.chdir(tmp_path)
    page = Path(__file__).resolve().parents[2] / "docs" / "learned-robots.md"
    blocks = re.findall(r"```python\n(.*?)```", page.read_text(), re.S)
    assert len(blocks) == 4
    for i, block in enumerate(blocks):
        exec(compile(block, f"{page.name}:block{i}", "exec"), {})


class WaitFirst:
    """A policy stub that always ranks ``wait`` first, then actions by index (numpy player interface)."""

    def __init__(self, n_actions: int, wait: int) -> None:
        self.logits = -np.arange(n_actions, dtype=float)
        self.logits[wait] = 10.0

    def initial(self, n: int = 1) -> np.ndarray:
        return np.zeros((n, 0))

    def step(self, obs: np.ndarray, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return self.logits[None, :].copy(), h


class Idle:
    """A human who always waits."""

    name = "idle"

    def reset(self, world: Any, agent: Any, rng: Any) -> None:
        self.wait = world.table.wait[Agent.HUMAN]

    def act(self, turn: Any) -> int:
        return int(self.wait)


@pytest.mark.parametrize("unstall", [0, 8])
def test_memory_robot_never_idles_forever_beside_an_idle_partner(unstall: int) -> None:
    """Waits 8 turns, then the policy's best feasible non-wait action (unstall=0: the policy as trained)."""
    world = World("paper2015")
    wait = world.table.wait[Agent.ROBOT]
    robot = make_robot("memory", net=WaitFirst(world.n_actions(Agent.ROBOT), wait), unstall=unstall)
    env = raw_env(scenario="paper2015", continuing=True, max_cycles=None)
    env.reset(seed=0)
    robot.reset(env.world, Agent.ROBOT, np.random.default_rng(0))
    human = Idle()
    human.reset(env.world, Agent.HUMAN, None)
    actions = []
    for _ in range(12):
        turn = env.turn("robot")
        action = robot.act(turn)
        assert turn.mask[action]
        actions.append(action)
        env.step(action)
        env.step(human.act(env.turn("human")))
    if unstall == 0:
        assert actions == [wait] * 12
    else:
        # the policy ranks wait first, then by index: its best other move is the lowest feasible index
        state = env.world.initial_state(np.random.default_rng(0))
        assert actions[:8] == [wait] * 8
        assert actions[8] == min(i for i in env.world.feasible_indices(state, Agent.ROBOT) if i != wait)
        assert robot.last_decision is not None
