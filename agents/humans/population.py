"""Partner populations: named scripted humans split into ``train``, ``validation`` and ``held_out``.

A population file is TOML (``hg-marl population generate`` writes one; see
``populations/`` for the bundled ones)::

    name = "paper2015"                 # free text; optional (default: the file's name without .toml)
    scenario = "paper2015"             # what the members' behaviour was measured on
    description = "..."                # optional

    [generator]                        # optional: how it was made (informational)
    seed = 0
    candidates = 32
    robots = ["planner", "random"]     # reference robots of the measuring runs
    duration = 300.0
    seeds = 2
    method = "br-div-rbf-logdet"

    [spread.held_out]                  # optional: the selection criterion's value
    selected = 2.31                    # ... of this split's members
    random = -4.02                     # ... of random subsets of the same size (mean)

    [[members]]
    name = "m07"                       # short id: letters, digits, '_' or '-', unique
    split = "held_out"                 # train | validation | held_out
    spec = "preference:handover=0.8,shared=0.1"   # any stationary registry human
    behaviour = { give = 0.12, throw = 0.0 }      # optional: measured features

:func:`load_population` validates everything before anything runs (each spec is
built once; non-stationary humans are refused, since the oracle must model every
member); a bad field is reported as one :class:`PopulationError` line ``path:line:
field: problem``, found in the file's text the way scenario files are.
"""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hg_marl.core.errors import HgMarlError, PopulationError, check_digits, read_limited, where
from hg_marl.core.scenario import _line_of

SPLITS = ("train", "validation", "held_out")
"""The splits of a population, in file order."""

MAX_FILE_BYTES = 1 << 20
"""A population file may be at most 1 MiB."""

MAX_MEMBERS = 1000
"""At most this many members (each is built once when the file is loaded)."""

_NAME = re.compile(r"^[A-Za-z0-9_-]{1,32}$")
_TOP = ("name", "scenario", "description", "generator", "spread", "members")
_GENERATOR = ("seed", "candidates", "robots", "duration", "seeds", "method", "features")
_MEMBER = ("name", "split", "spec", "behaviour")


@dataclass(frozen=True)
class Member:
    """One partner of a population."""

    name: str
    """Short id (``m07``): the label a study reports it under."""
    spec: str
    """A human spec accepted by ``make_human`` and study files."""
    split: str
    """``train``, ``validation`` or ``held_out``."""
    behaviour: Mapping[str, float] = field(default_factory=dict)
    """Measured behaviour features (informational)."""


@dataclass(frozen=True)
class Population:
    """A validated population file."""

    name: str
    path: Path
    scenario: str
    train: tuple[Member, ...]
    validation: tuple[Member, ...]
    held_out: tuple[Member, ...]
    description: str = ""
    generator: Mapping[str, Any] = field(default_factory=dict)
    spread: Mapping[str, Mapping[str, float]] = field(default_factory=dict)

    def members(self, split: str = "all") -> tuple[Member, ...]:
        """The members of ``split`` (``all``: every member, train first).

        Raises:
            PopulationError: an unknown split.
        """
        if split == "all":
            return (*self.train, *self.validation, *self.held_out)
        if split not in SPLITS:
            raise PopulationError(f"unknown split {split!r}: expected one of {', '.join(SPLITS)} or all")
        return tuple(getattr(self, split))


class _Source:
    def __init__(self, path: Path, text: str) -> None:
        self.path, self.text = path, text

    def error(self, field_path: str, message: str) -> PopulationError:
        line = _line_of(self.text, field_path)
        return PopulationError(f"{where(self.path, line)}: {field_path}: {message}")


def _finite(value: Any) -> bool:
    return not isinstance(value, bool) and isinstance(value, int | float) and math.isfinite(value)


def _check_spec(spec: str) -> str | None:
    """Why ``spec`` cannot be a member (None: it can)."""
    from hg_marl.agents.humans.registry import HUMANS, make_human, parse_human

    try:
        name, _ = parse_human(spec)
        make_human(spec)
    except HgMarlError as exc:
        return str(exc)
    if not HUMANS[name].stationary:
        return f"human {name!r} is not stationary (the oracle must model every member)"
    return None


def _member(item: Any, index: int, src: _Source) -> Member:
    at = f"members[{index}]"
    if not isinstance(item, dict):
        raise src.error(at, "expected a table with name, split and spec")
    unknown = sorted(set(item) - set(_MEMBER))
    if unknown:
        raise src.error(f"{at}.{unknown[0]}", f"unknown field (expected {', '.join(_MEMBER)})")
    name, split, spec = item.get("name"), item.get("split"), item.get("spec")
    if not isinstance(name, str) or not _NAME.match(name):
        raise src.error(f"{at}.name", f"expected a short id of letters, digits, '_' or '-' (1-32), got {name!r}")
    if split not in SPLITS:
        raise src.error(f"{at}.split", f"expected one of {', '.join(SPLITS)}, got {split!r}")
    if not isinstance(spec, str) or not spec:
        raise src.error(f"{at}.spec", f"expected a human spec like 'preference:handover=0.8', got {spec!r}")
    problem = _check_spec(spec)
    if problem:
        raise src.error(f"{at}.spec", problem)
    behaviour = item.get("behaviour", {})
    if not isinstance(behaviour, dict) or not all(isinstance(k, str) and _finite(v) for k, v in behaviour.items()):
        raise src.error(f"{at}.behaviour", "expected a table of finite numbers")
    return Member(name, spec, split, {k: float(v) for k, v in behaviour.items()})


def _read(path: Path) -> tuple[str, dict[str, Any]]:
    if not path.is_file():
        raise PopulationError(f"{path}: no such population file")
    try:
        raw = read_limited(path, MAX_FILE_BYTES)
        if raw is None:
            raise PopulationError(f"{path}: larger than {MAX_FILE_BYTES} bytes")
        text = raw.decode("utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise PopulationError(f"{path}: cannot read the population file ({exc.__class__.__name__})") from None
    check_digits(text, str(path), PopulationError, lines=True)
    try:
        return text, tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        found = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        message = re.sub(r"\s*\(at line \d+, column \d+\)", "", str(exc))
        raise PopulationError(
            f"{where(path, int(found.group(1)) if found else None)}: not valid TOML: {message}"
        ) from None
    except RecursionError:
        raise PopulationError(f"{path}: nested too deeply") from None


def load_population(path: str | Path) -> Population:
    """Read and validate a population file.

    Raises:
        PopulationError: an unreadable file or a bad field (``path:line: field: problem``).
    """
    path = Path(path)
    text, data = _read(path)
    src = _Source(path, text)
    for key in data:
        if key not in _TOP:
            raise src.error(key, f"unknown field (expected one of {', '.join(_TOP)})")
    for key in ("name", "scenario", "description"):
        if key in data and not isinstance(data[key], str):
            raise src.error(key, "expected a text")
    generator = data.get("generator", {})
    if not isinstance(generator, dict):
        raise src.error("generator", "expected a table")
    for key in generator:
        if key not in _GENERATOR:
            raise src.error(f"generator.{key}", f"unknown field (expected one of {', '.join(_GENERATOR)})")
    spread = data.get("spread", {})
    if not isinstance(spread, dict):
        raise src.error("spread", "expected a table of splits")
    for split, values in spread.items():
        if split not in SPLITS:
            raise src.error(f"spread.{split}", f"unknown split (expected one of {', '.join(SPLITS)})")
        if not isinstance(values, dict) or not all(
            k in ("selected", "random") and _finite(v) for k, v in values.items()
        ):
            raise src.error(f"spread.{split}", "expected selected and random, finite numbers")
    items = data.get("members")
    if not isinstance(items, list) or not items:
        raise src.error("members", "expected at least one [[members]] table")
    if len(items) > MAX_MEMBERS:
        raise src.error("members", f"at most {MAX_MEMBERS} members, got {len(items)}")
    members = [_member(item, i, src) for i, item in enumerate(items)]
    seen: dict[str, int] = {}
    for i, m in enumerate(members):
        if m.name in seen:
            raise src.error(f"members[{i}].name", f"{m.name!r} is also members[{seen[m.name]}]'s name")
        seen[m.name] = i
    by_split = {s: tuple(m for m in members if m.split == s) for s in SPLITS}
    return Population(
        name=data.get("name", path.stem),
        path=path,
        scenario=data.get("scenario", ""),
        description=data.get("description", ""),
        generator=dict(generator),
        spread={k: dict(v) for k, v in spread.items()},
        **by_split,
    )
