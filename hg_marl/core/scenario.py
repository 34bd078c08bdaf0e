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

import re
import tomllib
from importlib import resources
from pathlib import Path

from hg_marl.core.errors import ScenarioError, SpecError, check_digits, read_limited
from hg_marl.core.scenario_file import NAME_PATTERN, RESERVED_NAMES, SCENARIO_NAME_PATTERN, parse_scenario
from hg_marl.core.scenario_file import _line_of as _line_of  # re-exported: tests read it here
from hg_marl.core.scenario_generated import generate_scenario
from hg_marl.core.scenario_model import (
    LIMITS,
    Bin,
    LayoutGroup,
    Reach,
    Scenario,
    ScenarioWarning,
    Spot,
    check_sizes,
    layout_count,
    solvability_problems,
)
from hg_marl.core.spec import bind, parse_spec, signature_defaults

__all__ = [
    "BUILTIN",
    "DEFAULT_SCENARIO",
    "LIMITS",
    "MAX_FILE_BYTES",
    "NAME_PATTERN",
    "RESERVED_NAMES",
    "SCENARIO_NAME_PATTERN",
    "Bin",
    "LayoutGroup",
    "Reach",
    "Scenario",
    "ScenarioError",
    "ScenarioWarning",
    "Spot",
    "available_scenarios",
    "check_sizes",
    "generate_scenario",
    "layout_count",
    "load_scenario",
    "parse_scenario",
    "resolve_scenario",
    "solvability_problems",
]

BUILTIN = ("paper2015", "roboergosum", "forced_coordination", "asymmetric_advantages")
DEFAULT_SCENARIO = "paper2015"


def available_scenarios() -> tuple[str, ...]:
    """Names accepted by :func:`load_scenario` besides file paths."""
    return (*BUILTIN, "generated")


def resolve_scenario(text: str) -> tuple[str, str]:
    """What a scenario spec names: ``("builtin", name)``, ``("generated", spec)`` or ``("file", path)``.

    The one place a name is told from a path, so the loader and a result's content key
    (``hg_marl.agents.content.scenario_content``) resolve a spec alike.

    Raises:
        ScenarioError: neither a built-in name, ``generated[:...]``, nor an existing ``.toml`` file.
    """
    if text in BUILTIN:
        return "builtin", text
    if text == "generated" or text.startswith("generated:"):
        return "generated", text
    if Path(text).suffix != ".toml" or not Path(text).is_file():
        raise ScenarioError(
            f"unknown scenario {text!r}: expected one of {', '.join(available_scenarios())} "
            "or the path of an existing .toml file"
        )
    return "file", text


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
    kind, _ = resolve_scenario(text)
    if kind == "builtin":
        raw = resources.files("hg_marl.core.scenarios").joinpath(f"{text}.toml").read_text(encoding="utf-8")
        return parse_scenario(tomllib.loads(raw), source=text, text=raw, strict=strict)
    if kind == "generated":
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
    content = read_limited(path, MAX_FILE_BYTES)
    if content is None:
        raise ScenarioError(f"scenario file {path}: larger than {MAX_FILE_BYTES} bytes")
    try:
        raw = content.decode("utf-8")
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
