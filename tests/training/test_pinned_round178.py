"""Values that round 178's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.array_partners import LiveRobots
from hg_marl.agents.models.layouts import canonical_layouts
from hg_marl.core import World
from hg_marl.core.batch import BatchState
from hg_marl.core.scenario import Bin
from hg_marl.training.baselines import heldout_curve
from hg_marl.training.baselines.heldout_curve import HeldOutCurve
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig
from tests.env.test_pinned_array_partners_gate import _Recording

# --- training/baselines/heldout_curve.py ---


def test_each_partner_is_scored_on_the_configs_eval_envs_tables(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # heldout_curve.py: each partner, train and held-out alike, is played on ``eval_envs`` fresh
    # tables (one env per partner, the members recipe of that partner alone). The env builder is
    # stubbed (no network): it records the partner and the table count it is asked for.
    made: list[tuple[tuple[str, ...], str, int]] = []

    def make_env(config: RecurrentConfig, n: int) -> None:
        made.append((config.humans, config.recipe, n))

    monkeypatch.setattr(heldout_curve, "make_env", make_env)
    config = RecurrentConfig(humans=("cooperative",), scenario="paper2015", out=tmp_path, eval_envs=3).check()
    HeldOutCurve(config, ("lazy",), every=100, oracle=False)
    assert made == [(("cooperative",), "members", 3), (("lazy",), "members", 3)]


# --- agents/models/layouts.py ---


def test_canonical_layouts_deplete_each_class_group_by_group() -> None:
    # paper2015 with two bin classes: tapes 1 and 2 go in a red bin, tape 3 in a blue one (same
    # reach as the trashbin), so the classes are A = {tape1, tape2} and B = {tape3}. The layout
    # deals 2 objects on 2 of the spots (0, 1, 2), then 1 on one of (4, 5). Worked by hand: the
    # 36 deals (3 subsets for the first group x 6 ordered spot pairs x 2 spots for the last) are
    # equally likely, 1/36 each, and each has one twin with the two A tapes swapped (they never
    # share a place): 18 canonical layouts of 1/18 each. The second group deals from what the
    # first left: after {A, A} only B (3 x 2 = 6 layouts), after {A, B} only A (6 x 2 = 12).
    base = World("paper2015").scenario
    trash = base.bins[0]
    scenario = dataclasses.replace(
        base,
        object_colours=("red", "red", "blue"),
        bins=(Bin("red", trash.reach, "red"), Bin("blue", trash.reach, "blue")),
    )
    world = World(scenario)
    assert len(set(world.bins_of)) == 2
    layouts = canonical_layouts(world)
    assert len(layouts) == 18
    assert all(math.isclose(p, 1.0 / 18.0) for _, p in layouts)
    last = [s.where for s, _ in layouts if s.where[2] in (4, 5)]  # B dealt by the last group
    assert len(last) == 6


# --- agents/array_partners.py ---


def test_live_robots_of_some_tables_see_their_own_tables_tasks_and_clock() -> None:
    # A batch of tables 2 and 0 (in that order) of three: table 2's robot sees table 2's clock
    # and tasks solved (30 s, 3 tasks), table 0's its own (10 s, 1 task), not the batch's first
    # and second tables'.
    world = World("paper2015")
    robots = [_Recording(), _Recording(), _Recording()]
    live = LiveRobots(world, robots, 3)
    live.reset_rows(np.arange(3), np.random.default_rng(0))
    live.follow(np.array([10.0, 20.0, 30.0]), np.array([1, 2, 3], dtype=np.int64))
    state = world.initial_state(np.random.default_rng(0))
    one = BatchState.of([state, state])
    batch = BatchState(one.where, one.robot_at, one.offer_by, one.offer_obj, np.array([2, 0]))
    live.act(batch, np.full(2, -1), np.random.default_rng(0))
    assert [r.seen for r in robots] == [[(10.0, 1)], [], [(30.0, 3)]]
