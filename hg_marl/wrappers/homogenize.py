"""Homogenised view: every agent gets the same action space and the same observation space.

Spec sheet
----------
============================  =================================================================
Import                        ``from hg_marl.wrappers import homogenize_v0``;
                              ``env = homogenize_v0(hg_marl.env(), dtype=np.float32)``
Wraps                         any AEC env whose agents have ``Discrete`` action spaces and
                              ``Dict(observation=Box(F), action_mask=Box(A_i))`` observations
                              (TableCleaning-v0, or another wrapper with that shape).
Action space                  ``Discrete(A)`` for every agent, ``A = max_i A_i`` (31 for
                              ``paper2015``: the human's count). Index ``k < A_i`` is agent i's
                              own action ``k``; ``k >= A_i`` is padding, always masked out.
Observation space             ``Dict(observation=Box(0, 1, (F + N,), dtype), action_mask=Box(0,
                              1, (A,), int8))`` for every agent: the facts, then a one-hot agent
                              id (``N`` agents, in ``possible_agents`` order), so one shared
                              network can tell the seats apart.
Padding actions               legal input, like every element of the action space, and treated
                              as an infeasible action (no effect, the failure's cost, reported
                              in ``infos[agent]["failed"]``): the wrapper sends the agent's
                              first real action that the mask rules out. Masked policies never
                              send one.
dtype                         ``np.int8`` (default, as the env) or ``np.float32`` (what torch
                              networks want: Tianshou's ``Net``, RLlib's encoders).
Everything else               unchanged (rewards, terminations, infos, render, ``unwrapped``).
============================  =================================================================

Why: Tianshou's ``PettingZooEnv`` and SuperSuit's vector conversion require identical
spaces across agents, and SuperSuit's ``pad_action_space_v0`` / ``pad_observations_v0``
handle neither ``Dict`` observations nor keep the padded actions masked.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from gymnasium import spaces
from pettingzoo import AECEnv
from pettingzoo.utils import BaseWrapper

from hg_marl.envs.table_cleaning import InvalidActionError

DTYPES = (np.int8, np.float32)


def check_dtype(dtype: Any) -> type:
    """The observation dtype, checked against the supported ones (one line on bad input)."""
    for known in DTYPES:
        if np.dtype(dtype) == np.dtype(known):
            return known
    raise ValueError(f"dtype must be one of {[np.dtype(d).name for d in DTYPES]}, got {dtype!r}")


def dict_parts(env: AECEnv, agent: str) -> tuple[spaces.Box, int]:
    """The fact Box and the action count of ``agent`` in a Dict(observation, action_mask) env."""
    space = env.observation_space(agent)
    if not isinstance(space, spaces.Dict) or set(space.spaces) != {"observation", "action_mask"}:
        raise ValueError(f"expected a Dict(observation, action_mask) observation space for {agent!r}, got {space}")
    action_space = env.action_space(agent)
    if not isinstance(action_space, spaces.Discrete):
        raise ValueError(f"expected a Discrete action space for {agent!r}, got {action_space}")
    facts = space.spaces["observation"]
    assert isinstance(facts, spaces.Box)
    return facts, int(action_space.n)


class HomogenizeWrapper(BaseWrapper):
    """One shared ``Discrete`` action space and one shared observation space (see the module docstring)."""

    def __init__(self, env: AECEnv, dtype: Any = np.int8) -> None:
        super().__init__(env)
        self.dtype = check_dtype(dtype)
        agents = list(env.possible_agents)
        parts = [dict_parts(env, a) for a in agents]
        shapes = {facts.shape for facts, _ in parts}
        if len(shapes) != 1:
            raise ValueError(f"agents see fact vectors of different shapes {sorted(shapes)}; cannot share one space")
        n_facts = parts[0][0].shape[0]
        self._n_real = {a: n for a, (_, n) in zip(agents, parts, strict=True)}
        self.n_actions = max(self._n_real.values())
        self._agent_id = {a: np.eye(len(agents), dtype=self.dtype)[i] for i, a in enumerate(agents)}
        self._action_space = spaces.Discrete(self.n_actions)
        self._observation_space = spaces.Dict(
            {
                "observation": spaces.Box(0, 1, (n_facts + len(agents),), self.dtype),
                "action_mask": spaces.Box(0, 1, (self.n_actions,), np.int8),
            }
        )

    def observation_space(self, agent: str) -> spaces.Space:
        return self._observation_space

    def action_space(self, agent: str) -> spaces.Space:
        return self._action_space

    def observe(self, agent: str) -> dict[str, np.ndarray] | None:
        raw = super().observe(agent)
        if raw is None:
            return None
        mask = np.zeros(self.n_actions, np.int8)
        real = np.asarray(raw["action_mask"])
        mask[: real.shape[0]] = real
        facts: np.ndarray = np.asarray(raw["observation"], dtype=self.dtype)
        return {"observation": np.concatenate([facts, self._agent_id[agent]]), "action_mask": mask}

    def step(self, action: Any) -> None:
        agent = self.agent_selection
        live = not (self.terminations.get(agent, False) or self.truncations.get(agent, False))
        if live and action is not None:
            try:
                index = int(action)
            except (TypeError, ValueError):
                index = -1  # not an index: the env rejects it with its own message
            if self._n_real[agent] <= index < self.n_actions:
                action = self._infeasible_stand_in(agent, index)
        super().step(action)

    def _infeasible_stand_in(self, agent: str, index: int) -> int:
        """A real action of ``agent`` that is infeasible now: what a padded index does."""
        raw = super().observe(agent)
        ruled_out: Any = np.flatnonzero(np.asarray(raw["action_mask"]) == 0) if raw is not None else []
        if len(ruled_out) == 0:
            raise InvalidActionError(
                f"action {index} is padding for agent {agent!r} (real actions 0..{self._n_real[agent] - 1}) "
                "and every real action is feasible now, so none can stand in for it"
            )
        return int(ruled_out[0])


def homogenize_v0(env: AECEnv, dtype: Any = np.int8) -> HomogenizeWrapper:
    """Wrap ``env`` so that all agents share one action space and one observation space."""
    return HomogenizeWrapper(env, dtype=dtype)
