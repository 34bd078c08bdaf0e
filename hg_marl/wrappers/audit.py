"""Mask audit: counts the actions each agent sent, and those its real action mask ruled out.

Spec sheet
----------
============================  =================================================================
Import                        ``from hg_marl.wrappers import audit_v0``;
                              ``env = audit_v0(hg_marl.env())`` (innermost, over the raw env,
                              so it sees the real action indices before any padding)
Spaces, rewards, infos        unchanged.
``env.sent[agent]``           actions ``agent`` sent so far (``None`` steps of finished agents
                              are not counted).
``env.infeasible[agent]``     how many of them were infeasible in the state they were sent in.
============================  =================================================================

Why: every integration example claims "no infeasible action is ever sent"; this is the
independent check, read from the environment's own mask rather than from the library's.
Counts survive ``reset`` (they cover a whole training run).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from pettingzoo import AECEnv
from pettingzoo.utils import BaseWrapper


class MaskAuditWrapper(BaseWrapper):
    """Counts sent and infeasible actions per agent (see the module docstring)."""

    def __init__(self, env: AECEnv) -> None:
        super().__init__(env)
        self.sent = dict.fromkeys(env.possible_agents, 0)
        self.infeasible = dict.fromkeys(env.possible_agents, 0)

    def step(self, action: Any) -> None:
        agent = self.agent_selection
        if action is not None and not (self.terminations[agent] or self.truncations[agent]):
            mask = np.asarray(self.env.observe(agent)["action_mask"])
            index = int(action)
            self.sent[agent] += 1
            if not (0 <= index < mask.shape[0] and mask[index]):
                self.infeasible[agent] += 1
        super().step(action)


_INNER = ("env", "aec_env", "par_env", "venv", "vec_envs")


def find_audit(obj: Any, depth: int = 12) -> MaskAuditWrapper | None:
    """The :class:`MaskAuditWrapper` inside a stack of PettingZoo, SuperSuit or SB3 wrappers.

    Vector-env builders may copy the env they are given, so read the audit from the
    object actually stepped rather than keep a reference to the one built.
    """
    if isinstance(obj, MaskAuditWrapper):
        return obj
    if depth == 0:
        return None
    for name in _INNER:
        inner = getattr(obj, name, None)
        for candidate in inner if isinstance(inner, list) else [inner]:
            if candidate is not None and candidate is not obj:
                found = find_audit(candidate, depth - 1)
                if found is not None:
                    return found
    return None


def audit_v0(env: AECEnv) -> MaskAuditWrapper:
    """Wrap ``env`` so that it counts the actions each agent sent against its real mask."""
    return MaskAuditWrapper(env)
