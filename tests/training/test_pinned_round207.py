"""Values that round 207's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.core import ScenarioError, load_scenario
from hg_marl.core.errors import ConfigError
from hg_marl.core.registry import Entry, Param, Registry
from hg_marl.core.scenario_generated import generate_scenario
from tests.core.test_scenario_validation import line_containing, paper_text, write


class _Needs:
    """A thing with a required parameter (no default) beside one with a default."""

    name = "needs"

    def __init__(self, path: str, k: int = 2) -> None:
        self.path, self.k = path, k


def test_a_required_parameter_is_listed_with_the_default_none() -> None:
    # Param's own contract: "its default (the constructor's; None when required)". `path` has no
    # default, so it is listed as None, in the entry's params and in a listing with parameters.
    entry = Entry("needs", _Needs)
    assert entry.params == {"path": Param(None, ""), "k": Param(2, "")}
    listing = Registry("thing", ConfigError, [entry], list_params=True).listing()
    assert listing == "needs(path=None, k=2)"


def test_a_duplicate_name_is_reported_against_the_field_that_used_it_first(tmp_path: Path) -> None:
    # paper2015's objects are tape1, tape2, tape3: naming the second "tape1" is refused at the
    # second one's field, and the message names where the name was first used, the first object's
    # name field, objects[0].name (not only the list "objects").
    text = paper_text().replace('name = "tape2"', 'name = "tape1"', 1)
    path = write(tmp_path, text)
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    message = str(info.value)
    second = line_containing(text, 'name = "tape1"') + 3  # the second [[objects]]'s name, 3 lines below the first
    assert f"{path}:{second}" in message
    assert "'objects[1].name'" in message
    assert message.endswith("duplicate name 'tape1' (already used by objects[0].name)")


def test_a_generated_scenarios_objects_are_numbered_from_0_like_its_spots_bins_and_locations() -> None:
    # Every generated name carries its index, counted from 0: spot0.., bin0.., loc0.., and the
    # objects obj0.. (objects=3: obj0, obj1, obj2; the last is obj2, not obj3).
    sc = generate_scenario(objects=3, spots=4, locations=2, bins=2, seed=5)
    assert sc.objects == ("obj0", "obj1", "obj2")
    assert [s.name for s in sc.spots] == ["spot0", "spot1", "spot2", "spot3"]
    assert [b.name for b in sc.bins] == ["bin0", "bin1"]
    assert sc.robot_locations == ("loc0", "loc1")
