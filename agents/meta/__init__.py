"""MetaController criteria: one strategy per module, one signature, one registry.

====================  ========================================================
``random``            coin flip, p = 0.5 (Renaudo et al. 2015)
``planner``           the goal-directed expert only
``habit``             the habitual expert only
``entropy``           lower filtered normalised entropy
``entropy_and_cost``  entropy traded against decision cost (Dromnelle et al. 2022)
``vpi``               value of perfect information vs reward rate (Keramati et al. 2011)
``learning_state``    habit once its weights stop changing (the paper's proposal)
====================  ========================================================
"""

from hg_marl.agents.meta.base import (
    Criterion,
    Expert,
    HabitView,
    PlanProposal,
    entropy_bits,
    normalised_entropy,
    planner_distribution,
)
from hg_marl.agents.meta.controller import Decision, MetaController
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.meta.registry import CRITERIA, available_criteria, criterion_params, make_criterion

__all__ = [
    "CRITERIA",
    "CostModel",
    "Criterion",
    "Decision",
    "Expert",
    "HabitView",
    "MetaController",
    "PlanProposal",
    "available_criteria",
    "criterion_params",
    "entropy_bits",
    "make_criterion",
    "normalised_entropy",
    "planner_distribution",
]
