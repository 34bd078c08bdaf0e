"""Any project human or robot as a library policy, so scripted partners sit in MARL training loops.

A library policy sees only observations (often in another process), while the project's
actors reason on the full state through a :class:`~hg_marl.policy.Turn`. The bridge is
in the environment: :func:`scripted_v0` lets the actor decide on the real state and
shows the seat a one-hot action mask holding that decision. Any policy that follows
the mask then plays the actor exactly; the fixed policies below do just that:

- Tianshou: :func:`tianshou_fixed_algorithm` (an off-policy ``Algorithm`` whose
  ``BasePolicy`` takes the first allowed action; it never trains), for
  ``MultiAgentOffPolicyAlgorithm``.
- RLlib: :func:`rllib_fixed_module_class` (an ``RLModule`` whose logits are 0 on allowed
  actions and -inf elsewhere), for a module spec that the algorithm does not train.

Spec sheet of :func:`scripted_v0`
---------------------------------
============================  =================================================================
Import                        ``from hg_marl.agents.adapters import scripted_v0``;
                              ``env = homogenize_v0(scripted_v0(hg_marl.env(), human="lazy"))``
Wraps                         TableCleaning-v0 (AEC), under any padding/flattening wrapper.
Scripted seat's mask          one-hot on the actor's chosen action (which may be infeasible:
                              scripted humans may try what fails, as in the project's runs).
Other seats, spaces, rewards  unchanged.
Decisions                     one ``actor.act`` per turn, on the state when the seat is
                              observed; ``reset(seed=s)`` reseeds the actor from ``s``.
Parallel view                 the human is observed at the start of the cycle, so a scripted
                              human decides before the robot moves; use AEC loops for exact
                              turn-taking (Tianshou, RLlib's ``PettingZooEnv`` are AEC).
============================  =================================================================
"""

from __future__ import annotations

from typing import Any

import numpy as np
from pettingzoo import AECEnv
from pettingzoo.utils import BaseWrapper

from hg_marl.agents.humans.registry import resolve_human
from hg_marl.agents.views import make_robot_actor
from hg_marl.core import Agent
from hg_marl.policy import Actor


class ScriptedSeatWrapper(BaseWrapper):
    """Shows scripted seats a one-hot mask of their actor's decision (see the module docstring)."""

    def __init__(self, env: AECEnv, actors: dict[str, Actor]) -> None:
        super().__init__(env)
        unknown = sorted(set(actors) - set(env.possible_agents))
        if unknown:
            raise ValueError(f"scripted seats {unknown} are not agents of this env {env.possible_agents}")
        self.actors = dict(actors)
        self._rng = np.random.default_rng()
        self._turns = 0
        self._decided: dict[str, tuple[int, int]] = {}

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None) -> None:
        super().reset(seed=seed, options=options)
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        world = self.env.unwrapped.world
        for name, actor in self.actors.items():
            seat = Agent.ROBOT if name == "robot" else Agent.HUMAN
            actor.reset(world, seat, np.random.default_rng(int(self._rng.integers(2**63 - 1))))
        self._turns = 0
        self._decided = {}

    def step(self, action: Any) -> None:
        super().step(action)
        self._turns += 1

    def decision(self, agent: str) -> int:
        """The scripted ``agent``'s action for the current turn (decided once per turn)."""
        turn, action = self._decided.get(agent, (-1, -1))
        if turn != self._turns:
            action = int(self.actors[agent].act(self.env.unwrapped.turn(agent)))
            self._decided[agent] = (self._turns, action)
        return action

    def observe(self, agent: str) -> Any:
        raw = super().observe(agent)
        if agent not in self.actors or raw is None:
            return raw
        if self.terminations.get(agent, False) or self.truncations.get(agent, False):
            return raw
        mask = np.zeros_like(np.asarray(raw["action_mask"]))
        mask[self.decision(agent)] = 1
        return {"observation": raw["observation"], "action_mask": mask}


def scripted_v0(env: AECEnv, robot: str | Actor | None = None, human: str | Actor | None = None) -> ScriptedSeatWrapper:
    """Wrap ``env`` so that the given seats play a project robot/human (names as in ``hg-marl run --list``)."""
    actors: dict[str, Actor] = {}
    if robot is not None:
        actors["robot"] = make_robot_actor(robot)
    if human is not None:
        actors["human"] = resolve_human(human)
    if not actors:
        raise ValueError("scripted_v0 needs robot= or human= (a name or an Actor)")
    return ScriptedSeatWrapper(env, actors)


def tianshou_fixed_algorithm(action_space: Any) -> Any:
    """A Tianshou off-policy ``Algorithm`` that takes the first allowed action and never learns.

    Over a :func:`scripted_v0` seat that is exactly the scripted actor's action.
    """
    from tianshou.algorithm.random import MARLRandomDiscreteMaskedOffPolicyAlgorithm
    from tianshou.data import Batch

    class FirstAllowedPolicy(MARLRandomDiscreteMaskedOffPolicyAlgorithm.Policy):
        def forward(self, batch: Any, state: Any = None, **kwargs: Any) -> Any:
            return Batch(act=np.asarray(batch.obs.mask).argmax(axis=-1))

    algorithm = MARLRandomDiscreteMaskedOffPolicyAlgorithm(action_space)
    algorithm.policy = FirstAllowedPolicy(action_space)
    return algorithm


def rllib_fixed_module_class() -> type:
    """An RLlib ``TorchRLModule`` class (new API stack) that samples only allowed actions and has no weights to train.

    Its observations are ``{"observations": ..., "action_mask": ...}`` (``flatten_v0``'s
    default); over a :func:`scripted_v0` seat the one allowed action is the actor's.
    """
    import torch
    from ray.rllib.core.columns import Columns
    from ray.rllib.core.rl_module.apis.value_function_api import ValueFunctionAPI
    from ray.rllib.core.rl_module.torch import TorchRLModule

    class FixedMaskModule(TorchRLModule, ValueFunctionAPI):
        def setup(self) -> None:
            super().setup()
            self._dummy = torch.nn.Parameter(torch.zeros(1), requires_grad=False)

        def _forward(self, batch: dict[str, Any], **kwargs: Any) -> dict[str, Any]:
            mask = batch[Columns.OBS]["action_mask"].float()
            logits = torch.where(mask > 0, torch.zeros_like(mask), torch.full_like(mask, -1e9))
            return {Columns.ACTION_DIST_INPUTS: logits}

        def compute_values(self, batch: dict[str, Any], embeddings: Any = None) -> Any:
            # Values are asked for by PPO's connectors even for modules it does not train.
            return torch.zeros(batch[Columns.OBS]["action_mask"].shape[0])

    return FixedMaskModule
