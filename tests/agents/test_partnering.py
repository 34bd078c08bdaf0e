"""The planning robots' partnering: the bounded planner cache and the replan after a failed plan.

Expected values are stated from the docstrings' rules: at most ``MAX_PLANNERS`` planners,
the oldest dropped first; a failed plan with blocked actions forgets the blocks, and the
planner is then the one for the unblocked model.
"""

from __future__ import annotations

from hg_marl.agents.planner.models import cooperative
from hg_marl.agents.robots.partnering import MAX_PLANNERS, Partnering, planner_in
from hg_marl.core import Agent, Kind, World


def test_the_planner_cache_holds_at_most_max_planners_and_drops_the_oldest_first() -> None:
    planners: dict[str, str] = {}
    made: list[str] = []

    def make(model: str) -> str:
        made.append(model)
        return f"planner of {model}"

    assert MAX_PLANNERS == 8
    for i in range(MAX_PLANNERS + 1):  # nine distinct models
        assert planner_in(planners, f"m{i}", make) == f"planner of m{i}"
    assert list(planners) == [f"m{i}" for i in range(1, 9)]  # eight kept: m0, the oldest, dropped
    assert planner_in(planners, "m5", make) == "planner of m5" and len(made) == 9  # a kept one is not remade
    assert planner_in(planners, "m0", make) == "planner of m0" and len(made) == 10  # the dropped one is
    assert list(planners) == [f"m{i}" for i in range(2, 9)] + ["m0"]


def test_a_failed_plan_with_blocks_forgets_them_and_plans_with_the_unblocked_model() -> None:
    world = World("paper2015")
    partnering = Partnering(world, None, None, partner_aware=False)
    unblocked = partnering.model
    assert unblocked == cooperative()
    acts = world.actions(Agent.HUMAN)
    take = next(a for a in acts if a.kind is Kind.TAKE)
    partnering.monitor.blocked = frozenset({take})  # as after refusals of an expected take
    partnering.planned(True)  # a success changes nothing
    assert partnering.model == unblocked
    # the model the monitor implies now differs: take it, as ``observe`` does
    blocked_model = partnering.monitor.model(partnering.base)
    assert blocked_model != unblocked
    partnering.planner = partnering._planner_for(blocked_model)
    blocked_planner = partnering.planner
    partnering.planned(False)  # no plan with the blocks: they are forgotten
    assert not partnering.monitor.blocked
    assert partnering.model == unblocked and partnering.model is not blocked_model
    assert partnering.planner is partnering._planners[unblocked] and partnering.planner is not blocked_planner
