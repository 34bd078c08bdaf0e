"""Flat observation view: a ``Box`` of facts, with the action mask where the library looks for it.

Spec sheet
----------
============================  =================================================================
Import                        ``from hg_marl.wrappers import flatten_v0``;
                              ``env = flatten_v0(homogenize_v0(hg_marl.env()))``
Wraps                         any AEC env with ``Dict(observation=Box(F), action_mask=Box(A))``
                              observations (TableCleaning-v0, :func:`homogenize_v0`'s output).
Observation, ``mask="obs"``   ``Dict({obs_key: Box(0, 1, (F,), dtype), mask_key: Box(0, 1, (A,),
(default)                     int8)})``; the defaults ``observations`` / ``action_mask`` are the
                              keys RLlib's ``ActionMaskingTorchRLModule`` reads. The mask stays
                              ``int8``, the dtype Gymnasium's ``Discrete.sample(mask)`` requires.
Observation, ``mask="info"``  ``Box(0, 1, (F,), dtype)``; the mask is ``infos[agent]["action_mask"]``
                              (``int8``, shape ``(A,)``, always present), where SuperSuit's
                              vector envs pass it through to SB3 and CleanRL-style loops.
dtype                         of the facts: ``np.float32`` (default: torch layers refuse ``int8``
                              input) or ``np.int8``.
Actions, rewards, ...         unchanged.
============================  =================================================================

Why: RLlib has no default encoder for ``Dict`` observations unless they follow its
action-masking convention, and ``int8`` inputs fail in torch's matmul; SB3's policies and
SuperSuit's vector envs want a plain ``Box``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from gymnasium import spaces
from pettingzoo import AECEnv
from pettingzoo.utils import BaseWrapper

from hg_marl.wrappers.homogenize import check_dtype, dict_parts

MASK_PLACES = ("obs", "info")


class FlatObservationWrapper(BaseWrapper):
    """Facts as a flat ``Box``, the mask in the observation dict or in infos (see the module docstring)."""

    def __init__(
        self,
        env: AECEnv,
        mask: str = "obs",
        obs_key: str = "observations",
        mask_key: str = "action_mask",
        dtype: Any = np.float32,
    ) -> None:
        super().__init__(env)
        if mask not in MASK_PLACES:
            raise ValueError(f"mask must be one of {MASK_PLACES}, got {mask!r}")
        if not obs_key or not mask_key or obs_key == mask_key:
            raise ValueError(
                f"obs_key and mask_key must be two different non-empty names, got {obs_key!r}, {mask_key!r}"
            )
        self.mask_place = mask
        self.obs_key, self.mask_key = obs_key, mask_key
        self.dtype = check_dtype(dtype)
        self._infos: dict[str, dict[str, Any]] = {}
        self._spaces: dict[str, spaces.Space] = {}
        for agent in env.possible_agents:
            facts, n = dict_parts(env, agent)
            box = spaces.Box(0, 1, facts.shape, self.dtype)
            self._spaces[agent] = (
                box if mask == "info" else spaces.Dict({obs_key: box, mask_key: spaces.Box(0, 1, (n,), np.int8)})
            )

    def observation_space(self, agent: str) -> spaces.Space:
        return self._spaces[agent]

    def observe(self, agent: str) -> Any:
        raw = super().observe(agent)
        if raw is None:
            return None
        facts: np.ndarray = np.asarray(raw["observation"], dtype=self.dtype)
        if self.mask_place == "info":
            return facts
        return {self.obs_key: facts, self.mask_key: np.asarray(raw["action_mask"], dtype=np.int8)}

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None) -> None:
        super().reset(seed=seed, options=options)
        self._refresh_infos()

    def step(self, action: Any) -> None:
        super().step(action)
        self._refresh_infos()

    def _refresh_infos(self) -> None:
        """Masks change only on reset and step, so infos are built then (one array per agent and state)."""
        if self.mask_place == "info":
            self._infos = {}
            for agent, info in self.env.infos.items():
                raw = self.env.observe(agent)
                mask = np.asarray(raw["action_mask"], dtype=np.int8) if raw is not None else None
                self._infos[agent] = {**info, "action_mask": mask}

    @property
    def infos(self) -> dict[str, dict[str, Any]]:
        """The wrapped env's infos; with ``mask="info"`` each also carries the agent's current mask."""
        return self._infos if self.mask_place == "info" else self.env.infos

    @infos.setter
    def infos(self, value: dict[str, dict[str, Any]]) -> None:
        self.env.infos = value


def flatten_v0(env: AECEnv, **options: Any) -> FlatObservationWrapper:
    """Wrap ``env`` so that observations are a flat ``Box`` with the mask beside them.

    ``options``: ``mask``, ``obs_key``, ``mask_key``, ``dtype`` of :class:`FlatObservationWrapper`.
    """
    return FlatObservationWrapper(env, **options)
