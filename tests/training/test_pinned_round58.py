"""Round 58's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.planner import Planner, PlannerConfig, PlanResult
from hg_marl.core import World

PAPER = World("paper2015")


# --- agents/planner/halfstep.py ---


def test_a_node_budget_caps_the_robot_nodes_expanded_and_exactly_the_needed_count_suffices() -> None:
    # PlannerConfig.node_budget's docstring: "Maximum nodes expanded per call; beyond it the
    # call fails with reason 'budget'", and halfstep's docstring counts the nodes and the
    # budget over the same robot nodes. So, with N the nodes a search with room to spare
    # expands (property, no hand-worked number): a budget of N finds the same plan, and a
    # budget of N - 1 fails with reason 'budget' after exactly N - 1 nodes, never more.
    state = PAPER.initial_state(np.random.default_rng(3))

    def plan(budget: int) -> PlanResult:
        return Planner(PAPER, PlannerConfig(node_budget=budget, cache_size=0)).plan(state)

    free = plan(200_000)
    assert free.success
    needed = free.nodes
    assert needed > 1
    enough = plan(needed)
    assert enough.success
    assert enough.cost == free.cost
    short = plan(needed - 1)
    assert not short.success
    assert short.reason.startswith("budget")
    assert short.nodes == needed - 1
    assert f"node budget of {needed - 1} exhausted ({needed - 1} nodes)" in short.reason
