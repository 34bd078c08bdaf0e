"""The expectimax planner's node budget and its dead ends, pinned for the mutation gate.

- The budget counts the states expanded: a search that would need more stops with exactly
  ``budget`` nodes and the reason ``"budget"``, and a budget equal to the states the full
  search expands is enough (the whole space is known once the last one is expanded).
  Worked on ``roboergosum`` with three of its six objects in their bins (a few hundred
  states, more than 256, so that a count compared by identity would differ).
- A dead end (a state where some object has no disposal method left, bound infinite)
  must not stop the value sweep. A property: a human whose only help leads into dead
  ends (in a domain declared without the methods that go on from the human's hand)
  never helps, so a planner that chooses the human's action within its set makes it
  wait; the expected cost is then the cost of the robot working alone next to a human
  who only waits, found by the deterministic search.
"""

from __future__ import annotations

import pytest

from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.agents.planner.domain import Domain, handover_r2h, robot_alone
from hg_marl.agents.planner.expectimax import expectimax
from hg_marl.agents.planner.models import RestrictedHuman, cooperative
from hg_marl.agents.planner.space import Space
from hg_marl.core import Agent, Kind, State, World

CONFIG = PlannerConfig()


def _search(world: World, model: RestrictedHuman, root: State, budget: int) -> tuple[int, float, str, bool]:
    space = Planner(world, human_model=model).space
    out = expectimax(space, root, Agent.ROBOT, (0.0, -1), budget, CONFIG.value_tolerance, CONFIG.max_sweeps)
    return out.nodes, out.cost, out.reason, out.cycles is not None


def test_the_budget_stops_the_search_at_exactly_that_many_states_and_the_full_count_is_enough() -> None:
    world = World("roboergosum")
    # objects 0-2 go into bin 0 (place 7 = n_spots + 0): three disposed of, three on spots
    root = State((7, 7, 7, 0, 3, 2), 0, -1, -1)
    model = cooperative(p_idle=0.3)
    full, cost, _, ok = _search(world, model, root, 10**6)
    assert ok and full > 300
    assert _search(world, model, root, 300) == (300, float("inf"), "budget", False)
    assert _search(world, model, root, full) == (full, cost, "", True)


def test_a_human_whose_takes_lead_to_dead_ends_costs_what_a_human_who_only_waits_does() -> None:
    """``roboergosum`` with objects 0-2 in bin 0 and objects 3-5 (bin 1, in the human's reach)
    on spots, in a domain of two methods: the robot alone, and the robot handing over to
    the human. The human (idling half the time) may take what the robot offers, but no
    method goes on from the human's hand, so each take is a dead end and the human's best
    choice is to wait: the expected cost is the robot working alone next to a human who
    only waits, as the deterministic search finds it in the full domain. With these
    layouts the dead ends come early in the search's order."""
    world = World("roboergosum")
    root = State((7, 7, 7, 0, 3, 2), 0, -1, -1)
    methods = (("robot_alone", robot_alone), ("handover_r2h", handover_r2h))
    space = Space(Domain(world, cooperative(p_idle=0.5), methods), CONFIG.weights)
    out = expectimax(space, root, Agent.ROBOT, (0.0, -1), 10**6, CONFIG.value_tolerance, CONFIG.max_sweeps)
    alone = Planner(world, human_model=RestrictedHuman("waits", frozenset({Kind.WAIT}))).plan(root)
    assert alone.success and out.cycles is not None
    assert out.cost == pytest.approx(alone.cost, rel=1e-9)


@pytest.mark.parametrize(("tolerance", "reason"), [(0.0, "no plan"), (-1e-9, "budget")])
def test_a_tolerance_no_sweep_can_meet_gives_up_after_the_last_sweep(tolerance: float, reason: str) -> None:
    """``paper2015`` with tape3 on human_mat_1 (out of the robot's reach) and a human who only
    waits: every state is a dead end, so no value moves. A tolerance of 0 is met by the first
    sweep (no plan exists); a negative one is never met (a move is never below 0), so the
    search gives up after ``max_sweeps`` with the reason ``"budget"``, as documented."""
    world = World("paper2015")
    root = State((0, 2, 4), 1, -1, -1)
    space = Planner(world, human_model=RestrictedHuman("waits", frozenset({Kind.WAIT}), 0.5)).space
    out = expectimax(space, root, Agent.ROBOT, (0.0, -1), 10**6, tolerance, 3)
    assert (out.cycles, out.cost, out.reason) == (None, float("inf"), reason)
