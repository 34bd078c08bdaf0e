"""Values that round 165's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.humans.cooperative import CooperativeHuman
from hg_marl.agents.humans.family_out import Forgetful
from hg_marl.agents.humans.lazy import LazyHuman
from hg_marl.agents.humans.replay import ReplayHuman
from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.core import Agent, Kind, State, World
from hg_marl.training.population_gen import _spot_shared, event_of
from tests.agents.test_pinned_family_out_gate import _offer
from tests.agents.test_pinned_human_cooperative_gate import answer, planned
from tests.agents.test_pinned_human_lazy_gate import named
from tests.agents.test_pinned_human_replay_gate import start, write_trace

PAPER = World("paper2015")


def test_the_forgetful_partner_empty_handed_takes_what_the_robot_offers() -> None:
    # fo_forgetful is "otherwise helpful" (takes offers, tidies its own area): with nothing in its
    # hand there is nothing to forget, so when the robot offers tape1 at a handover place it takes it.
    state = _offer(PAPER, 0)
    assert state.where.count(PAPER.table.hand[Agent.HUMAN]) == 0  # the human holds nothing
    take = PAPER.table.action_index(Agent.HUMAN, Kind.TAKE, 0)
    assert PAPER.table.feasible(state, Agent.HUMAN, take)
    human = Forgetful(hold=30.0)
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    assert human.choose(SimpleNamespace(clock=0.0, world=PAPER, state=state)) == take
    assert human.choose(SimpleNamespace(clock=500.0, world=PAPER, state=state)) == take


def test_the_cooperative_human_plans_with_the_planner_config_it_is_given() -> None:
    # Holding tape3 with the robot at human_side: a cold default planner hands it over. A planner
    # allowed to expand a single node finds no plan (the intent fails), so a cooperative human
    # built with that config has no planned move and waits; its planner carries the budget given.
    state = State((0, 1, 8), 3)
    assert planned(PAPER, state, None) == "give(tape3)"
    tiny = PlannerConfig(node_budget=1)
    cold = Planner(PAPER, config=replace(tiny, cache_suffixes=False), human_model=None)
    assert not cold.intent(state, to_move=Agent.HUMAN, robot_action=None).success
    assert answer(CooperativeHuman(), PAPER, state) == "give(tape3)"
    human = CooperativeHuman(planner_config=tiny)
    assert answer(human, PAPER, state) == "wait"
    assert human.planner(PAPER).config.node_budget == 1
    assert human.planner(PAPER).config.cache_suffixes is False


@pytest.mark.parametrize("p_idle", [0.25, 0.04, 0.66])
def test_the_lazy_human_idles_with_exactly_its_p_idle(p_idle: float) -> None:
    # tape1 on human_mat_1 with mat_shared free: the lazy human picks it with 1 - p_idle and waits
    # with p_idle (0.25: 0.75 and 0.25; 0.04: 0.96 and 0.04; 0.66: 0.34 and 0.66), not a rounded one.
    dist = dict(named(LazyHuman(p_idle=p_idle).distribution(PAPER, State((4, 0, 1), 0))))
    assert dist.keys() == {"pick(tape1)", "wait"}
    assert dist["wait"] == pytest.approx(p_idle, abs=1e-12)
    assert dist["pick(tape1)"] == pytest.approx(1.0 - p_idle, abs=1e-12)


def test_a_trace_refused_in_another_scenario_names_its_recorded_scenario(tmp_path: Path) -> None:
    # The gate's trace is recorded in the human's seat of paper2015. Reset in asymmetric_advantages
    # (other human actions), the refusal names the recorded scenario first, then the live one.
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"))
    expected = (
        "episode 0 was recorded in scenario 'paper2015' as 'human'; "
        "its actions do not match 'asymmetric_advantages' as 'human'"
    )
    with pytest.raises(ValueError, match=re.escape(expected)):
        start(human, World("asymmetric_advantages"))


def test_a_place_onto_a_spot_only_the_human_reaches_is_place_keep() -> None:
    # paper2015's spots: mat_left, mat_centre, mat_right (robot only), mat_shared (both) and
    # human_mat_1, human_mat_2 (human only). "place_shared" is a place onto a spot the robot reaches.
    shared = _spot_shared("paper2015")
    expected = {n: True for n in ("mat_left", "mat_centre", "mat_right", "mat_shared")}
    expected |= {"human_mat_1": False, "human_mat_2": False}
    assert shared == expected
    assert event_of("place(tape1,mat_shared)", shared) == "place_shared"
    assert event_of("place(tape2,human_mat_1)", shared) == "place_keep"
    assert event_of("place(tape3,human_mat_2)", shared) == "place_keep"
