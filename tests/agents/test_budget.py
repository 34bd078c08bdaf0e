"""One budget, read in every phase: refusals counted in work (states, checks), never in seconds.

Expected values: a scenario built to explode (``roboergosum`` against ``lazy``: 5,040
layouts, about 250,000 states without symmetry) stopped by a budget of N states must stop
in the exploration having explored at most N; a clock that advances one second per
reading turns a seconds budget into a count of checks, so the phase a refusal names is
the phase under way after that many checks.
"""

from __future__ import annotations

import re

import pytest

from hg_marl.agents.headroom import headroom
from hg_marl.agents.models import Budget, OverBudget
from hg_marl.agents.models.layouts import CHECK_EVERY
from hg_marl.agents.oracle import oracle_rate


def counting_clock() -> tuple[Budget, list[int]]:
    ticks = [0]

    def clock() -> float:
        ticks[0] += 1
        return float(ticks[0])

    return Budget(seconds=1e7, clock=clock), ticks


def explored(message: str) -> tuple[int, int]:
    found = re.search(r"\(([\d,]+) states explored \(([\d,]+) known\)\)", message)
    assert found, message
    return int(found[1].replace(",", "")), int(found[2].replace(",", ""))


@pytest.mark.parametrize("limit", [8_000, 20_000])
def test_a_states_budget_stops_the_exploration_having_explored_at_most_that_many(limit: int) -> None:
    with pytest.raises(OverBudget) as refused:
        oracle_rate("roboergosum", "lazy", max_states=limit)
    message = str(refused.value)
    assert "\n" not in message and f"max_states={limit:,}" in message and "in phase 'explore'" in message
    done, known = explored(message)
    assert done <= limit < known


def test_the_layouts_are_refused_before_their_enumeration_when_they_alone_exceed_the_states_budget() -> None:
    budget = Budget(states=5_000)
    with pytest.raises(OverBudget, match=r"in phase 'layouts' \(0 of 5,040 initial layouts\)"):
        oracle_rate("roboergosum", "lazy", budget=budget)
    assert budget.checks == 0  # refused from the count, nothing enumerated


def test_the_layout_enumeration_reads_the_clock_every_so_many_deals() -> None:
    # generated:objects=8,bins=2 against lazy (no symmetry): 1,814,400 deals to enumerate
    budget, _ = counting_clock()
    budget.seconds, budget.states = 10.0, 10**7  # ten readings; the deals within the states budget
    with pytest.raises(OverBudget) as refused:
        oracle_rate("generated:objects=8,bins=2", "lazy", budget=budget)
    message = str(refused.value)
    assert "in phase 'layouts'" in message and "of wall time" in message
    done = int(re.search(r"\(([\d,]+) of 1,814,400 layouts\)", message)[1].replace(",", ""))  # type: ignore[index]
    assert done == 10 * CHECK_EVERY  # readings at deals 0, 1024, ...: the 11th (11 s spent) refuses


def test_a_slow_partner_is_checked_between_its_answers() -> None:
    # cooperative plans with a search per answer: the clock must be read between answers,
    # so a budget of a few readings refuses after a few answers, in the first-answers phase
    budget, _ = counting_clock()
    budget.seconds = 5.0
    with pytest.raises(OverBudget, match=r"in phase 'first answers' \((0|4|8|12|16) of \d+ partner answers"):
        oracle_rate("roboergosum", "cooperative", budget=budget)


def test_every_phase_reads_the_budget_and_the_last_is_the_solve() -> None:
    budget = Budget(None, None, None)
    oracle_rate("paper2015", "lazy", budget=budget)
    assert budget.phase == "solve" and budget.checks > 3


def test_the_headroom_model_refuses_in_its_phase_with_one_line() -> None:
    with pytest.raises(OverBudget) as refused:
        headroom("roboergosum", [("lazy", "lazy")], max_states=3_000)
    message = str(refused.value)
    assert "\n" not in message and "headroom model of 'roboergosum'" in message and "phase 'layouts'" in message
