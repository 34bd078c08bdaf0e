"""Round 57's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

import pytest

from hg_marl.agents.humans.family_out import Forgetful
from hg_marl.training.aggregate import MIN_CI_SEEDS, ci_flag

# --- training/aggregate.py ---


def test_one_seed_per_task_is_flagged_as_no_interval_at_all() -> None:
    # The rule (aggregate.py's docstring of ci_flag and the stratified bootstrap): with one
    # seed per task every resample of a task is that one run, so no interval exists; this is
    # a different caution from "few seeds" (2 .. MIN_CI_SEEDS - 1), whose intervals exist but
    # are coarse. So 1 seed reads "1 seed per task: no confidence interval ...", and the
    # "only N seeds" wording starts at 2 (both worked by hand from the rule, not the code).
    assert MIN_CI_SEEDS > 2
    one = ci_flag(1)
    assert one.startswith("1 seed per task")
    assert "no confidence interval" in one
    assert "only" not in one
    two = ci_flag(2)
    assert two.startswith("only 2 seeds per task")
    assert ci_flag(MIN_CI_SEEDS) == ""


# --- agents/humans/family_out.py ---


def test_a_forgetful_human_with_no_hold_time_is_accepted_and_a_negative_one_refused() -> None:
    # Forgetful's docstring and message: ``hold`` is "finite seconds >= 0" (0: an object is
    # never forgotten in the hand), so 0 is a valid input and only below 0 (or not finite)
    # is refused.
    human = Forgetful(hold=0.0)
    assert human.hold == 0.0
    with pytest.raises(ValueError, match="hold must be finite seconds >= 0"):
        Forgetful(hold=-1.0)
    with pytest.raises(ValueError, match="hold must be finite seconds >= 0"):
        Forgetful(hold=float("inf"))
