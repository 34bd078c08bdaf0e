"""Values that round 200's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import re

import pytest

from hg_marl.core import Agent
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario import load_scenario
from hg_marl.envs.table_cleaning import raw_env
from tests.training.test_pinned_round80 import _clean_state


@pytest.mark.parametrize(
    ("spec", "problem"),
    [
        ("generated:objects", ": expected key=value, got 'objects'"),
        ("generated:seed=1,seed=2", ": parameter 'seed' given twice"),
    ],
)
def test_a_malformed_generated_spec_is_refused_naming_the_generated_scenario(spec: str, problem: str) -> None:
    # Before any parameter is bound, the spec's own syntax is read (hg_marl.core.spec.parse_spec,
    # whose messages start with what the caller calls the spec, then the spec as typed, quoted): a
    # parameter without '=' and a key given twice. The loader calls it a "generated scenario", as
    # it does a bad parameter's value, so the message starts with those words, not "scenario".
    with pytest.raises(ScenarioError, match="^" + re.escape(f"generated scenario {spec!r}{problem}")):
        load_scenario(spec)


def test_a_turn_reports_the_tasks_solved_not_the_cycles_played() -> None:
    # Episodic paper2015 from the clean table: the robot's first action, its wait, completes the
    # task (tasks solved 1) before any cycle has closed (the human has not moved: 0 cycles). The
    # human's turn then says 1 task solved, as the env's own counter and the robot's info say.
    env = raw_env("paper2015", continuing=False)
    env.reset(seed=0, options={"state": _clean_state(env.world)})
    env.step(env.world.table.wait[Agent.ROBOT])
    assert (env.tasks_solved, env.cycles) == (1, 0)
    turn = env.turn("human")
    assert turn.tasks_solved == 1
    assert turn.reward == 1.0
