"""Values that round 156's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.family_out import SlowStart, helpful
from hg_marl.agents.humans.replay import ReplayHuman
from hg_marl.core import Agent, World
from tests.agents.test_pinned_human_replay_gate import PAPER, start, write_trace


@pytest.mark.parametrize(("clock", "watches"), [(0.0, True), (90.0, True), (119.9, True), (120.0, False)])
def test_fo_slow_start_by_default_watches_for_120_s(clock: float, watches: bool) -> None:
    # docs/adaptation.md: "fo_slow_start | watches for 120 s, then helps". By default it waits on
    # [0, 120) and helps from 120 s on; at 90 s it still watches (a 60 s default would help there).
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    helping = helpful(world, state)
    assert helping != wait_index(world)  # the initial table has work to do
    for human in (SlowStart(), make_human("fo_slow_start")):
        assert isinstance(human, SlowStart)
        human.reset(world, Agent.HUMAN, np.random.default_rng(0))
        action = human.choose(SimpleNamespace(clock=clock, world=world, state=state))
        assert action == (wait_index(world) if watches else helping)


def test_a_trace_refused_in_another_seat_names_the_seat_it_was_recorded_in(tmp_path: Path) -> None:
    # The gate's trace is recorded in the human's seat of paper2015 (its header says "seat": "human").
    # Reset in the robot's seat, the refusal names both: recorded as 'human', not matching as 'robot'.
    human = ReplayHuman(write_trace(tmp_path / "t.jsonl"))
    expected = (
        "episode 0 was recorded in scenario 'paper2015' as 'human'; its actions do not match 'paper2015' as 'robot'"
    )
    with pytest.raises(ValueError, match=re.escape(expected)):
        start(human, PAPER, Agent.ROBOT)
