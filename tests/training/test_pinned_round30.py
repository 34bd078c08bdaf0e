"""The values round 30's missed planted bugs changed, pinned after the round.

Round 30 planted 14 bugs in fourteen gated modules of the early rounds, written blind;
11 were caught. Each value below is stated from the rule the module documents, not read
from the code under test:

- the learning-state criterion's ``threshold`` is a positive RMS TD error: the habit acts
  where its error is *below* it, so a threshold of 0 (under which the habit could never
  act) is refused, naming the parameter;
- a registry turns a constructor's own ``TypeError`` (as its ``ValueError``) into the
  registry's error type, naming the kind and the thing;
- a scenario's layout group puts ``count`` objects on distinct spots of its own, so a
  group listing exactly ``count`` spots is valid (every spot filled at each reset), and
  one listing fewer is refused.
"""

from __future__ import annotations

from typing import Any

import pytest

from hg_marl.agents.meta.learning_state import LearningStateCriterion
from hg_marl.core.errors import ConfigError, ScenarioError
from hg_marl.core.registry import Registry
from hg_marl.core.scenario_file import parse_scenario

# --- agents/meta/learning_state.py ---


@pytest.mark.parametrize("threshold", [0, 0.0, -0.5])
def test_a_threshold_that_is_not_positive_is_refused(threshold: float) -> None:
    with pytest.raises(ValueError, match=r"^learning_state\.threshold: expected a positive number"):
        LearningStateCriterion(threshold=threshold)


def test_a_small_positive_threshold_is_accepted() -> None:
    assert LearningStateCriterion(threshold=1e-6).threshold == 1e-6


# --- hg_marl/core/registry.py ---


class _Strict:
    """A thing whose constructor raises a TypeError itself (a square needs two sides, given ``size``)."""

    name = "strict"

    def __init__(self, size: int = 2) -> None:
        self.size = size
        self.area = self._square(*range(1, size + 1))

    @staticmethod
    def _square(a: int, b: int) -> int:
        return a * b


class _Picky:
    """A thing whose constructor refuses a bad value itself, with a ValueError."""

    name = "picky"

    def __init__(self, size: int = 1) -> None:
        if size < 1:
            raise ValueError(f"size: expected at least 1, got {size}")
        self.size = size


WIDGETS = Registry("widget", ConfigError, [_Strict, _Picky])


def test_a_constructors_type_error_becomes_the_registrys_error_naming_the_thing() -> None:
    with pytest.raises(ConfigError, match=r"^widget 'strict': .*_square\(\) takes 2 positional arguments") as caught:
        WIDGETS.make("strict:size=3")
    assert not isinstance(caught.value, TypeError)


def test_a_constructors_value_error_becomes_the_registrys_error_naming_the_thing() -> None:
    with pytest.raises(ConfigError, match=r"^widget 'picky': size: expected at least 1, got 0$"):
        WIDGETS.make("picky:size=0")


def test_a_good_value_builds_the_thing() -> None:
    assert WIDGETS.make("strict:size=2").area == 2


# --- hg_marl/core/scenario_file.py ---


def _scenario(count: int, spots: list[str]) -> dict[str, Any]:
    """A small valid scenario: ``count`` objects, one group drawing from ``spots`` of mats a, b, c."""
    return {
        "name": "full_group",
        "robot_locations": ["near"],
        "handover_locations": ["near"],
        "objects": [{"name": f"o{i}"} for i in range(count)],
        "bins": [{"name": "bin", "robot_reach": ["near"], "human_reach": True}],
        "spots": [{"name": s, "robot_reach": ["near"], "human_reach": True} for s in ("a", "b", "c")],
        "layout": [{"count": count, "spots": spots}],
    }


@pytest.mark.parametrize(("count", "spots"), [(1, ["a"]), (2, ["a", "b"]), (3, ["a", "b", "c"])])
def test_a_group_with_exactly_as_many_spots_as_objects_is_accepted(count: int, spots: list[str]) -> None:
    scenario = parse_scenario(_scenario(count, spots), "full.toml", strict=True)
    assert [(g.count, g.spots) for g in scenario.layout] == [(count, tuple(range(count)))]


def test_a_group_with_fewer_spots_than_objects_is_refused() -> None:
    with pytest.raises(ScenarioError, match=r"3 objects need 3 distinct spots, the group lists 2"):
        parse_scenario(_scenario(3, ["a", "b"]), "short.toml", strict=True)
