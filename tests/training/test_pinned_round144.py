"""Values that round 144's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

import hg_marl
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario_file import parse_scenario
from hg_marl.core.scenario_generated import generate_scenario
from tests.env.test_env import nearly_done, play
from tests.training.test_pinned_round54 import _coloured

# --- hg_marl/core/scenario_file.py ---


def test_a_boolean_layout_count_is_refused_as_not_an_integer() -> None:
    # The reader is strict (its module docstring): a count is an int, and TOML's `true` is a
    # bool, which Python would take for 1. One red object, one colourless bin, one mat and a
    # layout group of `count = true`: read as 1 it would add up to the one object and load.
    data = _coloured([""])
    data["layout"][0]["count"] = True
    with pytest.raises(ScenarioError, match=r"field 'layout\[0\]\.count': expected int, got bool"):
        parse_scenario(data, "bool.toml", strict=True)
    data["layout"][0]["count"] = 1
    assert parse_scenario(data, "one.toml", strict=True).layout[0].count == 1


# --- hg_marl/core/scenario_model.py ---


def test_an_objects_bin_is_the_first_that_accepts_it_a_colourless_one_included() -> None:
    # Scenario.bin_of: "the index of the first bin that accepts its colour", and a colourless
    # bin "accepts objects of any colour" (Bin.colour). A red object with a colourless bin first
    # and a red one second goes to the first (index 0), not to the first of its own colour (1);
    # with the red bin first it goes to that one (0) as well.
    assert parse_scenario(_coloured(["", "red"]), "colourless_first.toml", strict=True).bin_of == (0,)
    assert parse_scenario(_coloured(["red", ""]), "red_first.toml", strict=True).bin_of == (0,)


# --- hg_marl/core/scenario_generated.py ---


def test_a_generated_bin_is_reachable_by_the_human_three_times_in_ten() -> None:
    # A generated bin is reached by the human with probability 0.3, as a robot-reachable spot
    # is. 16 bins (the bins limit) x 50 seeds = 800 bins: 240 expected, binomial sd
    # sqrt(800 x 0.3 x 0.7) = 13.0, so 190-290 is 3.8 sd either side; at probability 0.5 it
    # would be 400 (sd 14).
    reached = sum(bin_.reach.human for seed in range(50) for bin_ in generate_scenario(bins=16, seed=seed).bins)
    assert 190 <= reached <= 290, reached


# --- hg_marl/envs/table_cleaning.py ---


def test_the_ansi_render_shows_the_cycle_and_the_tasks_solved_each_in_its_place() -> None:
    # A continuing paper2015 table from nearly_done (tape1 and tape2 in the bin, tape3 in the
    # robot's hand at bin_side): cycle 1 the robot throws tape3 (the table is clean), cycle 2
    # it waits on the clean table (one task solved, the table is re-drawn), cycle 3 both wait;
    # the human waits throughout. Three cycles, one task: "cycle=3  tasks=1".
    env = hg_marl.env(render_mode="ansi", continuing=True)
    env.reset(seed=0, options={"state": nearly_done()})
    play(env, [("throw(tape3)", "wait"), ("wait", "wait"), ("wait", "wait")])
    first = env.render().splitlines()[0]
    assert first.startswith("TableCleaning-v0 [paper2015]")
    assert first.endswith("cycle=3  tasks=1"), first
