"""An object may go into any bin that accepts it: a second, human-reachable bin is used."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.planner import Planner
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.scenarios import __file__ as scenarios_init

PAPER = Path(scenarios_init).with_name("paper2015.toml").read_text()
HUMAN_BIN = '\n[[bins]]\nname = "human_bin"\nhuman_reach = true\n'


@pytest.fixture(scope="module")
def two_bins(tmp_path_factory: pytest.TempPathFactory) -> World:
    """paper2015 plus a bin for uncoloured objects that only the human reaches."""
    path = tmp_path_factory.mktemp("scenarios") / "two_bins.toml"
    path.write_text(PAPER.replace('name = "paper2015"', 'name = "two_bins"') + HUMAN_BIN)
    return World(str(path))


def test_human_throws_into_the_bin_it_reaches(two_bins: World) -> None:
    world = two_bins
    assert world.bins_of == ((0, 1), (0, 1), (0, 1))
    human_hand = world.hand[Agent.HUMAN]
    state = State((human_hand, 0, 1), 0)
    throw = world.index(Agent.HUMAN, world.actions(Agent.HUMAN)[world.table.action_index(1, Kind.THROW, 0)])
    out = world.step(state, Agent.HUMAN, throw)
    assert out.ok
    assert out.state.where[0] == world.n_spots + 1  # human_bin, the only bin the human reaches
    assert world.place_name(out.state.where[0]) == "human_bin"


def test_a_table_with_objects_in_either_bin_is_clean(two_bins: World) -> None:
    m = two_bins.n_spots
    state = State((m, m + 1, m), 0)
    assert two_bins.is_clean(state)
    wait = two_bins.n_actions(Agent.ROBOT) - 1
    assert two_bins.step(state, Agent.ROBOT, wait).reward == 1.0


def test_planner_lets_the_human_dispose_of_its_tape(two_bins: World) -> None:
    """With its own bin, the human throws the tape on its side away itself: no handover,
    no placing, and the plan is cheaper than on paper2015 from the same table."""
    paper = World("paper2015")
    for seed in range(3):
        state = paper.initial_state(np.random.default_rng(seed))
        one, two = Planner(paper).plan(state), Planner(two_bins).plan(state)
        assert one.success and two.success
        assert two.cost < one.cost
        human_kinds = {two_bins.actions(Agent.HUMAN)[s.action].kind for s in two.plan.streams[Agent.HUMAN]}
        assert Kind.THROW in human_kinds
        assert not human_kinds & {Kind.GIVE, Kind.TAKE, Kind.PLACE}


def test_oracle_is_faster_with_the_second_bin(two_bins: World) -> None:
    one = oracle_rate("paper2015", "no_handover")
    two = oracle_rate(two_bins, "no_handover")
    assert two.rate_per_hour > one.rate_per_hour
