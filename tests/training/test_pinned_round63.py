"""The values round 63's missed planted bugs changed (``mutation/planted.py``, FRESH63), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.humans.registry import available_humans
from hg_marl.core.errors import ScenarioError
from hg_marl.core.registry import Entry
from hg_marl.core.scenario_file import parse_scenario
from hg_marl.core.scenario_model import solvability_problems

POPULATION = Path(__file__).resolve().parents[2] / "populations" / "paper2015.toml"

# -- registry: an entry is stationary unless it says otherwise -----------------------------


class _Thing:
    """A stand-in target with ``distribution(world, state)``: what "stationary" means for an entry."""

    def distribution(self, world: object, state: object) -> list[tuple[int, float]]:
        return [(0, 1.0)]


def test_an_entry_is_stationary_unless_it_says_otherwise() -> None:
    # The module docstring: what the signature cannot say "the entry adds: ... whether the
    # thing is stationary"; the human registry says ``stationary=False`` only for the humans
    # that follow a clock or a trace, so an entry that says nothing is stationary.
    assert Entry("thing", _Thing).stationary is True
    assert Entry("thing", _Thing, stationary=False).stationary is False


def test_the_scripted_humans_are_listed_stationary_and_the_scheduled_ones_not() -> None:
    # agents/compiled.py: "A stationary human (every registry human but ``switching`` and
    # ``replay``...)"; the family-out humans that work by the clock (fo_bursts,
    # fo_forgetful, fo_slow_start) or count the robot's waits (fo_after_waits) are declared not.
    listed = {name: info["stationary"] for name, info in available_humans().items()}
    for name in ("cooperative", "lazy", "no_handover", "adversarial", "random", "noisy", "preference", "fo_picky"):
        assert listed[name] is True, name
    for name in ("switching", "replay", "fo_bursts", "fo_after_waits"):
        assert listed[name] is False, name


def test_the_bundled_population_of_preference_humans_loads() -> None:
    # The population module: "non-stationary humans are refused"; the bundled file's members
    # are all ``preference:...`` (a stationary human), so it loads with its eight train members.
    population = load_population(POPULATION)
    assert len(population.members("train")) == 8
    assert all(m.spec.startswith("preference:") for m in population.members("train"))


# -- scenario files written with inline table arrays -----------------------------------------


def _inline(objects: str = '{ name = "cup" }, { name = "pen" }', spots: str = "") -> str:
    """A small scenario whose tables are inline arrays (no ``[[objects]]`` headers); line 4 is ``objects``."""
    extra = f", {spots}" if spots else ""
    return "\n".join(
        [
            'name = "inline"',
            'robot_locations = ["near"]',
            'handover_locations = ["near"]',
            f"objects = [{objects}]",
            'bins = [{ name = "bin", robot_reach = ["near"], human_reach = true }]',
            "spots = ["
            '{ name = "s0", robot_reach = ["near"], human_reach = true }, '
            '{ name = "s1", robot_reach = ["near"], human_reach = true }' + extra + "]",
            'layout = [{ count = 2, spots = ["s0", "s1"] }]',
            "",
        ]
    )


@pytest.mark.parametrize("index", [0, 1])
def test_a_bad_name_in_an_inline_array_is_reported_at_the_arrays_line(index: int) -> None:
    # The module docstring: a refusal gives ``path:line``, "found by searching the file's text
    # for the field". With no ``[[objects]]`` header the field ``objects[i].name`` is found
    # at the ``objects = [...]`` key, line 4 of the text above, whichever entry is bad (the
    # first one included).
    names = ['{ name = "cup" }', '{ name = "pen" }']
    names[index] = '{ name = "two words" }'
    text = _inline(objects=", ".join(names))
    with pytest.raises(ScenarioError) as caught:
        parse_scenario(tomllib.loads(text), "inline.toml", text=text)
    message = str(caught.value)
    assert message.startswith(f"scenario inline.toml:4: field 'objects[{index}].name'"), message


def test_the_inline_scenario_loads_when_its_names_are_good() -> None:
    # The same text with good names is a valid scenario (so the refusals above are the names').
    text = _inline()
    scenario = parse_scenario(tomllib.loads(text), "inline.toml", text=text, strict=True)
    assert scenario.objects == ("cup", "pen")


# -- solvability: only the spots a layout group may draw count -------------------------------


def test_an_unreachable_spot_no_layout_group_draws_makes_no_problem() -> None:
    # scenario_model.solvability_problems: "Every spot a layout group may draw counts, since
    # any of them can hold an object at reset"; a spot outside every group never holds an
    # object at reset, so nobody reaching it is no problem, and a strict load accepts it.
    text = _inline(spots='{ name = "shelf" }')
    scenario = parse_scenario(tomllib.loads(text), "inline.toml", text=text, strict=True)
    assert [s.name for s in scenario.spots] == ["s0", "s1", "shelf"]
    assert solvability_problems(scenario) == []


def test_an_unreachable_spot_a_layout_group_draws_is_a_problem() -> None:
    # The counterpart: the same spot listed by the group may hold an object nobody reaches.
    text = _inline(spots='{ name = "shelf" }').replace('spots = ["s0", "s1"]', 'spots = ["s0", "s1", "shelf"]')
    with pytest.raises(ScenarioError, match="no agent reaches spot 'shelf'"):
        parse_scenario(tomllib.loads(text), "inline.toml", text=text, strict=True)
