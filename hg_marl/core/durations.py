"""Action durations in simulated seconds, configurable per action type."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, fields, replace
from typing import Any

from hg_marl.core.types import Kind


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

    def of(self, kind: Kind, ok: bool = True) -> float:
        """Duration of an action of ``kind`` (``failed`` when ``ok`` is False)."""
        if not ok:
            return self.failed
        return float(getattr(self, kind.name.lower()))

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], source: str = "<config>") -> Durations:
        """Build from a mapping such as a TOML table, naming any bad field."""
        known = {f.name for f in fields(cls)}
        out = cls()
        for key, value in data.items():
            if key not in known:
                raise ValueError(
                    f"{source}: field 'durations.{key}': unknown action type (known: {', '.join(sorted(known))})"
                )
            if isinstance(value, bool) or not isinstance(value, int | float) or value <= 0:
                raise ValueError(f"{source}: field 'durations.{key}': expected a positive number, got {value!r}")
            out = replace(out, **{key: float(value)})
        return out
