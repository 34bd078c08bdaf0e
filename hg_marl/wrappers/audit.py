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
Counts survive ``reset`` (they cover a whole training run); :func:`audit_totals` sums
them over every live audit of the process, wherever a library keeps its env copies.
"""

from __future__ import annotations

import weakref
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
        AUDITS.add(self)

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None) -> None:
        AUDITS.add(self)  # copies made by vector-env builders (deepcopy, pickling) register here
        super().reset(seed=seed, options=options)

    def step(self, action: Any) -> None:
        agent = self.agent_selection
        if action is not None and not (self.terminations[agent] or self.truncations[agent]):
            mask = np.asarray(self.env.observe(agent)["action_mask"])
            index = int(action)
            self.sent[agent] += 1
            if not (0 <= index < mask.shape[0] and mask[index]):
                self.infeasible[agent] += 1
        super().step(action)


AUDITS: weakref.WeakSet[MaskAuditWrapper] = weakref.WeakSet()
"""Every live audit wrapper of this process: vector-env builders (SuperSuit, Tianshou, RLlib)
copy or build the envs they step, so read the counts here rather than from the env you built."""


def audit_totals() -> tuple[dict[str, int], dict[str, int]]:
    """Actions sent and infeasible ones, per agent, summed over :data:`AUDITS`."""
    sent: dict[str, int] = {}
    infeasible: dict[str, int] = {}
    for audit in list(AUDITS):
        for agent, n in audit.sent.items():
            sent[agent] = sent.get(agent, 0) + n
            infeasible[agent] = infeasible.get(agent, 0) + audit.infeasible[agent]
    return sent, infeasible


def audit_v0(env: AECEnv) -> MaskAuditWrapper:
    """Wrap ``env`` so that it counts the actions each agent sent against its real mask."""
    return MaskAuditWrapper(env)
