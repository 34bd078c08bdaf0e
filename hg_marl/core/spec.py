"""The one parser of ``name:k=v,k2=v2`` specs, shared by humans, robots, criteria and scenarios.

A spec names a registered thing and sets some of its parameters, so a command line, a
study file or a population list can say ``"lazy:p_idle=0.5"``,
``"hybrid:criterion=vpi"`` or ``"generated:objects=6,seed=3"``. Values are written as
JSON literals where that is natural (``0.5``, ``true``, ``[1, 2]``,
``{"features": "tabular"}``); a bare word is a string, and ``a|b`` is a list of strings.
Commas inside brackets, braces or quotes do not split parameters.

Parsing gives raw text; :func:`bind` converts each value against the parameter's
default (its type is the declared type) and refuses unknown keys, so every registry
converts values the same way and reports errors the same way: naming the spec and the
parameter. Numbers must be finite; a boolean is ``true``/``false``, never ``"no"``.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from hg_marl.core.errors import HgMarlError, SpecError, check_digits

REQUIRED: Any = None
"""Default marking a parameter with no default (e.g. a file path)."""


class _PythonOnly:
    """Marks a parameter that takes a Python object (a learner, a cost model): not settable in a spec."""

    def __repr__(self) -> str:
        return "<python object>"


PYTHON_ONLY: Any = _PythonOnly()


@dataclass(frozen=True)
class Spec:
    """A parsed spec: the registry name and the raw text of each parameter."""

    name: str
    """Registry name (before the colon)."""
    raw: Mapping[str, str] = field(default_factory=dict)
    """Parameter texts, in the order written."""

    def __str__(self) -> str:
        return format_spec(self.name, self.raw)


def _split_top_level(text: str, what: str = "spec") -> list[str]:
    """Split on commas that are not inside brackets, braces or double quotes.

    Raises:
        SpecError: a closing bracket with none open (past it no comma would split again).
    """
    parts: list[str] = []
    depth, quoted, escaped, start = 0, False, False, 0
    for i, ch in enumerate(text):
        if quoted:
            if escaped:
                escaped = False
            elif ch == "\\":
                escaped = True
            elif ch == '"':
                quoted = False
        elif ch == '"':
            quoted = True
        elif ch in "[{(":
            depth += 1
        elif ch in "]})":
            if depth == 0:
                raise SpecError(f"{what}: an unmatched {ch!r} (it closes nothing)")
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def split_specs(text: str) -> list[str]:
    """A comma list of specs: ``a,b:k=1,j=2,c`` -> ``[a, b:k=1,j=2, c]``.

    A piece ``k=v`` without a name continues the spec before it (command-line lists of
    humans or robots, ``--humans`` and ``--robots``).
    """
    out: list[str] = []
    for piece in (p.strip() for p in text.split(",")):
        if not piece:
            continue
        if out and "=" in piece and ":" not in piece and ":" in out[-1]:
            out[-1] += "," + piece
        else:
            out.append(piece)
    return out


def parse_spec(text: str | Spec, what: str = "spec") -> Spec:
    """Split ``"name:k=v,k2=v2"`` into a :class:`Spec` (values stay text until :func:`bind`).

    Args:
        text: the spec.
        what: how the caller names it in messages (``--human``, ``robots[2].spec``).

    Raises:
        SpecError: an empty name, a parameter without ``=``, or a repeated key.
    """
    if isinstance(text, Spec):
        return text
    if not isinstance(text, str):
        raise SpecError(f"{what}: expected a text like 'name:key=value', got {text!r}")
    name, _, rest = text.partition(":")
    name = name.strip()
    if not name:
        raise SpecError(f"{what} {text!r}: missing the name before ':'")
    items = _split_top_level(rest, f"{what} {text!r}") if rest.strip() else []
    return Spec(name, collect_params(items, f"{what} {text!r}", SpecError))


def split_param(item: str) -> tuple[str, str] | None:
    """One ``key=value`` item as stripped ``(key, raw value)``, or ``None`` without ``=`` or key.

    The one reading of a parameter item, for specs and for repeated ``--x-param`` options.
    """
    key, sep, value = item.partition("=")
    key = key.strip()
    return (key, value.strip()) if sep and key else None


def collect_params(items: Iterable[str], where: str, error: type[HgMarlError]) -> dict[str, str]:
    """``key=value`` items as raw texts by key: the one loop for specs and ``--x-param`` options.

    Raises:
        error: an item without ``=`` or a key given twice, the message starting with ``where``.
    """
    raw: dict[str, str] = {}
    for item in items:
        pair = split_param(item)
        if pair is None:
            raise error(f"{where}: expected key=value, got {item.strip()!r}")
        if pair[0] in raw:
            raise error(f"{where}: parameter {pair[0]!r} given twice")
        raw[pair[0]] = pair[1]
    return raw


def format_spec(name: str, params: Mapping[str, Any]) -> str:
    """The canonical text of a spec: keys sorted, values as compact JSON (strings bare)."""
    if not params:
        return name

    def text(v: Any) -> str:
        return v if isinstance(v, str) else json.dumps(v, sort_keys=True, separators=(",", ":"))

    return name + ":" + ",".join(f"{k}={text(params[k])}" for k in sorted(params))


def _literal(text: str) -> Any:
    try:
        return json.loads(text)
    except (json.JSONDecodeError, RecursionError):
        return text


def _kind(default: Any) -> str:
    if isinstance(default, bool):
        return "true or false"
    if isinstance(default, int):
        return "an integer"
    if isinstance(default, float):
        return "a finite number"
    if isinstance(default, list | tuple):
        return "a list"
    if isinstance(default, dict):
        return "a JSON object"
    return "a text"


def convert(value: Any, default: Any, what: str, *, from_text: bool) -> Any:
    """Convert one parameter to the type of its default.

    Args:
        value: the raw text (``from_text``) or a Python value given directly.
        default: the parameter's default; :data:`REQUIRED` (``None``) accepts any JSON value.
        what: the name used in messages (``human 'lazy': parameter 'p_idle'``).
        from_text: whether ``value`` is spec text to be read as a JSON literal first.

    Raises:
        SpecError: a value of the wrong type, or a NaN/infinite number.
    """
    text = value if from_text else None
    if isinstance(default, _PythonOnly):
        if from_text:
            raise SpecError(f"{what}: takes a Python object, not a value in a spec")
        return value
    if from_text:
        check_digits(value, what, SpecError)
        value = _literal(value)
        if isinstance(value, str) and value.lstrip()[:1] in ("{", "["):
            raise SpecError(f"{what}: not valid JSON: {text}")
    if isinstance(default, bool):
        if from_text and isinstance(value, str) and value.lower() in ("true", "false"):
            value = value.lower() == "true"
        if not isinstance(value, bool):
            raise SpecError(f"{what}: expected true or false, got {text if from_text else value!r}")
        return value
    if isinstance(default, int | float) and default is not None:
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise SpecError(f"{what}: expected {_kind(default)}, got {text if from_text else value!r}")
        if isinstance(value, float) and not math.isfinite(value):
            raise SpecError(f"{what}: expected a finite number, got {value!r}")
        if isinstance(default, int):
            if isinstance(value, float):
                if not value.is_integer():
                    raise SpecError(f"{what}: expected an integer, got {value!r}")
                value = int(value)
            return value
        return float(value)
    if isinstance(default, str):
        if from_text:
            return text
        if not isinstance(value, str):
            raise SpecError(f"{what}: expected a text, got {value!r}")
        return value
    if isinstance(default, list | tuple):
        if isinstance(value, str):
            value = [x for x in value.split("|") if x]
        if not isinstance(value, list | tuple):
            raise SpecError(f"{what}: expected a list, got {text if from_text else value!r}")
        _check_finite_tree(value, what)
        return list(value)
    if isinstance(default, dict):
        if not isinstance(value, dict):
            raise SpecError(f'{what}: expected a JSON object like {{"key": 1}}, got {text if from_text else value!r}')
        _check_finite_tree(value, what)
        return value
    # REQUIRED (None) or another type: take the value as given; text stays text unless
    # it is a JSON container or number.
    _check_finite_tree(value, what)
    return value


def _check_finite_tree(value: Any, what: str) -> None:
    if isinstance(value, float) and not math.isfinite(value):
        raise SpecError(f"{what}: expected finite numbers, got {value!r}")
    if isinstance(value, dict):
        for v in value.values():
            _check_finite_tree(v, what)
    elif isinstance(value, list | tuple):
        for v in value:
            _check_finite_tree(v, what)


def signature_defaults(factory: Any) -> dict[str, Any]:
    """A class's or function's keyword parameters and defaults (:data:`REQUIRED` when none)."""
    import inspect

    out: dict[str, Any] = {}
    for name, param in inspect.signature(factory).parameters.items():
        if param.kind in (param.VAR_POSITIONAL, param.VAR_KEYWORD) or name == "self":
            continue
        default = REQUIRED if param.default is param.empty else param.default
        if default is None:
            default = _placeholder(str(param.annotation))
        out[name] = default
    return out


def _placeholder(annotation: str) -> Any:
    """A default of the right type for a parameter whose default is None, read from its annotation.

    ``dict[...] | None`` takes a JSON object, ``str | Path | None`` a text, numbers a
    number; anything else (a class of the project) only a Python object.
    """
    kinds = {part.strip().split("[")[0] for part in annotation.replace("Optional[", "").split("|")}
    kinds.discard("None")
    if "dict" in kinds:
        return {}
    if kinds & {"str", "Path"}:
        return ""
    if "float" in kinds:
        return 0.0
    if "int" in kinds:
        return 0
    return PYTHON_ONLY


def bind(
    spec: Spec,
    defaults: Mapping[str, Any],
    overrides: Mapping[str, Any] | None = None,
    *,
    what: str,
    error: type[HgMarlError] = SpecError,
) -> dict[str, Any]:
    """Convert a spec's parameters (plus Python overrides) against the declared defaults.

    Args:
        spec: the parsed spec.
        defaults: accepted parameter names and their defaults (types).
        overrides: values given as Python objects (keyword arguments); they win over the spec.
        what: the thing's description in messages (``"human 'lazy'"``).
        error: the area's error type to raise.

    Returns:
        Only the parameters given (defaults are left to the constructor).

    Raises:
        error: an unknown parameter (the message lists the accepted ones) or a bad value.
    """
    given: dict[str, tuple[Any, bool]] = {k: (v, True) for k, v in spec.raw.items()}
    given.update({k: (v, False) for k, v in (overrides or {}).items()})
    out: dict[str, Any] = {}
    for key, (value, from_text) in given.items():
        if key not in defaults:
            accepted = ", ".join(f"{k}={v!r}" for k, v in defaults.items()) or "none"
            raise error(f"{what} has no parameter {key!r}; its parameters: {accepted}")
        if not from_text and (value is None or not isinstance(value, str | int | float | list | tuple | dict)):
            out[key] = value  # a Python object (a learner, a cost model): the constructor checks it
            continue
        try:
            out[key] = convert(value, defaults[key], f"{what}: parameter {key!r}", from_text=from_text)
        except SpecError as exc:
            raise error(str(exc)) from None
    return out


@dataclass(frozen=True)
class AgentSpec:
    """A spec parsed once, its values typed as JSON reads them: what a job carries to a worker, as data.

    Parsing and typing happen where the user's text is read (a command line, a study file,
    a population); from there on the name and the typed values travel as they are, so a
    worker builds the agent with ``make_robot(spec.name, **spec.params)`` and nothing
    parses the text again. Values are typed without the registry (``REQUIRED``: any JSON
    value), as a study file types them, so the same robot written either way keys the
    same runs; the registry still checks each value against its parameter's default when
    the agent is built.
    """

    name: str
    """Registry name."""
    params: Mapping[str, Any] = field(default_factory=dict)
    """Typed parameter values, in the order written."""

    def __str__(self) -> str:
        return format_spec(self.name, self.params)

    @classmethod
    def of(cls, spec: Spec, where: str) -> AgentSpec:
        """Type the values of a parsed spec; ``where`` starts each message (``--robots planner``).

        Raises:
            SpecError: a value that is not valid JSON where it looks like it, or a NaN/infinite number.
        """
        return cls(spec.name, {k: convert(v, REQUIRED, f"{where} {k}", from_text=True) for k, v in spec.raw.items()})

    @classmethod
    def parse(cls, text: str | AgentSpec, what: str = "spec", where: str | None = None) -> AgentSpec:
        """:func:`parse_spec` (messages name ``what``) then :meth:`of` (messages start ``where``, default ``what``)."""
        if isinstance(text, AgentSpec):
            return text
        return cls.of(parse_spec(text, what), what if where is None else where)
