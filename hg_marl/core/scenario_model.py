"""A scenario as data: its frozen dataclasses, its size limits and what makes a layout solvable.

Read by :mod:`hg_marl.core.scenario_file` (the TOML reader) and
:mod:`hg_marl.core.scenario_generated`; :mod:`hg_marl.core.scenario` re-exports all of it.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field

from hg_marl.core.durations import Durations
from hg_marl.core.errors import ScenarioError


@dataclass(frozen=True)
class Reach:
    """Who reaches a spot or a bin."""

    robot_from: frozenset[int]
    """Indices of the robot locations from which it is reachable."""
    human: bool
    """Whether the human reaches it from its side of the table."""


@dataclass(frozen=True)
class Bin:
    """A trashbin."""

    name: str
    """Unique name."""
    reach: Reach
    """Who can throw into it."""
    colour: str = ""
    """Objects of this colour go here; empty accepts objects of any colour."""


@dataclass(frozen=True)
class Spot:
    """A place on the table (a placemat) that holds at most one object."""

    name: str
    """Unique name."""
    reach: Reach
    """Who can pick from or place on it."""


@dataclass(frozen=True)
class LayoutGroup:
    """``count`` objects are put on distinct spots drawn from ``spots`` at each reset."""

    count: int
    """How many objects this group places."""
    spots: tuple[int, ...]
    """Candidate spot indices."""


@dataclass(frozen=True)
class Scenario:
    """A validated table-cleaning scenario.

    Objects are shuffled at every reset and dealt to the layout groups in order, each
    group placing its objects on distinct random spots of its own; the robot starts at
    a location drawn from ``robot_start``.
    """

    name: str
    """Scenario name (the file stem for built-ins)."""
    objects: tuple[str, ...]
    """Object names, in index order."""
    object_colours: tuple[str, ...]
    """Colour of each object ('' for none)."""
    bins: tuple[Bin, ...]
    """Trashbins."""
    spots: tuple[Spot, ...]
    """Spots on the table."""
    robot_locations: tuple[str, ...]
    """Names of the places the robot can stand."""
    handover_locations: frozenset[int]
    """Robot locations next to the human, where handovers are possible."""
    robot_start: tuple[int, ...]
    """Candidate initial robot locations."""
    layout: tuple[LayoutGroup, ...]
    """How objects are placed at reset."""
    durations: Durations = field(default_factory=Durations)
    """Default action durations for this scenario."""
    description: str = ""
    """Free text."""

    @property
    def n_objects(self) -> int:
        """Number of objects."""
        return len(self.objects)

    @property
    def bin_of(self) -> tuple[int, ...]:
        """For each object, the index of the first bin that accepts its colour."""
        return tuple(
            next(b for b, bn in enumerate(self.bins) if bn.colour in ("", colour)) for colour in self.object_colours
        )


def _limit(name: str, default: int) -> int:
    """A size limit, raised by the environment variable ``HG_MARL_MAX_<NAME>``."""
    raw = os.environ.get(f"HG_MARL_MAX_{name.upper()}")
    if raw is None:
        return default
    try:
        value = int(raw)
    except ValueError:
        raise ScenarioError(f"HG_MARL_MAX_{name.upper()}={raw!r}: expected an integer") from None
    if value < 1:  # a limit of 0 or below would refuse every scenario under a message naming another limit
        raise ScenarioError(f"HG_MARL_MAX_{name.upper()}={raw!r}: expected an integer >= 1")
    return value


LIMITS = {"objects": 40, "spots": 120, "bins": 16, "locations": 32, "actions": 4000}
"""Documented size limits of a scenario (checked before anything is allocated); each is
raised by the environment variable ``HG_MARL_MAX_OBJECTS``, ``..._SPOTS``, ``..._BINS``,
``..._LOCATIONS``, ``..._ACTIONS``. ``actions`` bounds the human's largest action set,
about ``objects x (spots + 5)`` (``place(o, spot)`` dominates)."""


def check_sizes(source: str, objects: int, spots: int, bins: int, locations: int) -> None:
    """Refuse a scenario over a size limit, with the limit and how to raise it."""
    sizes = {
        "objects": objects,
        "spots": spots,
        "bins": bins,
        "locations": locations,
        "actions": objects * (spots + 5) + bins + locations + 2,
    }
    for name, value in sizes.items():
        limit = _limit(name, LIMITS[name])
        if value > limit:
            raise ScenarioError(
                f"scenario {source}: {value} {name} is over the limit {limit} "
                f"(set HG_MARL_MAX_{name.upper()} to raise it)"
            )


def layout_count(scenario: Scenario) -> int:
    """How many (object subset, ordered spots) deals the initial layouts enumerate, times start locations.

    The exact model (the oracle) enumerates them all; computed without allocating, so a
    caller can refuse a scenario whose enumeration would not fit.
    """
    count, left = len(scenario.robot_start), scenario.n_objects
    for group in scenario.layout:
        count *= math.comb(left, group.count) * math.perm(len(group.spots), group.count)
        left -= group.count
    return count


class ScenarioWarning(UserWarning):
    """A scenario that loads but where some initial layout cannot be cleaned."""


_WARNED: set[str] = set()


def solvability_problems(scenario: Scenario) -> list[str]:
    """Why some initial layout cannot be cleaned by the two agents, if it cannot.

    An object can be cleaned when someone reaches its spot and someone reaches a bin
    that accepts its colour (handovers carry it between the agents). Every spot a
    layout group may draw counts, since any of them can hold an object at reset.
    """
    problems = []
    layout_spots = {s for g in scenario.layout for s in g.spots}
    for s in sorted(layout_spots):
        spot = scenario.spots[s]
        if not spot.reach.robot_from and not spot.reach.human:
            problems.append(f"no agent reaches spot {spot.name!r}, where the layout may put an object")
    for o, colour in enumerate(scenario.object_colours):
        bins = [b for b in scenario.bins if b.colour in ("", colour)]
        if not any(b.reach.robot_from or b.reach.human for b in bins):
            problems.append(f"no agent reaches a bin for object {scenario.objects[o]!r}")
    return problems
