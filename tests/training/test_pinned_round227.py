"""Values that round 227's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.agents.compiled import answer_table
from hg_marl.agents.models import OverBudget
from hg_marl.core import World
from tests.env.test_compiled_tables import live


def test_a_refusal_of_a_compiled_tables_budget_names_the_scenario_then_the_human() -> None:
    # The table keeps the compiler's budget for the answers asked of it later; a refusal of that
    # budget (here the machine out of memory: free bytes 0, under the 512 MiB floor) opens with what
    # it was computing, the scenario first and the human second, as the compiler's own refusal does:
    # "scenario: 'paper2015' against 'random' is over its budget of the machine: ...".
    world = World("paper2015")
    table = answer_table(world, live("random", world))
    table.budget.free_memory = lambda: 0
    with pytest.raises(OverBudget) as refused:
        table.budget.check("partner answers", 0)
    assert str(refused.value).startswith("scenario: 'paper2015' against 'random' is over its budget of the machine")
