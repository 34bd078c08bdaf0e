"""Values that round 161's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.agents.models import OverBudget
from hg_marl.agents.models.forked import Forked, check_jobs
from tests.agents.test_budget import counting_clock


def test_a_wall_time_refusal_gives_the_seconds_spent_to_a_tenth() -> None:
    # The counting clock reads 1 at the budget's start and one more at each check: the first check
    # has spent 1 s, the second 2 s, the third 3 s > 2.5 s and refuses. The message states the budget
    # with 'g' (2.5) and the seconds spent to a tenth of a second: "(after 3.0 s)", not "(after 3 s)".
    budget, _ = counting_clock()
    budget.seconds, budget.memory, budget.states = 2.5, None, None
    budget.check("explore", 1, memory=False)
    budget.check("explore", 2, memory=False)
    with pytest.raises(OverBudget) as refused:
        budget.check("explore", 3, memory=False)
    assert str(refused.value) == (
        "the computation is over its budget of 2.5 s of wall time (after 3.0 s) in phase 'explore' "
        "(3 states); raise --max-seconds or raise the budget or use a smaller scenario"
    )


def test_a_bad_jobs_count_names_the_parameter_jobs_unless_the_caller_names_an_option() -> None:
    # A library caller (Forked, check_jobs without an option) passed the parameter `jobs`, not a
    # command's `--jobs`: the whole message begins with "jobs". The command names its option itself.
    with pytest.raises(ValueError) as refused:
        Forked(lambda i: i, jobs=-1)
    assert str(refused.value) == "jobs must be a whole number from 0 (one per CPU) to 256, got -1"
    with pytest.raises(ValueError) as refused:
        check_jobs(257)
    assert str(refused.value) == "jobs must be a whole number from 0 (one per CPU) to 256, got 257"
    with pytest.raises(ValueError) as refused:
        check_jobs(-1, "--jobs")
    assert str(refused.value).startswith("--jobs must be a whole number")
