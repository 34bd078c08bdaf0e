"""Scenarios: the table's geometry and its layout distribution, as data.

A scenario is a TOML file (see ``scenarios/paper2015.toml`` for a commented example)
validated on load into a frozen :class:`Scenario`. A malformed file is rejected with a
:class:`ScenarioError` that names the file and the offending field, e.g.
``spots[2].robot_reach: unknown robot location 'kitchen' (known: bin_side, ...)``.

Geometry is reachability only: each spot and bin lists the robot locations it can be
reached from and whether the human reaches it. The robot reaches what its current
location reaches; handovers need the robot at one of ``handover_locations``.

Built-in names: ``paper2015`` (default), ``roboergosum``, and ``generated`` (seeded
random geometry, parameters after a colon: ``"generated:objects=6,spots=9,seed=3"``).
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

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


BUILTIN = ("paper2015", "roboergosum")
DEFAULT_SCENARIO = "paper2015"


def available_scenarios() -> tuple[str, ...]:
    """Names accepted by :func:`load_scenario` besides file paths."""
    return (*BUILTIN, "generated")


def load_scenario(spec: str | Path | Scenario) -> Scenario:
    """Return a scenario from a built-in name, ``generated:k=v,...``, or a TOML path.

    Raises:
        ScenarioError: unknown name, unreadable file, or a malformed field.
    """
    if isinstance(spec, Scenario):
        return spec
    text = str(spec)
    if text in BUILTIN:
        raw = resources.files("hg_marl.core.scenarios").joinpath(f"{text}.toml").read_text()
        return parse_scenario(tomllib.loads(raw), source=text)
    if text == "generated" or text.startswith("generated:"):
        params: dict[str, Any] = _parse_params(text.partition(":")[2])
        try:
            return generate_scenario(**params)
        except TypeError as exc:
            raise ScenarioError(
                f"generated scenario {text!r}: {exc} (parameters: objects, spots, locations, bins, human_only, seed)"
            ) from exc
    path = Path(text)
    if path.suffix != ".toml" or not path.is_file():
        raise ScenarioError(
            f"unknown scenario {text!r}: expected one of {', '.join(available_scenarios())} "
            "or the path of an existing .toml file"
        )
    try:
        data = tomllib.loads(path.read_text())
    except tomllib.TOMLDecodeError as exc:
        raise ScenarioError(f"scenario file {path}: not valid TOML: {exc}") from exc
    return parse_scenario(data, source=str(path))


def _parse_params(text: str) -> dict[str, int | float]:
    params: dict[str, int | float] = {}
    for item in filter(None, text.split(",")):
        key, sep, value = item.partition("=")
        if not sep:
            raise ScenarioError(f"generated scenario parameter {item!r}: expected key=value")
        try:
            params[key.strip()] = int(value) if value.strip().lstrip("-").isdigit() else float(value)
        except ValueError as exc:
            raise ScenarioError(f"generated scenario parameter {key!r}: not a number") from exc
    return params


class _Reader:
    """Typed access to raw TOML data that names the field in every error."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, path: str, message: str) -> ScenarioError:
        return ScenarioError(f"scenario {self.source}: field {path!r}: {message}")

    def get(self, data: Mapping[str, Any], key: str, kind: type, path: str, default: Any = ...) -> Any:
        if key not in data:
            if default is ...:
                raise self.fail(path, "missing")
            return default
        value = data[key]
        if kind is float and isinstance(value, int) and not isinstance(value, bool):
            value = float(value)
        if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
            raise self.fail(path, f"expected {kind.__name__}, got {type(value).__name__}")
        return value

    def names(
        self, data: Mapping[str, Any], key: str, path: str, known: Sequence[str], default: Any = ...
    ) -> tuple[int, ...]:
        values = self.get(data, key, list, path, default)
        out = []
        for i, value in enumerate(values):
            if value not in known:
                raise self.fail(f"{path}[{i}]", f"unknown name {value!r} (known: {', '.join(known)})")
            out.append(known.index(value))
        return tuple(out)

    def table_list(self, data: Mapping[str, Any], key: str) -> list[Mapping[str, Any]]:
        items = self.get(data, key, list, key)
        if not items:
            raise self.fail(key, "must not be empty")
        for i, item in enumerate(items):
            if not isinstance(item, dict):
                raise self.fail(f"{key}[{i}]", "expected a table")
        return items


def _unique(reader: _Reader, names: Sequence[str], path: str) -> None:
    seen: set[str] = set()
    for i, name in enumerate(names):
        if name in seen:
            raise reader.fail(f"{path}[{i}].name", f"duplicate name {name!r}")
        seen.add(name)


def parse_scenario(data: Mapping[str, Any], source: str = "<dict>") -> Scenario:
    """Validate raw scenario data (as read from TOML) into a :class:`Scenario`."""
    r = _Reader(source)
    name = r.get(data, "name", str, "name")
    locs = tuple(r.get(data, "robot_locations", list, "robot_locations"))
    if not locs or not all(isinstance(x, str) for x in locs):
        raise r.fail("robot_locations", "expected a non-empty list of names")

    def reach(item: Mapping[str, Any], path: str) -> Reach:
        return Reach(
            frozenset(r.names(item, "robot_reach", f"{path}.robot_reach", locs, [])),
            r.get(item, "human_reach", bool, f"{path}.human_reach", False),
        )

    objs = r.table_list(data, "objects")
    objects = tuple(r.get(o, "name", str, f"objects[{i}].name") for i, o in enumerate(objs))
    colours = tuple(r.get(o, "colour", str, f"objects[{i}].colour", "") for i, o in enumerate(objs))
    bins = tuple(
        Bin(
            r.get(b, "name", str, f"bins[{i}].name"),
            reach(b, f"bins[{i}]"),
            r.get(b, "colour", str, f"bins[{i}].colour", ""),
        )
        for i, b in enumerate(r.table_list(data, "bins"))
    )
    spots = tuple(
        Spot(r.get(s, "name", str, f"spots[{i}].name"), reach(s, f"spots[{i}]"))
        for i, s in enumerate(r.table_list(data, "spots"))
    )
    _unique(r, objects, "objects")
    _unique(r, [b.name for b in bins], "bins")
    _unique(r, [s.name for s in spots], "spots")
    for i, colour in enumerate(colours):
        if not any(b.colour in ("", colour) for b in bins):
            raise r.fail(f"objects[{i}].colour", f"no bin accepts colour {colour!r}")
    spot_names = [s.name for s in spots]
    layout = []
    used: set[int] = set()
    for i, g in enumerate(r.table_list(data, "layout")):
        count = r.get(g, "count", int, f"layout[{i}].count")
        pool = r.names(g, "spots", f"layout[{i}].spots", spot_names)
        if not 0 < count <= len(set(pool)):
            raise r.fail(
                f"layout[{i}].count", f"{count} objects need {count} distinct spots, the group lists {len(set(pool))}"
            )
        shared = used & set(pool)
        if shared:
            names = ", ".join(spot_names[k] for k in sorted(shared))
            raise r.fail(
                f"layout[{i}].spots", f"{names} already listed by an earlier group (groups must not share spots)"
            )
        used |= set(pool)
        layout.append(LayoutGroup(count, pool))
    if sum(g.count for g in layout) != len(objects):
        raise r.fail(
            "layout", f"counts add up to {sum(g.count for g in layout)}, expected {len(objects)} (one per object)"
        )
    handover = frozenset(r.names(data, "handover_locations", "handover_locations", locs))
    if not handover:
        raise r.fail("handover_locations", "must name at least one robot location")
    start = r.names(data, "robot_start", "robot_start", locs, [locs[0]])
    if not start:
        raise r.fail("robot_start", "must name at least one robot location")
    try:
        durations = Durations.from_mapping(r.get(data, "durations", dict, "durations", {}), f"scenario {source}")
    except ValueError as exc:
        raise ScenarioError(str(exc)) from exc
    return Scenario(
        name=name,
        objects=objects,
        object_colours=colours,
        bins=bins,
        spots=spots,
        robot_locations=locs,
        handover_locations=handover,
        robot_start=start,
        layout=tuple(layout),
        durations=durations,
        description=r.get(data, "description", str, "description", ""),
    )


def generate_scenario(
    objects: int = 4,
    spots: int | None = None,
    locations: int = 2,
    bins: int = 1,
    human_only: float = 0.3,
    seed: int = 0,
) -> Scenario:
    """A seeded random geometry for scaling tests.

    Args:
        objects: number of objects N.
        spots: number of spots M (default ``N + 2``); must be at least N.
        locations: robot locations; location 0 is next to the human.
        bins: bins; objects get colours so that each bin takes a share.
        human_only: probability that a spot is reachable by the human only, i.e. its
            object needs a human-to-robot handover or the human to throw it.
        seed: the generator's seed; same arguments, same scenario.
    """
    n_spots = objects + 2 if spots is None else int(spots)
    if objects < 1 or n_spots < objects or locations < 1 or bins < 1:
        raise ScenarioError(
            f"generated scenario: need objects >= 1, spots >= objects, locations >= 1, bins >= 1; "
            f"got objects={objects}, spots={n_spots}, locations={locations}, bins={bins}"
        )
    if not 0.0 <= human_only <= 1.0:
        raise ScenarioError(f"generated scenario: human_only={human_only} is not a probability")
    rng = np.random.default_rng(seed)
    locs = tuple(f"loc{i}" for i in range(locations))

    def robot_subset() -> frozenset[int]:
        k = int(rng.integers(1, locations + 1))
        return frozenset(int(x) for x in rng.choice(locations, size=k, replace=False))

    spot_list = []
    for s in range(n_spots):
        if rng.random() < human_only:
            reach = Reach(frozenset(), True)
        else:
            reach = Reach(robot_subset(), bool(rng.random() < 0.3))
        spot_list.append(Spot(f"spot{s}", reach))
    colours = [f"c{b}" for b in range(bins)] if bins > 1 else [""]
    bin_list = tuple(Bin(f"bin{b}", Reach(robot_subset(), bool(rng.random() < 0.3)), colours[b]) for b in range(bins))
    return Scenario(
        name=f"generated:objects={objects},spots={n_spots},locations={locations},bins={bins},"
        f"human_only={human_only},seed={seed}",
        objects=tuple(f"obj{i}" for i in range(objects)),
        object_colours=tuple(colours[i % len(colours)] for i in range(objects)),
        bins=bin_list,
        spots=tuple(spot_list),
        robot_locations=locs,
        handover_locations=frozenset({0}),
        robot_start=(0,),
        layout=(LayoutGroup(objects, tuple(range(n_spots))),),
        description="seeded random geometry",
    )
