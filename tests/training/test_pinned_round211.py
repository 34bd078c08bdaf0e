"""Values that round 211's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents import compiled
from hg_marl.agents.compiled import cache_key, compile_human
from hg_marl.agents.planner.domain import Domain, handover_r2h
from hg_marl.agents.planner.halfstep import astar
from hg_marl.agents.planner.models import RestrictedHuman, cooperative
from hg_marl.agents.planner.space import Space
from hg_marl.core import Agent, State, World
from hg_marl.training.study import Actor, Study
from tests.agents.test_pinned_planner_expectimax_gate import CONFIG


def test_a_half_step_search_that_explores_and_finds_nothing_says_no_plan() -> None:
    # roboergosum with objects 0-2 in bin 0 and objects 3-5 (bin 1, in the human's reach) on
    # spots, in a domain whose only method is the robot handing over to the human: every object
    # has a method at the root (finite bound), but once the human has taken an object no method
    # goes on from the human's hand, so every path is a dead end. The search expands states and
    # finds no plan: the reason is "no plan" ("unreachable" is for a root the bound already rules
    # out, with nothing expanded).
    world = World("roboergosum")
    root = State((7, 7, 7, 0, 3, 2), 0, -1, -1)
    space = Space(Domain(world, cooperative(), (("handover_r2h", handover_r2h),)), CONFIG.weights)
    out = astar(space, root, Agent.ROBOT, (0.0, -1), 10**6)
    assert out.cycles is None and out.nodes > 0
    assert out.reason == "no plan"


def test_a_p_idle_of_one_is_refused_with_the_half_open_range_in_the_message() -> None:
    # p_idle must lie in [0, 1): 1 is refused (a human idling for sure), and the message
    # writes the range as it is, with its open end: "[0, 1)".
    with pytest.raises(ValueError, match=re.escape("idler: p_idle must be in [0, 1), got 1.0")):
        RestrictedHuman("idler", p_idle=1.0)


def test_a_narrowed_study_keeps_only_the_validation_partners_it_kept() -> None:
    # Two partners: "coop" a train partner, "lazy-v" a validation one (a population member of
    # the validation split). Narrowed to "coop", the study has no validation partner left, so
    # "lazy-v" is in no group; narrowed to "lazy-v" it keeps that one validation partner.
    study = Study(
        name="s",
        path=Path("s.toml"),
        robots=(Actor("planner", {}, "planner"),),
        humans=(Actor("cooperative", {}, "coop"), Actor("lazy", {}, "lazy-v")),
        scenarios=("paper2015",),
        seeds=(0,),
        duration=100.0,
        train=("coop",),
        validation=("lazy-v",),
    )
    only_coop = study.narrowed(humans=["coop"])
    assert (only_coop.train, only_coop.validation) == (("coop",), ())
    assert only_coop.group("lazy-v") == ""
    only_lazy = study.narrowed(humans=["lazy-v"])
    assert (only_lazy.train, only_lazy.validation) == ((), ("lazy-v",))


def test_a_whole_cached_table_under_another_content_key_is_rebuilt_not_loaded(tmp_path: Path) -> None:
    # A complete entry (every array present) at the table's file name but stamped with another
    # content key, holding another human's answers (the cooperative human's), is foreign: it is
    # rebuilt, so the answers are the lazy human's again and the file is rewritten with its key.
    world = World("generated:objects=1,seed=0")
    first = compile_human(world, "lazy", cache=tmp_path)
    (entry,) = tmp_path.glob("*.npz")
    other = compile_human(world, "cooperative", cache=None)
    foreign = {k: getattr(other, k) for k in ("keys", "starts", "actions", "cum")} | other.outcome
    compiled.save_table(entry, "0" * 64, foreign)
    again = compile_human(world, "lazy", cache=tmp_path)
    assert np.array_equal(again.keys, first.keys) and np.array_equal(again.actions, first.actions)
    assert np.array_equal(again.cum, first.cum)
    with np.load(entry, allow_pickle=False) as data:
        assert str(data["key"]) == cache_key(world, "lazy")
