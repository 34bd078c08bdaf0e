"""The one registry of MetaController criteria: ``make_criterion(name, **params)``."""

from __future__ import annotations

import inspect
from typing import Any

from hg_marl.agents.meta.base import Criterion
from hg_marl.agents.meta.coin import RandomCriterion
from hg_marl.agents.meta.entropy import EntropyCriterion
from hg_marl.agents.meta.entropy_cost import EntropyAndCostCriterion
from hg_marl.agents.meta.fixed import HabitOnly, PlannerOnly
from hg_marl.agents.meta.learning_state import LearningStateCriterion
from hg_marl.agents.meta.vpi import VPICriterion
from hg_marl.core.errors import CriterionError
from hg_marl.core.spec import construct

CRITERIA: dict[str, type[Criterion]] = {
    c.name: c
    for c in (
        RandomCriterion,
        PlannerOnly,
        HabitOnly,
        EntropyCriterion,
        EntropyAndCostCriterion,
        VPICriterion,
        LearningStateCriterion,
    )
}
"""Criterion classes by name (a registry of classes: the only module-level table)."""


def available_criteria() -> tuple[str, ...]:
    """Names accepted by :func:`make_criterion`."""
    return tuple(CRITERIA)


def criterion_params(name: str) -> tuple[str, ...]:
    """Parameter names a criterion accepts."""
    return tuple(inspect.signature(_lookup(name)).parameters)


def _lookup(name: str) -> type[Criterion]:
    try:
        return CRITERIA[name]
    except KeyError:
        raise CriterionError(f"unknown criterion {name!r}; available: {', '.join(CRITERIA)}") from None


def make_criterion(name: str, **params: Any) -> Criterion:
    """Build a criterion from a spec, e.g. ``make_criterion("vpi:tau=0.1")`` or ``make_criterion("vpi", tau=0.1)``.

    Raises:
        CriterionError: unknown name (the message lists the known ones), unknown parameter
            (lists the accepted ones) or a parameter out of range.
    """
    criterion: Criterion = construct(name, CRITERIA, params, kind="criterion", error=CriterionError)
    return criterion
