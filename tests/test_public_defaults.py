"""What a caller gets without asking: every public default is the one pinned in tests/data/.

A default is part of the interface: a study run without ``--duration``, a budget built
without ``states=``, a robot made without its ``stall_after`` all take it, and a changed
default silently changes every such result. ``tests/data/public_defaults.json`` pins each
module's public literal defaults and each command's option defaults (what
``tests/public_defaults.py`` reads by importing the module, as a caller meets them). An
intended change is made there too, by hand, in the same commit: the review sees it.
"""

from __future__ import annotations

import functools
import json

import pytest

from tests.public_defaults import MACHINE_DEPENDENT, SNAPSHOT, command_defaults, package_modules, public_defaults

PINNED: dict[str, dict[str, str]] = json.loads(SNAPSHOT.read_text(encoding="utf-8"))


@functools.cache
def _commands() -> dict[str, dict[str, str]]:
    return command_defaults()


def _now(name: str) -> dict[str, str]:
    return _commands().get(name, {}) if name.startswith("hg-marl") else public_defaults(name)


def _differences(name: str, pinned: dict[str, str], now: dict[str, str]) -> list[str]:
    lines = []
    for key in sorted(pinned.keys() | now.keys()):
        if pinned.get(key) != now.get(key):
            lines.append(f"{name}: {key}: pinned {pinned.get(key, '(absent)')}, now {now.get(key, '(absent)')}")
    return lines


@pytest.mark.parametrize("name", sorted(PINNED), ids=lambda name: name.replace(" ", "-"))
def test_public_defaults_are_the_pinned_ones(name: str) -> None:
    differences = _differences(name, PINNED[name], _now(name))
    hint = "a default changed (if intended, change tests/data/public_defaults.json too)"
    assert not differences, "\n".join([hint, *differences])


def test_every_module_and_command_with_a_default_is_pinned() -> None:
    """A new module or command with defaults joins the file; one that loses them all leaves it."""
    found = {name for name in package_modules() if public_defaults(name)} | set(_commands())
    assert sorted(found - PINNED.keys()) == []
    assert sorted(PINNED.keys() - found) == []


def test_a_changed_default_is_named_with_both_values() -> None:
    """The failure a changed default gives: the module, the name, the pinned value and the new one."""
    pinned = {"Budget(states)": "1500000", "MAX_KEYS": "5000000"}
    now = {"Budget(states)": "1000000", "MAX_KEYS": "5000000", "NEW": "1"}
    assert _differences("m", pinned, now) == [
        "m: Budget(states): pinned 1500000, now 1000000",
        "m: NEW: pinned (absent), now 1",
    ]


def test_machine_dependent_defaults_are_not_pinned() -> None:
    """A worker count taken from the CPU count differs between machines: no file pins it."""
    pinned = {f"{module}.{name}" for module, names in PINNED.items() for name in names}
    pinned |= {f"{command} {option}" for command, options in PINNED.items() for option in options}
    assert sorted(pinned & MACHINE_DEPENDENT) == []
    assert "--workers" not in PINNED["hg-marl evaluate"]  # min(2, CPU count): 1 on a one-core machine
