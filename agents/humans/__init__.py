"""Swappable humans: one protocol (:class:`hg_marl.policy.Actor`), one registry.

>>> from hg_marl.agents.humans import make_human, available_humans
>>> human = make_human("lazy", p_idle=0.5)          # or make_human("lazy:p_idle=0.5")
>>> sorted(available_humans())[:3]
['adversarial', 'cooperative', 'lazy']

Stationary humans (all but ``switching``, ``replay`` and SB3 ``learned``) also expose
``distribution(world, state)``, which the oracle folds into its exact model.
"""

from hg_marl.agents.humans.base import Distribution, HumanError, StationaryHuman
from hg_marl.agents.humans.learned import save_learned_policy, save_sb3_policy
from hg_marl.agents.humans.registry import HUMANS, HumanSpec, Param, available_humans, make_human, resolve_human
from hg_marl.agents.humans.trace import Episode, TraceRecorder, TraceWriter, behaviour_table, read_trace

__all__ = [
    "HUMANS",
    "Distribution",
    "Episode",
    "HumanError",
    "HumanSpec",
    "Param",
    "StationaryHuman",
    "TraceRecorder",
    "TraceWriter",
    "available_humans",
    "behaviour_table",
    "make_human",
    "read_trace",
    "resolve_human",
    "save_learned_policy",
    "save_sb3_policy",
]
