"""Pinned against a planted bug: a states budget is a most, so a model of exactly that size is accepted."""

from __future__ import annotations

import pytest

from hg_marl.agents.models import Budget, OverBudget


def test_a_model_of_exactly_the_budget_passes_and_one_more_state_is_refused() -> None:
    budget = Budget(seconds=None, memory=None, states=100, free_memory=lambda: None)
    budget.check("explore", 100, states=100)  # at the budget: within it
    assert budget.phase == "explore"
    with pytest.raises(OverBudget, match="max_states=100 states"):
        budget.check("explore", 101, states=101)
