"""Values that round 188's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
from types import SimpleNamespace
from typing import Any

import numpy as np
import pandas as pd

from hg_marl.agents.model_limits import sb3_budget
from hg_marl.agents.vector_envs import seat_robot
from hg_marl.core import World
from hg_marl.core.batch import BatchState
from hg_marl.core.scenario_model import Bin, Reach
from hg_marl.training.baselines.recipes import CoveragePartner
from hg_marl.training.runner import summarise
from tests.training.test_pinned_round80 import _clean_state, _Table, _Waiting


def test_an_sb3_budget_with_a_dict_part_of_unknown_width_is_not_estimated() -> None:
    # A Dict observation is as wide as its parts together; one part of an unknown kind makes the
    # whole width unknown, so no budget is estimated (None), whatever the known part adds.
    header = {
        "algo": "PPO",
        "observation_space": {"type": "Dict", "spaces": {"a": {"type": "Box", "shape": [3]}, "b": {"type": "Odd"}}},
        "action_space": {"type": "Discrete", "n": 2},
        "policy_kwargs": {},
    }
    assert sb3_budget(header) is None


class _CountingRules:
    """The coverage partner's rules, counting the moves it steps (each agent's step of a cycle)."""

    def __init__(self, rules: Any) -> None:
        self.rules, self.steps = rules, 0

    def step(self, *args: Any) -> Any:
        self.steps += 1
        return self.rules.step(*args)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.rules, name)


def test_the_coverage_partner_plays_as_many_cycles_as_the_most_it_drew() -> None:
    # Eight tables reset together with cycles=3: each draws 0, 1 or 2 cycles of random moves, one
    # robot step and one human step a cycle, the tables moved together; so the partner steps
    # twice the largest draw. The draw is the first thing the seeded generator gives (the inner
    # partner, _Waiting, draws nothing), worked here from a generator of the same seed.
    world = World("paper2015")
    table = _Table(BatchState.of([_clean_state(world)] * 8))
    partner = CoveragePartner(world, _Waiting(world), cycles=3)
    counting = _CountingRules(partner.rules)
    partner.rules = counting
    partner.attach(table)
    drawn = np.random.default_rng(4).integers(3, size=8)
    assert drawn.max() == 2
    partner.reset_rows(np.arange(8), np.random.default_rng(4))
    assert counting.steps == 2 * 2


def test_a_run_with_one_human_turn_reports_its_one_expectation() -> None:
    # One decision row whose human acted as expected: the share of expected actions is 1/1 = 1.0,
    # not missing (None is kept for a run where no human action had an expectation).
    log = pd.DataFrame(
        {
            "reward": [0],
            "failed": [False],
            "time": [2.0],
            "expert": ["planner"],
            "weight_amplitude": [0.0],
            "human_as_expected": [True],
        }
    )
    assert summarise(log, 10.0)["human_as_expected"] == 1.0


def test_the_human_seats_live_robots_are_described_one_per_table() -> None:
    partner = SimpleNamespace(name="planner")
    assert seat_robot(partner) == "live robots (planner), one per table, as runs and studies play them"


def test_an_object_belongs_to_the_first_bin_that_accepts_it() -> None:
    # paper2015 with a second bin of no colour: both bins accept every tape, so each tape's
    # bins are (0, 1) and its bin is the first, the trashbin (0).
    base = World("paper2015").scenario
    box = Bin(name="box", reach=Reach(robot_from=frozenset({0}), human=True), colour="")
    world = World(dataclasses.replace(base, bins=(*base.bins, box)))
    assert world.bins_of == ((0, 1), (0, 1), (0, 1))
    assert world.bin_of == (0, 0, 0)
