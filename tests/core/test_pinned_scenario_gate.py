"""Scenario files and generated scenarios at their boundaries, values stated by hand.

A generated scenario needs at least one object, as many spots as objects, one robot
location and one bin; each count at zero is refused on its own (one line naming the
counts), and the smallest accepted one is one of each.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario import load_scenario

NEED = "generated scenario: need objects >= 1, spots >= objects, locations >= 1, bins >= 1; got "


@pytest.mark.parametrize(
    ("spec", "got"),
    [
        ("generated:objects=0", "objects=0, spots=2, locations=2, bins=1"),
        ("generated:objects=3,spots=2", "objects=3, spots=2, locations=2, bins=1"),
        ("generated:locations=0", "objects=4, spots=6, locations=0, bins=1"),
        ("generated:bins=0", "objects=4, spots=6, locations=2, bins=0"),
    ],
)
def test_each_count_below_its_minimum_is_refused_alone(spec: str, got: str) -> None:
    with pytest.raises(ScenarioError) as info:
        load_scenario(spec)
    assert str(info.value) == NEED + got


def test_one_of_each_is_the_smallest_generated_scenario() -> None:
    sc = load_scenario("generated:objects=1,spots=1,locations=1,bins=1")
    assert (len(sc.objects), len(sc.spots), len(sc.robot_locations), len(sc.bins)) == (1, 1, 1, 1)
    assert sc.name == "generated:objects=1,spots=1,locations=1,bins=1,human_only=0.3,seed=0"
    assert sc.object_colours == ("",) and sc.bins[0].colour == ""  # one bin takes every object: no colours


def test_several_bins_share_the_objects_by_colour() -> None:
    sc = load_scenario("generated:objects=5,bins=2")
    assert [b.colour for b in sc.bins] == ["c0", "c1"]
    assert sc.object_colours == ("c0", "c1", "c0", "c1", "c0")


def test_a_robot_spot_is_shared_with_the_human_about_three_times_in_ten() -> None:
    """With ``human_only=0`` every spot is the robot's, and each is also the human's with
    probability 0.3 (the generator's rule); over 110 seeded spots the share is within a
    few standard deviations of 0.3 (sd 0.044), far from all or none, and each bin is the
    human's with the same probability (20 bins: sd 0.1)."""
    shared, bins = [], []
    for seed in range(5):
        sc = load_scenario(f"generated:objects=20,human_only=0,locations=3,bins=4,seed={seed}")
        assert all(s.reach.robot_from for s in sc.spots)
        shared += [s.reach.human for s in sc.spots]
        bins += [b.reach.human for b in sc.bins]
    assert len(shared) == 110 and 0.15 < sum(shared) / 110 < 0.45
    assert len(bins) == 20 and 0.05 < sum(bins) / 20 < 0.75


def test_human_only_spots_are_the_humans_alone() -> None:
    sc = load_scenario("generated:objects=6,human_only=1,seed=2")
    assert all(s.reach.human and not s.reach.robot_from for s in sc.spots)


def test_the_actions_estimate_is_objects_times_spots_plus_five_and_the_rest(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """3 objects, 5 spots, 2 bins, 2 locations: 3 x (5 + 5) + 2 + 2 + 2 = 36 actions by the
    documented estimate; a limit of 36 passes it, 35 refuses it naming both numbers."""
    spec = "generated:objects=3,spots=5,locations=2,bins=2"
    monkeypatch.setenv("HG_MARL_MAX_ACTIONS", "36")
    assert len(load_scenario(spec).objects) == 3
    monkeypatch.setenv("HG_MARL_MAX_ACTIONS", "35")
    with pytest.raises(ScenarioError) as info:
        load_scenario(spec)
    assert str(info.value) == (
        "scenario generated: 36 actions is over the limit 35 (set HG_MARL_MAX_ACTIONS to raise it)"
    )


def _paper() -> str:
    from importlib import resources

    return resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()


def test_a_missing_key_in_an_array_table_names_that_tables_header_line(tmp_path: Path) -> None:
    # paper2015.toml: the second [[spots]] header is line 30 (counted in the file); without its
    # name key the error points at that header
    text = _paper()
    assert text.splitlines()[29] == "[[spots]]" and text.splitlines()[30] == 'name = "mat_centre"'
    path = tmp_path / "s.toml"
    path.write_text(text.replace('name = "mat_centre"\n', "", 1))
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value) == f"scenario {path}:30: field 'spots[1].name': missing"


def test_several_unsolvable_layouts_are_counted_after_the_first(tmp_path: Path) -> None:
    # no agent reaches the bin: each of paper2015's 3 objects is a problem, the first named, 2 more
    path = tmp_path / "s.toml"
    path.write_text(_paper().replace('robot_reach = ["bin_side"]', "robot_reach = []", 1))
    with pytest.raises(ScenarioError) as info:
        load_scenario(path, strict=True)
    assert str(info.value) == f"scenario {path}: no agent reaches a bin for object 'tape1' (and 2 more)"


def test_a_single_unsolvable_layout_is_named_alone(tmp_path: Path) -> None:
    path = tmp_path / "s.toml"
    path.write_text(
        _paper().replace('name = "mat_left"\nrobot_reach = ["table_left"]', 'name = "mat_left"\nrobot_reach = []')
    )
    with pytest.raises(ScenarioError) as info:
        load_scenario(path, strict=True)
    assert str(info.value) == f"scenario {path}: no agent reaches spot 'mat_left', where the layout may put an object"


@pytest.mark.parametrize(
    ("name", "limit", "spec"),
    [
        ("objects", 40, "generated:objects={n},spots=41"),
        ("spots", 120, "generated:objects=1,spots={n}"),
        ("bins", 16, "generated:objects=1,bins={n}"),
        ("locations", 32, "generated:objects=1,locations={n}"),
    ],
)
def test_each_documented_size_limit_is_accepted_and_one_more_refused(name: str, limit: int, spec: str) -> None:
    # docs/inputs.md: 40 objects, 120 spots, 16 bins, 32 robot locations
    assert load_scenario(spec.format(n=limit)) is not None
    with pytest.raises(ScenarioError) as info:
        load_scenario(spec.format(n=limit + 1))
    assert f"{limit + 1} {name} is over the limit {limit} (set HG_MARL_MAX_{name.upper()} to raise it)" in str(
        info.value
    )


def test_without_robot_start_the_robot_starts_at_its_first_location(tmp_path: Path) -> None:
    # forced_coordination's locations are bin_side, pass; its file says robot_start = bin_side.
    # Without that line the robot starts at the first location, bin_side (index 0), not at pass.
    text = (Path(__file__).parents[2] / "hg_marl/core/scenarios/forced_coordination.toml").read_text()
    assert 'robot_start = ["bin_side"]\n' in text
    moved = tmp_path / "no_start.toml"
    moved.write_text(
        text.replace('robot_start = ["bin_side"]\n', "").replace(
            'robot_locations = ["bin_side", "pass"]', 'robot_locations = ["pass", "bin_side"]'
        )
    )
    plain = tmp_path / "plain.toml"
    plain.write_text(text.replace('robot_start = ["bin_side"]\n', ""))
    assert load_scenario(str(plain)).robot_start == (0,)
    assert load_scenario(str(moved)).robot_start == (0,)  # still the first listed, now pass
    assert load_scenario(str(moved)).robot_locations[0] == "pass"


@pytest.mark.parametrize("raw", ["0", "-5"])
def test_a_limit_below_one_is_refused_naming_the_variable(monkeypatch, raw: str) -> None:  # type: ignore[no-untyped-def]
    """A limit of 0 or less would refuse every scenario (it used to be read as 1, and the
    refusal then named a limit of 1 the user never set); 1 itself is a limit."""
    monkeypatch.setenv("HG_MARL_MAX_BINS", raw)
    with pytest.raises(ScenarioError) as info:
        load_scenario("paper2015")
    assert str(info.value) == f"HG_MARL_MAX_BINS={raw!r}: expected an integer >= 1"
    monkeypatch.setenv("HG_MARL_MAX_BINS", "1")
    assert len(load_scenario("paper2015").bins) == 1
