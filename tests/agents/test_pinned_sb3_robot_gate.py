"""The ``sb3`` robot's arguments, observations, masks, draws and records, pinned for the mutation gate.

Expected values come from the module's documented rules, checked against SB3's own API as
the reference (untrained models, their output layer scaled so greedy actions vary by
state): a maskable model is always given the turn's mask and a plain one never is; the
view's observation is the facts, the facts then the mask, or the dict of both; with
``deterministic=False`` the action is drawn from the policy's distribution with the robot's
own generator (DQN, which has no distribution, stays greedy); each decision is recorded as
the ``sb3`` expert, charged the habit's constant (or the wall time in ``"wall"`` mode).
"""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.model_file import save_sb3, world_fields
from hg_marl.agents.robots import sb3 as sb3_module
from hg_marl.agents.robots.sb3 import SB3Robot, is_maskable, observation_of
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, World
from hg_marl.core.errors import ModelFileError, RobotError
from hg_marl.policy import Turn

pytest.importorskip("sb3_contrib")
torch = pytest.importorskip("torch")

SCENARIO = "paper2015"
WORLD = World(SCENARIO)
STATES = [WORLD.initial_state(np.random.default_rng(seed)) for seed in range(12)]


def _model(algo: str, observation: str = "facts") -> Any:
    """An untrained model in the robot seat, its output layer scaled so its greedy actions vary."""
    from sb3_contrib import MaskablePPO
    from stable_baselines3 import DQN, PPO

    torch.set_num_threads(1)
    view = RobotView(SCENARIO, observation=observation)
    policy = "MultiInputPolicy" if observation == "dict" else "MlpPolicy"
    if algo == "dqn":
        return DQN(policy, view, buffer_size=100, learning_starts=0, seed=0, device="cpu")
    cls = MaskablePPO if algo == "maskable" else PPO
    model: Any = cls(policy, view, n_steps=16, batch_size=16, seed=0, device="cpu")
    with torch.no_grad():
        model.policy.action_net.weight.mul_(300.0)
    return model


@pytest.fixture(scope="module")
def maskable() -> Any:
    return _model("maskable")


@pytest.fixture(scope="module")
def plain_flat() -> Any:
    return _model("ppo", "flat")


def _turn(state: Any) -> Turn:
    obs = {"observation": WORLD.facts(state), "action_mask": WORLD.mask(state, Agent.ROBOT)}
    return Turn(WORLD, state, Agent.ROBOT, obs)


def _robot(model: Any, observation: str, seed: int = 0, **kwargs: Any) -> SB3Robot:
    robot = SB3Robot(model=model, observation=observation, **kwargs)
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(seed))
    return robot


def test_the_robot_needs_exactly_one_of_a_path_and_a_model(maskable: Any) -> None:
    with pytest.raises(RobotError, match="needs a trained model"):
        SB3Robot()
    with pytest.raises(RobotError, match="needs a trained model"):
        SB3Robot(path="model.json", model=maskable, observation="facts")


@pytest.mark.parametrize("observation", [None, "pixels"])
def test_an_in_memory_model_needs_a_known_observation_mode(maskable: Any, observation: str | None) -> None:
    with pytest.raises(RobotError, match=rf"^observation must be one of facts, flat, dict, got {observation!r}$"):
        SB3Robot(model=maskable, observation=observation)


def test_only_a_maskable_algorithm_takes_masks_and_neither_is_recurrent(maskable: Any, plain_flat: Any) -> None:
    assert is_maskable(maskable) and not is_maskable(plain_flat)
    robot = SB3Robot(model=maskable, observation="facts")
    assert robot.maskable and not robot.recurrent and robot.observation == "facts"
    assert not SB3Robot(model=plain_flat, observation="flat").maskable


def test_the_views_observations_are_the_facts_the_facts_then_the_mask_or_both_by_name() -> None:
    facts, mask = np.array([1, 0, 1], dtype=np.int8), np.array([0, 1], dtype=np.int8)
    turn_obs = {"observation": facts, "action_mask": mask}
    np.testing.assert_array_equal(observation_of(turn_obs, "facts"), facts)
    np.testing.assert_array_equal(observation_of(turn_obs, "flat"), [1, 0, 1, 0, 1])
    built = "".join(["fl", "at"])  # a mode built at run time (a header read from JSON): equal, not the same object
    np.testing.assert_array_equal(observation_of(turn_obs, built), [1, 0, 1, 0, 1])
    as_dict = observation_of(turn_obs, "dict")
    assert set(as_dict) == {"observation", "action_mask"}
    np.testing.assert_array_equal(as_dict["observation"], facts)
    np.testing.assert_array_equal(as_dict["action_mask"], mask)


def test_a_maskable_model_acts_on_the_masked_greedy_action_and_is_recorded_as_sb3(maskable: Any) -> None:
    robot = _robot(maskable, "facts")
    for state in STATES:
        mask = WORLD.mask(state, Agent.ROBOT).astype(bool)
        want, _ = maskable.predict(WORLD.facts(state), deterministic=True, action_masks=mask)
        action = robot.act(_turn(state))
        assert action == int(want) and mask[action]
        decision = robot.last_decision
        assert decision is not None and decision.expert == "sb3" and decision.action == action
        assert decision.decision_time == CostModel().habit
        assert decision.planning_time >= 0.0


def test_a_plain_model_acts_on_its_greedy_action_without_the_mask(plain_flat: Any) -> None:
    robot = _robot(plain_flat, "flat")
    for state in STATES:
        facts, mask = WORLD.facts(state), WORLD.mask(state, Agent.ROBOT)
        want, _ = plain_flat.predict(np.concatenate([facts, mask]), deterministic=True)
        assert robot.act(_turn(state)) == int(want)


def test_in_wall_mode_a_decision_is_charged_its_measured_forward_pass(
    maskable: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A fake clock read at 0.125 s before the forward pass and 0.375 s after: 0.25 s, recorded and charged."""
    readings = iter([0.125, 0.375])
    monkeypatch.setattr(sb3_module, "time", types.SimpleNamespace(perf_counter=lambda: next(readings)))
    robot = _robot(maskable, "facts", cost=CostModel(mode="wall"))
    robot.act(_turn(STATES[0]))
    decision = robot.last_decision
    assert decision is not None and decision.planning_time == 0.25 and decision.decision_time == 0.25


def test_a_sampling_robot_draws_from_the_policy_distribution_with_its_own_generator(maskable: Any) -> None:
    """Reference: SB3's masked distribution's probabilities, drawn with a generator seeded as the robot's."""
    robot = _robot(maskable, "facts", seed=11, deterministic=False)
    reference = np.random.default_rng(11)
    policy = maskable.policy
    for state in STATES * 3:
        facts, mask = WORLD.facts(state), WORLD.mask(state, Agent.ROBOT).astype(bool)
        with torch.no_grad():
            tensor, _ = policy.obs_to_tensor(facts)
            dist = policy.get_distribution(tensor, action_masks=mask)
        probs = dist.distribution.probs.numpy().reshape(-1).astype(np.float64)
        probs /= probs.sum()
        want = int(reference.choice(len(probs), p=probs))
        action = robot.act(_turn(state))
        assert action == want and mask[action]


def test_a_sampling_plain_model_draws_without_the_mask(plain_flat: Any) -> None:
    robot = _robot(plain_flat, "flat", seed=3, deterministic=False)
    reference = np.random.default_rng(3)
    policy = plain_flat.policy
    for state in STATES * 2:
        obs = np.concatenate([WORLD.facts(state), WORLD.mask(state, Agent.ROBOT)])
        with torch.no_grad():
            tensor, _ = policy.obs_to_tensor(obs)
            probs = policy.get_distribution(tensor).distribution.probs.numpy().reshape(-1).astype(np.float64)
        assert robot.act(_turn(state)) == int(reference.choice(len(probs), p=probs / probs.sum()))


def test_dqn_has_no_distribution_so_even_a_sampling_robot_acts_greedily() -> None:
    dqn = _model("dqn")
    robot = _robot(dqn, "facts", deterministic=False)
    for state in STATES:
        want, _ = dqn.predict(WORLD.facts(state), deterministic=True)
        assert robot.act(_turn(state)) == int(want)


def test_the_robot_plays_the_robot_seat_only(maskable: Any) -> None:
    robot = SB3Robot(model=maskable, observation="facts")
    with pytest.raises(RobotError, match="robot seat only"):
        robot.reset(WORLD, Agent.HUMAN, np.random.default_rng(0))


def test_a_saved_model_plays_as_the_in_memory_one_and_only_in_its_own_world(maskable: Any, tmp_path: Path) -> None:
    save_sb3(maskable, tmp_path / "model.json", world_fields(WORLD, Agent.ROBOT), observation="facts")
    robot = SB3Robot(path=tmp_path)
    assert robot.observation == "facts" and robot.maskable and robot.file is not None
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    memory = _robot(maskable, "facts")
    assert [robot.act(_turn(s)) for s in STATES] == [memory.act(_turn(s)) for s in STATES]
    with pytest.raises(ModelFileError, match="differ from 'roboergosum'"):
        robot.reset(World("roboergosum"), Agent.ROBOT, np.random.default_rng(0))


def test_a_sampling_recurrent_robot_draws_with_its_generator_and_carries_its_lstm_state() -> None:
    """Reference: sb3-contrib's own recurrent distribution, its LSTM state carried from turn to
    turn (zeros at the start), each action drawn with a generator seeded as the robot's."""
    from sb3_contrib import RecurrentPPO

    torch.set_num_threads(1)
    model: Any = RecurrentPPO(
        "MlpLstmPolicy",
        RobotView(SCENARIO),
        n_steps=16,
        batch_size=16,
        seed=0,
        device="cpu",
        policy_kwargs={"lstm_hidden_size": 8},
    )
    with torch.no_grad():
        model.policy.action_net.weight.mul_(300.0)
    robot = _robot(model, "facts", seed=5, deterministic=False)
    assert robot.recurrent and not robot.maskable
    reference = np.random.default_rng(5)
    policy: Any = model.policy
    zeros = np.zeros(policy.lstm_hidden_state_shape, dtype=np.float32)
    state = (torch.as_tensor(zeros), torch.as_tensor(zeros))
    for turn_number, s in enumerate(STATES * 2):
        with torch.no_grad():
            tensor, _ = policy.obs_to_tensor(WORLD.facts(s))
            start = torch.tensor([1.0 if turn_number == 0 else 0.0])
            dist, state = policy.get_distribution(tensor, state, start)
        probs = dist.distribution.probs.numpy().reshape(-1).astype(np.float64)
        want = int(reference.choice(len(probs), p=probs / probs.sum()))
        assert robot.act(_turn(s)) == want


def test_a_model_of_another_algorithm_than_recurrent_ppo_is_not_recurrent() -> None:
    """sb3-contrib's TRPO (a name sorting after "RecurrentPPO") has no LSTM: it acts as its predict."""
    from sb3_contrib import TRPO

    torch.set_num_threads(1)
    model: Any = TRPO("MlpPolicy", RobotView(SCENARIO), n_steps=16, batch_size=16, seed=0, device="cpu")
    robot = _robot(model, "facts")
    assert not robot.recurrent and not robot.maskable
    for state in STATES[:4]:
        want, _ = model.predict(WORLD.facts(state), deterministic=True)
        assert robot.act(_turn(state)) == int(want)
