"""A learned SB3 human in the batched env: one forward pass per step, each table's answer the live human's."""

from __future__ import annotations

from pathlib import Path

import gymnasium
import numpy as np
import pytest

from hg_marl.agents.batched_learned import BatchedLearned
from hg_marl.agents.humans.learned import save_sb3_policy
from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.views import CompiledPopulation, HumanView, RobotView, robot_vector_env
from hg_marl.core import Agent, World
from hg_marl.core.errors import ModelFileError
from hg_marl.envs.batched import BatchedRules
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.policy import Turn

pytest.importorskip("sb3_contrib")
torch = pytest.importorskip("torch")

SCENARIO = "paper2015"
KINDS = ["maskable-facts", "ppo-flat", "maskable-dict"]
"""MaskablePPO on the facts (given the mask), plain PPO on facts + mask (not given it:
its greedy action may be infeasible), MaskablePPO on the dict observation."""


def _policy(kind: str, folder: Path) -> str:
    """An untrained policy in the human seat, its output layer scaled so greedy actions vary by state."""
    from sb3_contrib import MaskablePPO
    from stable_baselines3 import PPO

    torch.set_num_threads(1)
    observation = kind.split("-")[1]
    view = HumanView(SCENARIO, robot="random", observation=observation)
    cls = MaskablePPO if kind.startswith("maskable") else PPO
    policy = "MultiInputPolicy" if observation == "dict" else "MlpPolicy"
    model = cls(policy, view, n_steps=16, batch_size=16, seed=0, device="cpu")
    with torch.no_grad():
        model.policy.action_net.weight.mul_(300.0)  # orthogonal init at gain 0.01: near-uniform logits otherwise
    save_sb3_policy(folder, model, SCENARIO, observation=observation)
    return f"learned:path={folder}"


@pytest.fixture(scope="module", params=KINDS)
def spec(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> str:
    return _policy(request.param, tmp_path_factory.mktemp(request.param) / "policy")


def _live(spec: str, world: World):  # type: ignore[no-untyped-def]
    live = make_human(spec)
    live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    return live


def _mid_cycle_states(world: World, count: int, seed: int):  # type: ignore[no-untyped-def]
    """``count`` human-turn states: random play (70% feasible actions), then a robot action."""
    rules = BatchedRules(world)
    rng = np.random.default_rng(seed)
    batch = rules.initial(rng, count)
    for t in range(2 * int(rng.integers(0, 12)) + 1):
        agent = Agent(t % 2)
        masks = rules.masks(batch, agent)
        feasible = (rng.random(masks.shape) * masks).argmax(1)
        actions = np.where(rng.random(count) < 0.7, feasible, rng.integers(0, masks.shape[1], count))
        rules.step(batch, agent, actions)
    return batch


def test_batched_actions_are_the_live_humans_on_sampled_states(spec: str) -> None:
    """Per table: observation = ``World.facts`` / ``World.mask``, action = the live human's ``act``."""
    world = World(SCENARIO)
    partner = BatchedLearned(world, make_human(spec))
    live = _live(spec, world)
    batch = _mid_cycle_states(world, 400, seed=1)
    facts, masks = partner.observations(batch)
    got = partner.act(batch, np.full(len(batch), -1), np.random.default_rng(0))
    infeasible = 0
    for i in range(len(batch)):
        state = batch.state(i)
        f, m = world.facts(state), world.mask(state, Agent.HUMAN)
        assert (facts[i] == f).all() and (masks[i] == m).all()
        turn = Turn(world=world, state=state, agent=Agent.HUMAN, observation={"observation": f, "action_mask": m})
        expected = live.act(turn)
        assert got[i] == expected
        infeasible += not m[expected]
    assert len(set(got.tolist())) > 3  # the policy answers differently across states
    if live.masked:
        assert infeasible == 0
    else:  # not given the mask: some greedy actions are infeasible, returned as they are
        assert infeasible > 0


@pytest.mark.parametrize("seed", [0, 7])
def test_robot_seat_with_a_learned_human_replays_in_the_aec_env(spec: str, seed: int) -> None:
    """Each table replayed in the AEC env: the human's answer is the live human's act on the AEC turn.

    Also observations, rewards, flags, clock, cycle, tasks and the failed flags, through
    NEXT_STEP autoresets. Half the tables' humans are the learned policy and half the
    compiled cooperative human (a population; its answers must have positive probability).
    """
    n, max_cycles = 8, 12
    world = World(SCENARIO)
    env = robot_vector_env(n, SCENARIO, human=[spec, "cooperative"], max_cycles=max_cycles, cache=None)
    assert isinstance(env.partner, CompiledPopulation) and isinstance(env.partner.members[0], BatchedLearned)
    lives = [_live(spec, world), _live("cooperative", world)]
    obs, _ = env.reset(seed=seed)
    aecs = []
    for i in range(n):
        aec = raw_env(scenario=world.scenario, max_cycles=max_cycles)
        aec.reset(options={"state": env.state.state(i)})
        assert (obs[i] == aec.observe("robot")["observation"]).all()
        aecs.append(aec)
    rng = np.random.default_rng(seed)
    pending = np.zeros(n, dtype=bool)
    learned_answers = 0
    for _ in range(40):
        masks = env.action_masks()
        actions = np.where(
            rng.random(n) < 0.8, (rng.random(masks.shape) * masks).argmax(1), rng.integers(0, masks.shape[1], n)
        )
        member = env.partner.member.copy()
        obs, reward, term, trunc, info = env.step(actions)
        for i, aec in enumerate(aecs):
            if pending[i]:
                assert reward[i] == 0.0 and not term[i] and not trunc[i]
                aec.reset(options={"state": env.state.state(i)})
                assert (obs[i] == aec.observe("robot")["observation"]).all()
                continue
            assert (masks[i] == aec.observe("robot")["action_mask"].astype(bool)).all()
            aec.step(int(actions[i]))
            h = int(info["human_action"][i])
            if member[i] == 0:
                assert h == lives[0].act(aec.turn("human"))
                learned_answers += 1
            else:
                seen = int(actions[i]) if not aec.infos["robot"]["failed"] else -1  # cooperative reads it
                assert dict(lives[1].distribution(world, aec.world_state, seen)).get(h, 0.0) > 0.0
            r = aec.rewards["robot"]
            aec.step(h)
            assert reward[i] == r + aec.rewards["robot"]
            assert (obs[i] == aec.observe("robot")["observation"]).all()
            assert term[i] == aec.terminations["robot"] and trunc[i] == aec.truncations["robot"]
            assert (info["clock"][i], info["cycle"][i], info["tasks_solved"][i]) == (
                aec.clock,
                aec.cycles,
                aec.tasks_solved,
            )
            assert info["failed"][i] == aec.infos["robot"]["failed"]
            assert info["human_failed"][i] == aec.infos["human"]["failed"]
        pending = term | trunc
    assert learned_answers > 50


@pytest.mark.parametrize("num_envs", [1, 5, 300])
def test_one_policy_forward_pass_per_env_step_whatever_num_envs(spec: str, num_envs: int) -> None:
    """Counted on the policy network's output layer (a forward hook) and on ``predict``, autoresets included."""
    env = robot_vector_env(num_envs, SCENARIO, human=spec, max_cycles=3)
    partner = env.partner
    assert isinstance(partner, BatchedLearned)
    model = partner.human.model
    forwards = []
    handle = model.policy.action_net.register_forward_hook(lambda _m, inputs, _o: forwards.append(len(inputs[0])))
    predict, calls = model.predict, []
    model.predict = lambda *a, **k: (calls.append(1), predict(*a, **k))[1]
    try:
        env.reset(seed=0)
        assert forwards == [] and calls == []
        rng = np.random.default_rng(0)
        for step in range(1, 8):  # max_cycles=3: tables end and are autoreset along the way
            masks = env.action_masks()
            env.step((rng.random(masks.shape) * masks).argmax(1))
            assert len(calls) == step and forwards == [num_envs] * step
    finally:
        handle.remove()


def test_make_vec_with_a_learned_human_is_batched_and_seeded(spec: str) -> None:
    """``gymnasium.make_vec(..., human="learned:path=...")``: same seed, same trajectory."""
    runs = []
    for _ in range(2):
        env = gymnasium.make_vec(
            "hg_marl:hg_marl/RobotTableCleaning-v0", num_envs=4, vectorization_mode="vector_entry_point", human=spec
        )
        assert isinstance(env.unwrapped.partner, BatchedLearned)
        env.reset(seed=3)
        rng = np.random.default_rng(3)
        actions = []
        for _ in range(10):
            masks = env.unwrapped.action_masks()
            _, _, _, _, info = env.step((rng.random(masks.shape) * masks).argmax(1))
            actions.append(info["human_action"].copy())
        runs.append(np.array(actions))
    assert (runs[0] == runs[1]).all()


def test_a_policy_saved_for_the_robot_seat_is_refused_naming_the_file(tmp_path: Path) -> None:
    from sb3_contrib import MaskablePPO

    model = MaskablePPO("MlpPolicy", RobotView(SCENARIO), n_steps=16, batch_size=16, seed=0, device="cpu")
    folder = save_sb3_policy(tmp_path / "robot", model, SCENARIO, seat=Agent.ROBOT)
    with pytest.raises(ModelFileError, match=r"policy\.json: saved for .*\(robot\)"):
        BatchedLearned(World(SCENARIO), make_human(f"learned:path={folder}"))


def test_the_benchmarks_learned_option_prints_both_rows(tmp_path: Path) -> None:
    """``batched_throughput.py --learned FOLDER`` (the command of docs/batched.md) on a short budget."""
    import subprocess
    import sys

    folder = tmp_path / "policy"
    _policy("maskable-facts", folder)
    script = Path(__file__).resolve().parents[2] / "benchmarks" / "batched_throughput.py"
    argv = [str(script), "--learned", str(folder), "--num-envs", "8", "--seconds", "0.2", "--no-compiled"]
    out = subprocess.run(
        [sys.executable, *argv, "--scenario", SCENARIO], capture_output=True, text=True, timeout=600, check=False
    )
    assert out.returncode == 0, out.stderr
    assert "batched learned-sb3 num_envs=8:" in out.stdout and "single RobotView learned-sb3:" in out.stdout
    assert "CartPole" not in out.stdout
