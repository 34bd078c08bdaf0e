"""PettingZoo wrappers that make TableCleaning-v0 fit the common MARL libraries.

Each is an AEC ``BaseWrapper``; they compose, and :func:`to_parallel` turns any stack
into the turn-based parallel view (one step = one cycle, robot then human).

============================  ===============================================  ================
library                       stack                                             mask
============================  ===============================================  ================
Tianshou ``PettingZooEnv``    ``homogenize_v0(env(), dtype=np.float32)``       obs dict
                                                                                ``action_mask``
RLlib ``PettingZooEnv`` +     ``flatten_v0(homogenize_v0(env()))``             obs dict
``ActionMaskingTorchRLModule``                                                  ``action_mask``
SuperSuit vector env -> SB3   ``to_parallel(flatten_v0(homogenize_v0(env()),   ``infos``
                              mask="info"))``
CleanRL-style loops           ``to_parallel(flatten_v0(homogenize_v0(env())))``  obs dict
============================  ===============================================  ================

SB3 adapters (``hg_marl.wrappers.sb3``, SB3 imported on demand): ``InfoMasks`` serves
the masks SuperSuit's vector env carries in ``infos`` to sb3-contrib; ``BatchedVecEnv``
makes the batched table (``hg_marl.envs.batched``) an SB3 ``VecEnv``.

``audit_v0`` (innermost) counts the actions each agent sent that its real mask ruled out.
``homogenize_v0`` gives every agent one ``Discrete`` action space padded with masked-out
actions and one observation space with an agent-id feature; ``flatten_v0`` makes the
facts a flat ``Box`` (``float32`` by default) with the mask in the observation dict under
the keys the library reads, or in ``infos``. Both pass PettingZoo's ``api_test`` and, through
:func:`to_parallel`, ``parallel_api_test``.
"""

from __future__ import annotations

from pettingzoo import AECEnv

from hg_marl.envs.parallel import TurnBasedParallelEnv
from hg_marl.wrappers.audit import AUDITS, MaskAuditWrapper, audit_totals, audit_v0
from hg_marl.wrappers.flat import FlatObservationWrapper, flatten_v0
from hg_marl.wrappers.homogenize import HomogenizeWrapper, homogenize_v0


def __getattr__(name: str) -> object:
    """The SB3 adapters (``InfoMasks``, ``BatchedVecEnv``, ``batched_vec_env``), imported on demand: SB3 is optional."""
    if name in ("InfoMasks", "BatchedVecEnv", "batched_vec_env"):
        from hg_marl.wrappers import sb3

        return getattr(sb3, name)
    raise AttributeError(f"module 'hg_marl.wrappers' has no attribute {name!r}")


def to_parallel(env: AECEnv) -> TurnBasedParallelEnv:
    """The turn-based parallel view of a (wrapped) TableCleaning-v0 AEC env."""
    return TurnBasedParallelEnv(env)


__all__ = [
    "AUDITS",
    "FlatObservationWrapper",
    "HomogenizeWrapper",
    "MaskAuditWrapper",
    "audit_totals",
    "audit_v0",
    "flatten_v0",
    "homogenize_v0",
    "to_parallel",
]
