"""Values that round 126's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from hg_marl.core import ScenarioError, World, load_scenario
from hg_marl.core.scenario_generated import generate_scenario
from tests.core.test_scenario_validation import paper_text, write

# --- hg_marl/core/scenario_file.py ---


def test_a_layout_short_of_an_object_says_how_many_objects_it_expected(tmp_path: Path) -> None:
    # paper2015 with a fourth object: its two layout groups still place 2 + 1 = 3 objects, and the
    # file has 4 objects, so the counts add up to 3 where 4 (one per object) were expected. The
    # number of groups (2) is not what the message promises.
    text = paper_text().replace("[[bins]]", '[[objects]]\nname = "tape4"\n\n[[bins]]', 1)
    with pytest.raises(ScenarioError, match=re.escape("counts add up to 3, expected 4 (one per object)")):
        load_scenario(write(tmp_path, text))


# --- hg_marl/core/scenario_generated.py ---


@pytest.mark.parametrize("locations", [2, 3, 5])
def test_a_generated_scenarios_robot_starts_at_location_0_next_to_the_human(locations: int) -> None:
    # The generator's docstring: "location 0 is next to the human" (the handover location);
    # the robot starts there, whatever the number of locations.
    scenario = generate_scenario(objects=3, locations=locations, seed=7)
    assert scenario.robot_start == (0,)
    world = World(scenario)
    rng = np.random.default_rng(0)
    assert {world.initial_state(rng).robot_at for _ in range(5)} == {0}
