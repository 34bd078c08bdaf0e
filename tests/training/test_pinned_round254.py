"""Values that round 254's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.trace import read_trace
from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman
from hg_marl.agents.robots.base import make_planner
from hg_marl.core import Agent, Kind, World
from hg_marl.core.errors import ModelFileError
from tests.agents.test_pinned_trace_gate import header, step, write


def test_the_goal_directed_expert_plans_against_the_human_model_it_is_given() -> None:
    # forced_coordination (its file says so): every tape starts where only the human reaches, the
    # one bin is where only the robot reaches, and a tape crosses either by a handover at `pass` or
    # by the human placing it on the counter. A cooperative human may use the counter; a human
    # who never places can only hand over, so the expert built with that model must plan a
    # handover for each of the three tapes.
    world = World("forced_coordination")
    state = world.initial_state(np.random.default_rng(0))
    assert "human_places" in _methods(make_planner(world).plan(state))
    no_place = RestrictedHuman("no_place", HUMAN_KINDS - {Kind.PLACE})
    assert _methods(make_planner(world, None, no_place).plan(state)) == ["handover_h2r"] * 3


def _methods(result: Any) -> list[str]:
    """Per tape, the method the plan disposes of it by."""
    assert result.success
    return [
        method
        for _, method in sorted({s.obj: s.method for s in result.plan.streams[Agent.HUMAN] if s.obj >= 0}.items())
    ]


@pytest.mark.parametrize("key", ["player", "robot", "started", "front_end"])
def test_each_meta_field_of_a_recorded_person_must_be_a_text(tmp_path: Path, key: str) -> None:
    # The module docstring: a recording of a person adds who played, when, the front end and the
    # robot's spec in the header's meta, all texts. The same header with the field as a text is
    # read; with a number instead it is refused, naming the field.
    (episode,) = read_trace(write(tmp_path, header(meta={key: "x"}), step()))
    assert episode.header["meta"] == {key: "x"}
    with pytest.raises(ModelFileError, match=f"field 'meta.{key}': expected a string"):
        read_trace(write(tmp_path, header(meta={key: 3}), step()))
