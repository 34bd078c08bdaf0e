"""The one Registry: defaults come from the constructor, specs are parsed once, errors name the thing."""

from __future__ import annotations

import sys
from dataclasses import fields

import pytest

from hg_marl.agents.humans.registry import HUMANS
from hg_marl.agents.meta.registry import CRITERIA
from hg_marl.agents.robots.registry import ROBOTS
from hg_marl.core.errors import ConfigError
from hg_marl.core.registry import Entry, Param, Registry


class Toy:
    name = "toy"

    def __init__(self, speed: float = 1.5, label: str = "a", tags: tuple[str, ...] = ("x",), path: str | None = None):
        if speed < 0:
            raise ValueError("speed must be non-negative")
        self.speed, self.label, self.tags, self.path = speed, label, tags, path


TOYS = Registry("toy", ConfigError, [Toy, Entry("lazy_toy", "json:JSONDecoder", "imported on demand")])


def test_defaults_are_the_constructors() -> None:
    assert TOYS["toy"].params == {
        "speed": Param(1.5, ""),
        "label": Param("a", ""),
        "tags": Param(["x"], ""),
        "path": Param(None, ""),
    }


def test_a_spec_and_keywords_build_with_values_typed_by_the_defaults() -> None:
    toy = TOYS.make("toy:speed=2,tags=a|b", label="z")
    assert (toy.speed, toy.label, toy.tags, toy.path) == (2.0, "z", ["a", "b"], None)
    assert isinstance(toy.speed, float)


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ("cat", "unknown toy 'cat'; available: toy, lazy_toy"),
        ("toy:colour=red", "toy 'toy' has no parameter 'colour'; its parameters: speed=1.5"),
        ("toy:speed=fast", "toy 'toy': parameter 'speed': expected a finite number, got 'fast'"),
        ("toy:speed=-1", "toy 'toy': speed must be non-negative"),
    ],
)
def test_errors_name_the_thing_in_the_registrys_error_type(spec: str, message: str) -> None:
    with pytest.raises(ConfigError, match=message):
        TOYS.make(spec)


def test_a_text_target_is_imported_only_when_used() -> None:
    entry = TOYS["lazy_toy"]
    assert entry.module == "json"
    assert entry.factory() is sys.modules["json"].JSONDecoder


def test_entries_hold_no_default_so_none_can_drift_from_the_constructor() -> None:
    assert {f.name for f in fields(Entry)} == {"name", "target", "doc", "param_docs", "stationary"}


@pytest.mark.parametrize("registry", [HUMANS, ROBOTS, CRITERIA], ids=["humans", "robots", "criteria"])
def test_every_documented_parameter_exists_in_its_constructor(registry: Registry) -> None:
    for name, entry in registry.items():
        assert set(entry.param_docs) <= set(entry.defaults()), name
