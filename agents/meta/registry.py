"""The registry of MetaController criteria: ``make_criterion(name, **params)``.

A :class:`hg_marl.core.registry.Registry` like the humans' and the robots': each
criterion's parameters and defaults are read from its constructor's signature.
"""

from __future__ import annotations

from typing import Any

from hg_marl.agents.meta.base import Criterion
from hg_marl.agents.meta.coin import RandomCriterion
from hg_marl.agents.meta.entropy import EntropyCriterion
from hg_marl.agents.meta.entropy_cost import EntropyAndCostCriterion
from hg_marl.agents.meta.fixed import HabitOnly, PlannerOnly
from hg_marl.agents.meta.learning_state import LearningStateCriterion
from hg_marl.agents.meta.vpi import VPICriterion
from hg_marl.core.errors import CriterionError
from hg_marl.core.registry import Registry

CRITERIA = Registry(
    "criterion",
    CriterionError,
    (
        RandomCriterion,
        PlannerOnly,
        HabitOnly,
        EntropyCriterion,
        EntropyAndCostCriterion,
        VPICriterion,
        LearningStateCriterion,
    ),
)
"""Every criterion by name (``CRITERIA[name].factory()`` is its class)."""


def available_criteria() -> tuple[str, ...]:
    """Names accepted by :func:`make_criterion`."""
    return tuple(CRITERIA)


def criterion_params(name: str) -> tuple[str, ...]:
    """Parameter names a criterion accepts."""
    return tuple(CRITERIA.lookup(name).defaults())


def make_criterion(name: str, **params: Any) -> Criterion:
    """Build a criterion from a spec, e.g. ``make_criterion("vpi:tau=0.1")`` or ``make_criterion("vpi", tau=0.1)``.

    Raises:
        CriterionError: unknown name (the message lists the known ones), unknown parameter
            (lists the accepted ones) or a parameter out of range.
    """
    criterion: Criterion = CRITERIA.make(name, **params)
    return criterion
