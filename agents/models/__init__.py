"""Exact models on arrays: one budget, one builder, one solver (see ``docs/exact-references.md``).

The oracle (``agents/oracle.py``) builds its semi-MDP here; the layering is that of the
package: this module uses the core rules and the batched rules, never a robot.
"""

from hg_marl.agents.models.answers import AnswerTable
from hg_marl.agents.models.budget import Budget, OverBudget
from hg_marl.agents.models.builder import Model, build_model
from hg_marl.agents.models.packing import PackedMap, StatePacker
from hg_marl.agents.models.solve import Solution, solve

__all__ = [
    "AnswerTable",
    "Budget",
    "Model",
    "OverBudget",
    "PackedMap",
    "Solution",
    "StatePacker",
    "build_model",
    "solve",
]
