"""Scenarios: the table's geometry and its layout distribution, as data.

A scenario is a TOML file (see ``scenarios/paper2015.toml`` for a commented example)
validated on load into a frozen :class:`Scenario`. A malformed file is rejected with a
:class:`ScenarioError` that names the file and the offending field, e.g.
``spots[2].robot_reach: unknown robot location 'kitchen' (known: bin_side, ...)``.

Geometry is reachability only: each spot and bin lists the robot locations it can be
reached from and whether the human reaches it. The robot reaches what its current
location reaches; handovers need the robot at one of ``handover_locations``.

Built-in names: ``paper2015`` (default), ``roboergosum``, the hard layouts ``forced_coordination`` and
``asymmetric_advantages`` (each file says what it tests), and ``generated`` (seeded
random geometry, parameters after a colon: ``"generated:objects=6,spots=9,seed=3"``,
read by the one spec parser of :mod:`hg_marl.core.spec`).

Strictness. Files must be UTF-8; unknown keys, duplicate names and non-finite or
non-positive durations are refused, with ``path:line`` found by searching the file's
text for the field. Sizes are bounded (:data:`LIMITS`, raised by environment variables)
and checked before anything is built. A layout where no agent can bring some object to
a bin loads with a :class:`ScenarioWarning` (``strict=True`` refuses it).
"""

from __future__ import annotations

import math
import os
import re
import tomllib
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.core.durations import Durations
from hg_marl.core.errors import HgMarlError, ScenarioError, SpecError, check_digits, check_int, check_probability, where
from hg_marl.core.spec import bind, parse_spec, signature_defaults


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


BUILTIN = ("paper2015", "roboergosum", "forced_coordination", "asymmetric_advantages")
DEFAULT_SCENARIO = "paper2015"


def _limit(name: str, default: int) -> int:
    """A size limit, raised by the environment variable ``HG_MARL_MAX_<NAME>``."""
    raw = os.environ.get(f"HG_MARL_MAX_{name.upper()}")
    if raw is None:
        return default
    try:
        return max(1, int(raw))
    except ValueError:
        raise ScenarioError(f"HG_MARL_MAX_{name.upper()}={raw!r}: expected an integer") from None


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


def available_scenarios() -> tuple[str, ...]:
    """Names accepted by :func:`load_scenario` besides file paths."""
    return (*BUILTIN, "generated")


def load_scenario(spec: str | Path | Scenario, *, strict: bool = False) -> Scenario:
    """Return a scenario from a built-in name, ``generated:k=v,...``, or a TOML path.

    Args:
        spec: the scenario.
        strict: refuse (instead of warn about) a layout some object of which no agent can
            bring to a bin.

    Raises:
        ScenarioError: unknown name, unreadable file, a malformed field (``path:line``
            where the file says it), a size over its limit, or (strict) an unsolvable layout.
    """
    if isinstance(spec, Scenario):
        return spec
    text = str(spec)
    if text in BUILTIN:
        raw = resources.files("hg_marl.core.scenarios").joinpath(f"{text}.toml").read_text(encoding="utf-8")
        return parse_scenario(tomllib.loads(raw), source=text, text=raw, strict=strict)
    if text == "generated" or text.startswith("generated:"):
        try:
            parsed = parse_spec(text, "generated scenario")
        except SpecError as exc:
            raise ScenarioError(str(exc)) from None
        params = bind(
            parsed,
            signature_defaults(generate_scenario),
            what=f"generated scenario {text!r}",
            error=ScenarioError,
        )
        return generate_scenario(**params)
    path = Path(text)
    if path.suffix != ".toml" or not path.is_file():
        raise ScenarioError(
            f"unknown scenario {text!r}: expected one of {', '.join(available_scenarios())} "
            "or the path of an existing .toml file"
        )
    if path.stat().st_size > MAX_FILE_BYTES:
        raise ScenarioError(f"scenario file {path}: larger than {MAX_FILE_BYTES} bytes")
    try:
        raw = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ScenarioError(
            f"scenario file {path}: not UTF-8 text (byte {exc.start}); TOML files must be UTF-8, re-save it as UTF-8"
        ) from None
    check_digits(raw, f"scenario file {path}", ScenarioError, lines=True)
    try:
        data = tomllib.loads(raw)
    except tomllib.TOMLDecodeError as exc:
        found = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        message = re.sub(r"\s*\(at line \d+, column \d+\)", "", str(exc))
        where_ = f"{path}:{found.group(1)}" if found else str(path)
        raise ScenarioError(f"scenario file {where_}: not valid TOML: {message}") from None
    except RecursionError:
        raise ScenarioError(f"scenario file {path}: nested too deeply") from None
    return parse_scenario(data, source=str(path), text=raw, strict=strict)


MAX_FILE_BYTES = 1 << 20
"""A scenario file may be at most 1 MiB."""


def _line_of(text: str, field: str) -> int | None:
    """The line of ``field`` (``spots[2].robot_reach[0]``) in a TOML text, when it can be found."""
    parts = re.findall(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?", field)
    if not parts:
        return None
    lines = text.splitlines()
    first, index = parts[0]
    start, end = 0, len(lines)
    if index:
        headers = [i for i, line in enumerate(lines) if re.match(rf"\s*\[\[\s*{first}\s*\]\]", line)]
        if int(index) >= len(headers):
            return _key_line(lines, first, 0, len(lines))
        start = headers[int(index)]
        end = next((i for i in range(start + 1, len(lines)) if re.match(r"\s*\[", lines[i])), len(lines))
        if len(parts) == 1:
            return start + 1
        return _key_line(lines, parts[1][0], start + 1, end) or start + 1
    table = next((i for i, line in enumerate(lines) if re.match(rf"\s*\[\s*{first}\s*\]", line)), None)
    if table is not None and len(parts) > 1:
        end = next((i for i in range(table + 1, len(lines)) if re.match(r"\s*\[", lines[i])), len(lines))
        return _key_line(lines, parts[1][0], table + 1, end) or table + 1
    if table is not None:
        return table + 1
    top_end = next((i for i, line in enumerate(lines) if re.match(r"\s*\[", line)), len(lines))
    return _key_line(lines, first, 0, top_end)


def _key_line(lines: list[str], key: str, start: int, end: int) -> int | None:
    for i in range(start, end):
        if re.match(rf"\s*{re.escape(key)}\s*=", lines[i]):
            return i + 1
    return None


class _Reader:
    """Typed access to raw TOML data that names the field in every error."""

    def __init__(self, source: str, text: str | None = None) -> None:
        self.source = source
        self.text = text

    def fail(self, path: str, message: str) -> ScenarioError:
        line = _line_of(self.text, path) if self.text is not None else None
        return ScenarioError(f"scenario {where(self.source, line)}: field {path!r}: {message}")

    def keys(self, data: Mapping[str, Any], allowed: Sequence[str], path: str) -> None:
        """Refuse keys the format does not know (a typo would otherwise be silently ignored)."""
        for key in data:
            if key not in allowed:
                field_ = f"{path}.{key}" if path else key
                raise self.fail(field_, f"unknown key (known: {', '.join(allowed)})")

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
                raise self.fail(f"{path}[{i}]", f"unknown name {value!r} (known: {', '.join(map(str, known))})")
            if known.index(value) in out:
                raise self.fail(f"{path}[{i}]", f"{value!r} listed twice")
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


NAME_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9_-]{0,63}")
"""What an object, bin, spot or robot location may be called: a letter then letters, digits,
``_`` or ``-``, at most 64 characters. Names appear inside action and fact names
(``place(tape1,mat_left)``) and in file names, so ``,``, ``(``, ``|``, ``/`` and spaces
would make two actions share one name or a path leave its folder."""

SCENARIO_NAME_PATTERN = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,63}")
"""What a scenario file's ``name`` may be: it becomes part of trace file names
(``play --record DIR``), so it holds no path separator and does not start with a dot."""

RESERVED_NAMES = frozenset({"human", "robot", "wait"})
"""Words the action and fact syntax already uses (``goto(human)``, ``hasInHand(robot,o)``)."""


def _check_name(reader: _Reader, name: str, path: str, pattern: re.Pattern[str] = NAME_PATTERN) -> None:
    if not pattern.fullmatch(name):
        raise reader.fail(
            path,
            f"name {name!r} must be a letter then letters, digits, '_' or '-' (at most 64 characters)"
            if pattern is NAME_PATTERN
            else f"name {name!r} must be letters, digits, '_', '-' or '.' (no path separator, at most 64 characters)",
        )
    if pattern is NAME_PATTERN and name.lower() in RESERVED_NAMES:
        raise reader.fail(path, f"name {name!r} is reserved by the action syntax ({', '.join(sorted(RESERVED_NAMES))})")


def _unique(reader: _Reader, groups: Sequence[tuple[str, Sequence[str]]]) -> None:
    """Every object, bin and spot name well formed and distinct from every other (across kinds)."""
    seen: dict[str, str] = {}
    for path, names in groups:
        for i, name in enumerate(names):
            field_ = f"{path}[{i}].name"
            _check_name(reader, name, field_)
            if name in seen:
                raise reader.fail(field_, f"duplicate name {name!r} (already used by {seen[name]})")
            seen[name] = field_


_TOP_KEYS = (
    "name",
    "description",
    "robot_locations",
    "handover_locations",
    "robot_start",
    "objects",
    "bins",
    "spots",
    "layout",
    "durations",
)
_ITEM_KEYS = {
    "objects": ("name", "colour"),
    "bins": ("name", "colour", "robot_reach", "human_reach"),
    "spots": ("name", "robot_reach", "human_reach"),
    "layout": ("count", "spots"),
}


def parse_scenario(
    data: Mapping[str, Any], source: str = "<dict>", *, text: str | None = None, strict: bool = False
) -> Scenario:
    """Validate raw scenario data (as read from TOML) into a :class:`Scenario`.

    Args:
        data: the parsed TOML.
        source: the file (or name) for messages.
        text: the file's text, to give ``path:line`` in messages.
        strict: refuse an unsolvable layout instead of warning.
    """
    r = _Reader(source, text)
    r.keys(data, _TOP_KEYS, "")
    for key, allowed in _ITEM_KEYS.items():
        items = data.get(key)
        if isinstance(items, list):
            for i, item in enumerate(items):
                if isinstance(item, dict):
                    r.keys(item, allowed, f"{key}[{i}]")
    name = r.get(data, "name", str, "name")
    _check_name(r, name, "name", SCENARIO_NAME_PATTERN)
    locs = tuple(r.get(data, "robot_locations", list, "robot_locations"))
    if not locs or not all(isinstance(x, str) for x in locs):
        raise r.fail("robot_locations", "expected a non-empty list of names")
    for i, loc in enumerate(locs):
        _check_name(r, loc, f"robot_locations[{i}]")
        if loc in locs[:i]:
            raise r.fail(f"robot_locations[{i}]", f"duplicate name {loc!r}")
    for key in ("objects", "spots", "bins"):
        if isinstance(data.get(key), list) and not data.get(key):
            raise r.fail(key, "must not be empty")
    check_sizes(
        source,
        len(data["objects"]) if isinstance(data.get("objects"), list) else 0,
        len(data["spots"]) if isinstance(data.get("spots"), list) else 0,
        len(data["bins"]) if isinstance(data.get("bins"), list) else 0,
        len(locs),
    )

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
    _unique(r, (("objects", objects), ("bins", [b.name for b in bins]), ("spots", [s.name for s in spots])))
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
    raw_durations = r.get(data, "durations", dict, "durations", {})
    try:
        durations = Durations.from_mapping(raw_durations, "scenario")
    except HgMarlError as exc:
        bad = next((k for k in raw_durations if f"durations.{k}'" in str(exc)), None)
        line = _line_of(text, f"durations.{bad}") if text is not None and bad else None
        raise ScenarioError(str(exc).replace("scenario:", f"scenario {where(source, line)}:", 1)) from None
    scenario = Scenario(
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
    problems = solvability_problems(scenario)
    if problems:
        more = f" (and {len(problems) - 1} more)" if len(problems) > 1 else ""
        message = f"scenario {source}: {problems[0]}{more}"
        if strict:
            raise ScenarioError(message)
        if message not in _WARNED:
            _WARNED.add(message)
            warnings.warn(message, ScenarioWarning, stacklevel=2)
    return scenario


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
    objects = check_int(objects, "generated scenario: objects", error=ScenarioError)
    spots = None if spots is None else check_int(spots, "generated scenario: spots", error=ScenarioError)
    locations = check_int(locations, "generated scenario: locations", error=ScenarioError)
    bins = check_int(bins, "generated scenario: bins", error=ScenarioError)
    seed = check_int(seed, "generated scenario: seed", minimum=0, error=ScenarioError)
    human_only = check_probability(human_only, "generated scenario: human_only", error=ScenarioError)
    n_spots = objects + 2 if spots is None else spots
    check_sizes("generated", objects, n_spots, bins, locations)
    if objects < 1 or n_spots < objects or locations < 1 or bins < 1:
        raise ScenarioError(
            f"generated scenario: need objects >= 1, spots >= objects, locations >= 1, bins >= 1; "
            f"got objects={objects}, spots={n_spots}, locations={locations}, bins={bins}"
        )
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
