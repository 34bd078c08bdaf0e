"""``sb3``: a robot that plays a Stable-Baselines3 / sb3-contrib model trained in the robot seat.

A trained model is a model file (:mod:`hg_marl.agents.model_file`): a JSON header
(``model.json``) and its ``.npz`` weights. The header says what the weights cannot: the
algorithm and policy class to rebuild, the view's observation mode it was trained on
(``"facts"``, ``"flat"`` or ``"dict"``, see :mod:`hg_marl.agents.views`), the scenario,
the seat, and the fact and action names, so the robot rebuilds exactly the observation
the network saw and refuses a world whose facts or actions differ. Loading never
unpickles; SB3's own ``.zip`` is refused (``hg-marl convert --trust F`` converts one).

Action masks. A maskable model (``MaskablePPO``) is always given the turn's mask, as in
training. Plain models (PPO, A2C, DQN) act as they were trained: they never saw the mask
and may choose an infeasible action, which then fails (legal input, as in the paper).

Memory. A ``RecurrentPPO`` model (an LSTM policy) carries its LSTM state from turn to
turn and resets it when the episode starts, as in training; its action is the mode of
the policy's distribution (or a draw with the robot's generator). A model trained with the
history observation on the batched table (``training/baselines/recurrent_ppo_sb3.py``)
is refused: the robot does not rebuild that observation.

Decision time. A forward pass of a small MLP is about as cheap as the habit's; the robot
charges the same deterministic constant as the habitual expert
(:class:`~hg_marl.agents.meta.cost.CostModel` ``habit``) unless given a ``cost``
in ``"wall"`` mode, so SB3 robots and the paper's habit are charged alike.
``planning_time`` records the measured wall time of the forward pass.

Randomness. ``deterministic=True`` (default) takes the policy's mode. Otherwise the
action is sampled from the policy's distribution with the robot's own generator (never
torch's global one), so a run stays a function of its seed; DQN has no distribution
and always acts greedily.

torch and SB3 are imported inside functions only: importing this module (and the
robots registry) never imports torch.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.model_file import OBSERVATIONS, ModelFile, build_sb3, check_world, load_model_file
from hg_marl.agents.robots.base import Robot
from hg_marl.core import Agent, World
from hg_marl.core.errors import RobotError
from hg_marl.policy import Turn


def is_maskable(model: Any) -> bool:
    """Whether ``model`` takes action masks (sb3-contrib's Maskable* algorithms)."""
    return type(model).__name__.startswith("Maskable")


def observation_of(turn_observation: dict[str, np.ndarray], mode: str) -> Any:
    """The view's observation (``facts``/``flat``/``dict``) from an AEC observation."""
    facts, mask = turn_observation["observation"], turn_observation["action_mask"]
    if mode == "facts":
        return np.asarray(facts)
    if mode == "flat":
        return np.concatenate([facts, mask])
    return {"observation": np.asarray(facts), "action_mask": np.asarray(mask)}


class SB3Robot(Robot):
    """Plays a trained SB3 model in the robot seat (see the module docstring).

    Args:
        path: the model header (``model.json``), its weights, its stem, or its folder.
        deterministic: take the policy's most probable action (False: sample with the
            robot's generator).
        cost: decision cost model (default: the habit's constant, ``CostModel.habit``).
        model: an in-memory model instead of ``path`` (evaluation during training);
            then ``observation`` must be given.
        observation: the observation mode, when ``model`` is given.
    """

    name = "sb3"

    def __init__(
        self,
        path: str | Path | None = None,
        deterministic: bool = True,
        cost: CostModel | None = None,
        model: Any = None,
        observation: str | None = None,
    ) -> None:
        super().__init__(cost)
        if (path is None) == (model is None):
            raise RobotError("robot 'sb3' needs a trained model: --model FILE")
        self.deterministic = bool(deterministic)
        self.file: ModelFile | None = None
        if path is not None:
            self.file = load_model_file(path, what="--model", seat="robot")
            if self.file.header.get("history"):
                raise RobotError(
                    f"--model {path}: trained with the history observation on the batched table, which the sb3 "
                    "robot does not rebuild (play it with the library, see docs/learned-robots.md)"
                )
            model = build_sb3(self.file, optimizer=False)
            observation = self.file.header["observation"]
        if observation not in OBSERVATIONS:
            raise RobotError(f"observation must be one of {', '.join(OBSERVATIONS)}, got {observation!r}")
        self.model = model
        self.observation: str = str(observation)
        self.maskable = is_maskable(model)
        self.recurrent = type(model).__name__ == "RecurrentPPO"
        """An LSTM policy: its state is carried from turn to turn and reset with the episode."""
        self._lstm: Any = None
        self._start = True

    def _reset(self, world: World) -> None:
        if self.agent is not Agent.ROBOT:
            raise RobotError("the sb3 robot plays the robot seat only")
        if self.file is not None:
            check_world(self.file, world, Agent.ROBOT)
        self._lstm, self._start = None, True

    def _recurrent(self, obs: Any) -> int:
        """An LSTM policy's action (mode or a draw with the robot's generator), its state carried."""
        import torch

        policy = self.model.policy
        if self._lstm is None:
            zeros = np.zeros(policy.lstm_hidden_state_shape, dtype=np.float32)
            self._lstm = (zeros, zeros)
        with torch.no_grad():
            tensor, _ = policy.obs_to_tensor(obs)
            states = (torch.as_tensor(self._lstm[0]), torch.as_tensor(self._lstm[1]))
            start = torch.tensor([float(self._start)])
            dist, (h, c) = policy.get_distribution(tensor, states, start)
            probs = dist.distribution.probs.cpu().numpy().reshape(-1).astype(np.float64)
        self._lstm, self._start = (h.cpu().numpy(), c.cpu().numpy()), False
        if self.deterministic:
            return int(np.argmax(probs))
        probs /= probs.sum()
        return int(self.rng.choice(len(probs), p=probs))

    def _sample(self, obs: Any, mask: np.ndarray) -> int:
        """Draw from the policy's distribution with the robot's own generator."""
        import torch

        policy = self.model.policy
        with torch.no_grad():
            tensor, _ = policy.obs_to_tensor(obs)
            dist = (
                policy.get_distribution(tensor, action_masks=mask) if self.maskable else policy.get_distribution(tensor)
            )
            probs = dist.distribution.probs.cpu().numpy().reshape(-1).astype(np.float64)
        probs /= probs.sum()
        return int(self.rng.choice(len(probs), p=probs))

    def act(self, turn: Turn) -> int:
        """The model's action for the turn's observation (mask given to maskable models)."""
        t0 = time.perf_counter()
        obs = observation_of(turn.observation, self.observation)
        mask = np.asarray(turn.mask).astype(bool)
        if self.recurrent:
            action = self._recurrent(obs)
        elif not self.deterministic and hasattr(self.model.policy, "get_distribution"):
            action = self._sample(obs, mask)
        else:
            kwargs: dict[str, Any] = {"action_masks": mask} if self.maskable else {}
            predicted, _ = self.model.predict(obs, deterministic=True, **kwargs)
            action = int(predicted)
        wall = time.perf_counter() - t0
        self._record("sb3", action, planning_time=wall, decision_time=self.cost.habit_cost(wall))
        return action
