"""Values that round 252's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math

from hg_marl.agents.planner.exactsum import ExactSums
from hg_marl.training.limits import MAX_RUNS, check_runs


def test_check_runs_hands_back_the_number_of_runs_it_checked() -> None:
    # 2 robots x 3 humans x 1 scenario x 2 seeds = 12 runs, far under MAX_RUNS: accepted and
    # returned as given (the gate tests only asked at the limit itself, where both are MAX_RUNS).
    assert MAX_RUNS > 12
    assert check_runs(2 * 3 * 1 * 2, "robots x humans x scenarios x seeds") == 12
    assert check_runs(1, "sweep") == 1


def test_exact_sums_scale_and_width_cover_the_offer_tables_too() -> None:
    # One weight, one robot location, one object, one status: tables[k][at][o][status].
    # The plain table holds 1.0 and the offer table 8.0. By hand: fsum of one object's value is
    # the value itself, so the plain sum is (1.0,) and the offer sum (8.0,). Packed with the
    # plain table's scale alone (2**-52 for 1.0), 8.0 would be 2**55, past the field's 54 bits
    # and onto the dead-end flag, and the offer sum would read as a dead end (None).
    sums = ExactSums([[[[1.0]]]], [[[[8.0]]]], n_objects=1)
    assert sums.packed is not None
    assert sums.sums(False, 0, [0]) == (math.fsum([1.0]),)
    assert sums.sums(True, 0, [0]) == (math.fsum([8.0]),)
    # two objects, offer values 8.0 and 0.75: their fsum, 8.75, exactly
    two = ExactSums([[[[1.0], [1.0]]]], [[[[8.0], [0.75]]]], n_objects=2)
    assert two.sums(True, 0, [0, 0]) == (math.fsum([8.0, 0.75]),) == (8.75,)
