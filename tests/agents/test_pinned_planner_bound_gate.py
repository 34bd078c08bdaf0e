"""The planner's bound with a short move (0.5 s), pinned for the mutation gate.

Worked by hand as in tests/agents/test_planner_hand.py (the one-tape scenario, robot
alone, the human waits: idle weight 0.05, so each cycle of d seconds costs 1.05 d), with
``goto = 0.5`` s: pick 2 s -> 2.1, goto(bin) 0.5 s -> 0.525, throw 2 s -> 2.1, the
completing wait 1 s -> 1.05. The handover is at the bin's side, so at the table only the
tape's own spot saves the empty-handed move. With nothing to wait for the relaxation is exact, also when
a saved empty-handed move is worth less than a second.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig
from hg_marl.core import Agent, State, World
from tests.agents.test_planner_hand import DURATIONS, ONE_TAPE


@pytest.mark.parametrize(
    ("where", "at", "action", "to_go"),
    [
        (2, 0, "throw(tape)", 2.1 + 1.05),
        (2, 1, "goto(bin)", 0.525 + 3.15),
        (0, 1, "pick(tape)", 2.1 + 3.675),
        (0, 0, "goto(tape)", 0.525 + 5.775),
    ],
)
def test_bound_is_the_exact_cost_to_go_with_a_half_second_move(
    tmp_path: Path, where: int, at: int, action: str, to_go: float
) -> None:
    path = tmp_path / "layout.toml"
    text = ONE_TAPE.replace('handover_locations = ["table"]', 'handover_locations = ["bin_side"]')
    path.write_text(text + DURATIONS.replace("goto = 3.0", "goto = 0.5"))
    planner = Planner(World(str(path)))
    assert planner.world.durations.goto == 0.5
    names = planner.world.action_names[Agent.ROBOT]
    edges = {names[edge.action]: edge.h for edge in planner.space.robot_edges(State((where,), at))}
    assert edges[action] == pytest.approx(to_go)


def test_the_humans_holding_weight_raises_the_bound_where_every_method_has_the_human_hold() -> None:
    # every term of the bound is a nonnegative weight times a nonnegative work, so the bound
    # cannot fall as the holding weight grows; it rises where some object can only be
    # disposed of by the human carrying it (paper2015: the objects out of the robot's reach)
    world = World("paper2015")
    light = Planner(world, PlannerConfig(weights=CostWeights(human_holding=0.0))).space
    heavy = Planner(world, PlannerConfig(weights=CostWeights(human_holding=1.0))).space
    rng = np.random.default_rng(0)
    rose = 0
    for _ in range(40):
        state = world.initial_state(rng)
        low, high = light.bound(state), heavy.bound(state)
        assert high >= low, state
        rose += high > low
    assert rose > 0


def test_each_memo_of_the_space_is_emptied_once_it_holds_more_than_its_limit(monkeypatch: pytest.MonkeyPatch) -> None:
    """With a limit of 3, a memo grows 1, 2, 3, 4 and the fifth entry finds it over the limit:
    emptied, it holds that entry alone (a cleared entry is computed again, to the same value)."""
    from hg_marl.agents.planner import space as module

    monkeypatch.setattr(module, "_CACHE_LIMIT", 3)
    world = World("paper2015")
    space = Planner(world).space
    where = world.initial_state(np.random.default_rng(0)).where
    states = [State(where, at) for at in range(len(world.scenario.robot_locations))]
    states += [State(where, 0, 0, 0)]  # the robot offering object 0
    assert len({space.key(s) for s in states}) == len(states) >= 5
    sizes = []
    for state in states[:5]:
        space._new_sums(state, space.key(state))
        sizes.append(len(space._sums))
    assert sizes == [1, 2, 3, 4, 1]
