"""Action durations in simulated seconds, configurable per action type."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, fields, replace
from typing import Any

from hg_marl.core.errors import ConfigError, check_finite
from hg_marl.core.types import Kind

MAX_DURATION = 86_400.0
"""Longest action duration accepted (one simulated day)."""

MIN_DURATION = 0.01
"""Shortest action duration accepted (simulated seconds). A cycle lasts at least
the shortest duration, so a run of ``--duration D`` takes at most ``D / MIN_DURATION``
cycles; durations of 1e-300 s (finite, positive) would make any run endless."""


@dataclass(frozen=True)
class Durations:
    """How long each action type takes when it succeeds (seconds of simulated time).

    A cycle (robot turn then human turn) lasts as long as the longer of its two actions:
    the agents act in parallel, so the robot's ``wait`` lasts until the human is done.
    """

    pick: float = 2.0
    """Grasp an object from a spot."""
    throw: float = 2.0
    """Drop the held object into its bin."""
    give: float = 1.0
    """Hold the object out to the partner."""
    take: float = 1.5
    """Take the object being offered."""
    place: float = 2.0
    """(Human) put the held object on a spot."""
    goto: float = 3.0
    """(Robot) move to another location."""
    wait: float = 1.0
    """Do nothing for a moment."""
    failed: float = 0.2
    """An action whose preconditions do not hold: only the precondition check."""

    def __post_init__(self) -> None:
        for f in fields(self):
            check_finite(getattr(self, f.name), f"durations.{f.name}", minimum=MIN_DURATION, maximum=MAX_DURATION)

    def of(self, kind: Kind, ok: bool = True) -> float:
        """Duration of an action of ``kind`` (``failed`` when ``ok`` is False)."""
        if not ok:
            return self.failed
        return float(getattr(self, kind.name.lower()))

    @property
    def shortest(self) -> float:
        """The shortest duration: a lower bound on the length of a cycle."""
        return min(float(getattr(self, f.name)) for f in fields(self))

    @property
    def longest(self) -> float:
        """The longest duration (a cycle lasts at most this, plus any charged decision time)."""
        return max(float(getattr(self, f.name)) for f in fields(self))

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], source: str = "<config>") -> Durations:
        """Build from a mapping such as a TOML table, naming any bad field (NaN and infinity are refused).

        Raises:
            ConfigError: an unknown action type or a value that is not a finite positive number.
        """
        known = {f.name for f in fields(cls)}
        values: dict[str, float] = {}
        for key, value in data.items():
            if key not in known:
                raise ConfigError(
                    f"{source}: field 'durations.{key}': unknown action type (known: {', '.join(sorted(known))})"
                )
            values[key] = check_finite(
                value, f"{source}: field 'durations.{key}'", minimum=MIN_DURATION, maximum=MAX_DURATION
            )
        return replace(cls(), **values)
