"""Scenario files are strict: unknown keys, duplicates, NaN, sizes, encodings, unsolvable layouts.

Every expected line number below is counted by hand in the edited text (the test finds
the line of the edited key by searching the text, independently of the parser).
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

import pytest

from hg_marl.core import ScenarioError, load_scenario
from hg_marl.core.scenario import LIMITS, ScenarioWarning, solvability_problems


def paper_text() -> str:
    return resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()


def line_containing(text: str, needle: str) -> int:
    return next(i + 1 for i, line in enumerate(text.splitlines()) if needle in line)


def write(tmp_path: Path, text: str, name: str = "s.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("old", "new", "field", "needle"),
    [
        ("[[bins]]\n", '[[bins]]\ncolor = "red"\n', "bins[0].color", 'color = "red"'),
        ('name = "paper2015"\n', 'name = "paper2015"\nseed = 3\n', "seed", "seed = 3"),
        ("robot_locations = [", 'robot_locations = ["bin_side", ', "robot_locations[1]", "robot_locations ="),
        ("count = 1", "count = 1\nspot = 2", "layout[1].spot", "spot = 2"),  # the second group has count 1
    ],
)
def test_unknown_keys_and_duplicates_give_path_line(
    tmp_path: Path, old: str, new: str, field: str, needle: str
) -> None:
    text = paper_text().replace(old, new, 1)
    path = write(tmp_path, text)
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    message = str(info.value)
    assert f"{path}:{line_containing(text, needle)}" in message and repr(field) in message


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "0", "-1", "true", '"2"', "1e9"])
def test_durations_must_be_finite_positive_numbers(tmp_path: Path, value: str) -> None:
    text = paper_text() + f"\n[durations]\npick = {value}\n"
    path = write(tmp_path, text)
    with pytest.raises(ScenarioError, match=r"durations\.pick") as info:
        load_scenario(path)
    assert f"{path}:{line_containing(text, 'pick = ')}" in str(info.value)


def test_duplicate_toml_key_gives_path_line(tmp_path: Path) -> None:
    text = paper_text().replace('name = "paper2015"\n', 'name = "paper2015"\nname = "again"\n', 1)
    path = write(tmp_path, text)
    with pytest.raises(ScenarioError, match=f"{path}:{line_containing(text, 'again')}: not valid TOML"):
        load_scenario(path)


def test_latin1_file_is_named(tmp_path: Path) -> None:
    path = tmp_path / "latin.toml"
    path.write_bytes(paper_text().replace('description = "', 'description = "caf\xe9 ', 1).encode("latin-1"))
    with pytest.raises(ScenarioError, match=f"{path}: not UTF-8"):
        load_scenario(path)


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ("generated:objects=10000", f"over the limit {LIMITS['objects']} (set HG_MARL_MAX_OBJECTS"),
        ("generated:bins=1e6", f"over the limit {LIMITS['bins']} (set HG_MARL_MAX_BINS"),
        ("generated:objects=40,spots=120", f"over the limit {LIMITS['actions']} (set HG_MARL_MAX_ACTIONS"),
        ("generated:objects=2.5", "parameter 'objects': expected an integer, got 2.5"),
        ("generated:human_only=nan", "parameter 'human_only': expected a finite number"),
        ("generated:seed=-1", "seed: expected an integer >= 0"),
        ("generated:colour=red", "has no parameter 'colour'"),
        ("generated:objects", "expected key=value"),
    ],
)
def test_generated_parameters_and_limits(spec: str, message: str) -> None:
    with pytest.raises(ScenarioError, match=message.replace("(", r"\(").replace(".", r"\.")):
        load_scenario(spec)


def test_limit_is_raised_by_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("HG_MARL_MAX_OBJECTS", "50")
    assert load_scenario("generated:objects=45,spots=45").n_objects == 45


def test_too_many_objects_in_a_file_is_refused_before_parsing_them(tmp_path: Path) -> None:
    objects = "".join(f'[[objects]]\nname = "o{i}"\n' for i in range(1000))
    text = paper_text().replace('[[objects]]\nname = "tape1"\n', objects, 1)
    with pytest.raises(ScenarioError, match="objects is over the limit"):
        load_scenario(write(tmp_path, text))


def test_unreachable_bin_warns_or_refuses(tmp_path: Path) -> None:
    text = paper_text().replace('robot_reach = ["bin_side"]', "robot_reach = []", 1)
    path = write(tmp_path, text)
    with pytest.warns(ScenarioWarning, match="no agent reaches a bin for object 'tape1'"):
        scenario = load_scenario(path)
    assert len(solvability_problems(scenario)) == 3  # one per object
    with pytest.raises(ScenarioError, match="no agent reaches a bin"):
        load_scenario(path, strict=True)


def test_builtins_are_solvable() -> None:
    for name in ("paper2015", "roboergosum", "generated:objects=6,seed=3"):
        assert solvability_problems(load_scenario(name)) == []


def test_layout_count_is_the_oracles_enumeration() -> None:
    from hg_marl.core.scenario import layout_count

    # paper2015 by hand: 3 objects; group 1 takes 2 of them (C(3,2)=3) onto 2 of its 3 spots in
    # order (P(3,2)=6); group 2 takes the last one onto 1 of its 2 spots (2); 1 start location.
    assert layout_count(load_scenario("paper2015")) == 3 * 6 * 2
    # 12 objects on 14 spots: 14!/2! ordered deals, refused by `hg-marl oracle` before enumerating.
    assert layout_count(load_scenario("generated:objects=12,spots=14")) == 43_589_145_600
