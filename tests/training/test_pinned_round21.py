"""The value round 21's missed planted bug changed, pinned after the round.

Round 21 planted 14 bugs in fourteen older modules (runner, switching, population
generator, aggregation, report, store, sweep, stalls, hybrid and memory robots, family-out
partners, batched table, world, adaptation) after their documented promises had been
pinned (``tests/training/test_pinned_promises_c.py``, ``tests/agents/test_pinned_promises_d.py``);
13 were caught. The one missed: the hybrid robot explains each decision by the rule that
made it (``agents/robots/hybrid.py``): a move of the progress guard says ``no_progress``
(or ``patience``), a stall move of its own habit says ``partner_stalled``, whether or not
the partner monitor also reads the partner as stalled at that turn.
"""

from __future__ import annotations

from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.training.runner import RunConfig, run
from tests.agents.test_progress import REFUSER


def test_the_hybrids_reason_names_the_rule_that_made_the_move() -> None:
    log = run(
        make_robot("hybrid"), make_human(REFUSER), RunConfig(scenario="asymmetric_advantages", duration=900, seed=0)
    ).log
    experts = log["expert"].astype(str)
    reasons = log["reason"].astype(str)
    guard = experts == "guard"
    assert guard.sum() > 0 and (reasons == "partner_stalled").sum() > 0  # both rules fired
    assert set(reasons[guard]) <= {"no_progress", "patience"}
    assert set(experts[reasons == "partner_stalled"]) == {"habit"}
