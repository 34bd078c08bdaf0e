"""The goal-directed expert: a cost-optimal human-aware HTN planner for the two agents.

HATP-style: the plan is a joint plan of two streams (robot, human) with cross-stream
links, optimal for a cost model with social terms (see :mod:`.costs`), against a model
of what the human will do (:mod:`.models`; a stochastic model is planned against with
expectimax, which is how a partner-aware robot hands the planner its belief about the
human: ``Planner(world, human_model=model)``).

Quick use::

    from hg_marl.agents.planner import Planner
    planner = Planner(world)                       # cooperative human
    result = planner.plan(state)                   # robot to move
    result.robot_action, result.plan.duration, result.breakdown

Modules: ``costs`` (cost terms, weights, config, the cycle cost), ``models`` (human
models), ``domain`` (HTN methods), ``space`` (candidates, symmetry, admissible bound),
``halfstep`` (A* over half-steps), ``expectimax`` (stochastic humans), ``plan`` (plans
and results), ``planner`` (the facade and its cache), ``gantt`` (text and PNG charts).
The rules themselves are the core's (``World.table``).
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
