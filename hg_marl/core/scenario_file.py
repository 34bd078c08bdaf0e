"""Reading a scenario's TOML into a :class:`~hg_marl.core.scenario_model.Scenario`, strictly.

Unknown keys, duplicate names, bad references and non-finite or non-positive durations
are refused with ``path:line``, found by searching the file's text for the field.
:func:`hg_marl.core.scenario.load_scenario` reads the file and calls :func:`parse_scenario`.
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

from hg_marl.core.durations import Durations
from hg_marl.core.errors import HgMarlError, ScenarioError, where
from hg_marl.core.scenario_model import (
    _WARNED,
    Bin,
    LayoutGroup,
    Reach,
    Scenario,
    ScenarioWarning,
    Spot,
    check_sizes,
    solvability_problems,
)


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
