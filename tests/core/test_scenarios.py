"""Scenario files: built-ins load, malformed ones are rejected naming the field."""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path

import pytest

from hg_marl.core import ScenarioError, World, available_scenarios, load_scenario


def paper_text() -> str:
    return resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()


def test_builtins_load() -> None:
    assert set(available_scenarios()) >= {"paper2015", "roboergosum", "generated"}
    paper = load_scenario("paper2015")
    assert paper.n_objects == 3 and len(paper.bins) == 1
    robo = load_scenario("roboergosum")
    assert robo.n_objects == 6 and len(robo.bins) == 2 and len(robo.spots) == 7
    assert robo.bin_of == (0, 0, 0, 1, 1, 1)


def test_roboergosum_reachability() -> None:
    w = World("roboergosum")
    reach = {
        s.name: (sorted(w.scenario.robot_locations[i] for i in s.reach.robot_from), s.reach.human)
        for s in w.scenario.spots
    }
    assert reach["placemat1"] == (["ROBOT_LOC"], False)
    assert reach["placemat3"] == (["ROBOT_LOC"], True)
    assert reach["placemat4"] == (["ROBOT_LOC", "SECOND_LOC"], True)
    assert reach["placemat7"] == (["SECOND_LOC"], True)


def test_user_file_round_trip(tmp_path: Path) -> None:
    path = tmp_path / "mine.toml"
    path.write_text(paper_text().replace('name = "paper2015"', 'name = "mine"'))
    assert load_scenario(path).name == "mine"
    assert World(str(path)).n_objects == 3


def test_unknown_scenario_lists_choices() -> None:
    with pytest.raises(ScenarioError, match=r"unknown scenario 'kitchen'.*paper2015"):
        load_scenario("kitchen")


@pytest.mark.parametrize(
    ("edit", "field"),
    [
        (lambda t: t.replace('robot_reach = ["table_left"]', 'robot_reach = ["garden"]', 1), "spots[0].robot_reach[0]"),
        (lambda t: t.replace('name = "tape2"', 'name = "tape1"'), "objects[1].name"),
        (lambda t: t.replace("count = 1", "count = 2"), "layout"),
        (lambda t: t.replace("human_reach = true", "human_reach = 3", 1), "spots[3].human_reach"),
        (lambda t: t.replace('handover_locations = ["human_side"]', "handover_locations = []"), "handover_locations"),
        (lambda t: t.replace('name = "paper2015"\n', ""), "name"),
        (lambda t: t + "\n[durations]\npick = -1\n", "durations.pick"),
        (lambda t: t.replace("count = 2", "count = 4"), "layout[0].count"),
        (
            lambda t: t.replace('spots = ["human_mat_1", "human_mat_2"]', 'spots = ["human_mat_1", "mat_left"]'),
            "layout[1].spots",
        ),
    ],
    ids=[
        "unknown location",
        "duplicate object",
        "layout sum",
        "wrong type",
        "empty handover",
        "missing name",
        "bad duration",
        "too few spots",
        "groups share a spot",
    ],
)
def test_malformed_file_names_the_field(tmp_path: Path, edit, field: str) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(edit(paper_text()))
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert field in str(info.value) and str(path) in str(info.value)


def test_invalid_toml_is_reported(tmp_path: Path) -> None:
    path = tmp_path / "broken.toml"
    path.write_text("name = [unclosed")
    with pytest.raises(ScenarioError, match="not valid TOML"):
        load_scenario(path)


def test_generated_bad_params() -> None:
    with pytest.raises(ScenarioError, match="spots >= objects"):
        load_scenario("generated:objects=5,spots=2")
    with pytest.raises(ScenarioError, match="expected key=value"):
        load_scenario("generated:objects")


def test_builtin_files_are_valid_toml() -> None:
    for name in ("paper2015", "roboergosum"):
        tomllib.loads(resources.files("hg_marl.core.scenarios").joinpath(f"{name}.toml").read_text())
