"""The goal-directed expert: a cost-optimal human-aware HTN planner (DESIGN.md section 3).

Quick use::

    from hg_marl.agents.planner import Planner
    planner = Planner(world)                       # cooperative human
    result = planner.plan(state)                   # robot to move
    result.robot_action, result.plan.duration, result.breakdown

Modules: ``costs`` (cost terms, weights, config), ``models`` (human models),
``domain`` (HTN methods), ``space`` (candidates, symmetry, admissible bound),
``halfstep`` (A* over half-steps, the one in use), ``search`` (the joint-cycle A* it
replaced, kept as a cross-check), ``expectimax`` (stochastic humans), ``plan`` (plans and results),
``planner`` (the facade and its cache), ``execution`` (following and monitoring a plan),
``gantt`` (text and PNG charts).
"""

from hg_marl.agents.planner.costs import TERMS, CostWeights, PlannerConfig, Terms
from hg_marl.agents.planner.domain import DEFAULT_METHODS, Domain
from hg_marl.agents.planner.models import HumanModel, RestrictedHuman, cooperative, lazy, make_human_model, no_handover
from hg_marl.agents.planner.plan import NO_ACTION, Link, Plan, PlanResult, Step
from hg_marl.agents.planner.planner import Planner

__all__ = [
    "DEFAULT_METHODS",
    "NO_ACTION",
    "TERMS",
    "CostWeights",
    "Domain",
    "HumanModel",
    "Link",
    "Plan",
    "PlanResult",
    "Planner",
    "PlannerConfig",
    "RestrictedHuman",
    "Step",
    "Terms",
    "cooperative",
    "lazy",
    "make_human_model",
    "no_handover",
]
