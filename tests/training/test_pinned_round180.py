"""Values that round 180's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import tomllib
from types import SimpleNamespace

import pytest

import hg_marl.agents.robots.memory as memory_module
from hg_marl.core.errors import ConfigError, ScenarioError
from hg_marl.core.scenario_file import parse_scenario
from tests.agents.test_pinned_memory_robot_gate import (
    GOTO_BIN,
    GOTO_HUMAN,
    GOTO_TAPE1,
    GOTO_TAPE2,
    WAIT,
    _Clock,
    robot,
)
from tests.core.test_pinned_registry_gate import TOYS
from tests.training.test_pinned_round72 import _scenario_text

# --- agents/robots/memory.py ---


def test_the_guard_skips_the_policys_feasible_choice_not_a_masked_logit(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The policy's largest logit is goto bin (9.0), masked at this state (the robot is already at
    # the bin); its best feasible move is goto human (1.0), then wait 0.5, goto tape2 0.0, goto
    # tape1 -0.5. The state never changes: turns 1 and 2 play goto human; from turn 3 (K = 2)
    # the guard leaves out the move the policy keeps choosing, goto human, and plays the other
    # feasible non-wait moves best first: goto tape2, then goto tape1. Leaving out the masked goto
    # bin instead would leave goto human first in line, and the guard would repeat the stall.
    r, turn = robot({GOTO_BIN: 9.0, GOTO_HUMAN: 1.0, WAIT: 0.5, GOTO_TAPE2: 0.0, GOTO_TAPE1: -0.5}, unstall=2)
    monkeypatch.setattr(memory_module, "time", SimpleNamespace(perf_counter=_Clock().perf_counter))
    played = []
    for _ in range(4):
        played.append(r.act(turn))
        assert r.last_decision is not None
        played.append(r.last_decision.expert)
    assert played == [GOTO_HUMAN, "memory", GOTO_HUMAN, "memory", GOTO_TAPE2, "guard", GOTO_TAPE1, "guard"]


# --- hg_marl/core/registry.py ---


@pytest.mark.parametrize("name", ["TOY", "Toy"])
def test_a_name_in_another_case_is_an_unknown_name(name: str) -> None:
    # Registry names are matched exactly: the toy registry holds "toy" only, so "TOY" is
    # refused with the registry's message, naming what it was given and what exists.
    with pytest.raises(ConfigError) as info:
        TOYS.make(name)
    assert str(info.value) == f"unknown toy {name!r}; available: toy"
    with pytest.raises(ConfigError, match="unknown toy"):
        TOYS.lookup(name)
    assert TOYS.make("toy").speed == 1.5  # the control: the exact name builds


# --- hg_marl/core/scenario_file.py ---


def _with_location(name: str) -> str:
    """Round 72's small valid scenario with its one robot location called ``name``."""
    return _scenario_text("cup").replace('"near"', f'"{name}"')


@pytest.mark.parametrize(
    ("name", "message"),
    [
        ("Human", "is reserved by the action syntax"),
        ("wait", "is reserved by the action syntax"),
        ("1st", "must be a letter then letters, digits, '_' or '-'"),
        ("a.b", "must be a letter then letters, digits, '_' or '-'"),
    ],
)
def test_a_robot_location_is_held_to_the_object_name_rules(name: str, message: str) -> None:
    # A robot location's name appears inside action names (goto(near)), so it follows the
    # rules of object, bin and spot names (NAME_PATTERN, RESERVED_NAMES), not the scenario
    # name's: a letter first, no '.', and none of human, robot, wait in any case.
    text = _with_location(name)
    with pytest.raises(ScenarioError, match=message) as info:
        parse_scenario(tomllib.loads(text), "tiny.toml", text=text)
    assert "robot_locations[0]" in str(info.value)


def test_a_robot_location_with_an_ordinary_name_loads() -> None:
    # The control: the refusals above are the location's name's, not the rest of the scenario's.
    text = _with_location("far_side-2")
    assert parse_scenario(tomllib.loads(text), "tiny.toml", text=text, strict=True).robot_locations == ("far_side-2",)
