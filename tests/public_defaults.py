"""Read a module's public defaults the way a caller meets them: by importing it.

A *public default* is a value a caller gets without asking: a public upper-case constant
the module defines (``MAX_KEYS``), or a literal default of a parameter of a public function,
class (its constructor, dataclass fields included), method or command option (a typer
``Option``'s default). Only literals count (numbers, strings, booleans, ``None`` and tuples
or frozensets of them); an object built at import (a ``Path``, an enum, a config) is left
to the tests of its module. Names a module imports are its source module's, not its own.
"""

from __future__ import annotations

import ast
import enum
import importlib
import inspect
import pkgutil
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

PACKAGES = ("hg_marl", "hg_marl.agents", "hg_marl.training")
"""The project's three import roots (``agents/`` and ``training/`` install as subpackages)."""

MACHINE_DEPENDENT = frozenset(
    {
        "hg-marl evaluate --workers",
        "hg-marl headroom --jobs",
        "hg-marl population generate --workers",
        "hg-marl reproduce --workers",
    }
)
"""Defaults computed from the machine (its CPU count), so no file can pin them."""

SNAPSHOT = Path(__file__).resolve().parent / "data" / "public_defaults.json"
"""The pinned values: ``{module: {name: repr}}``, reviewed by hand when an API changes."""


def package_modules() -> list[str]:
    """Every module of the three packages, by its import name."""
    names = set(PACKAGES)
    for package in PACKAGES:
        path = importlib.import_module(package).__path__
        names.update(m.name for m in pkgutil.walk_packages(path, package + "."))
    return sorted(names)


def _is_literal(value: object) -> bool:
    if isinstance(value, enum.Enum):
        return False
    if isinstance(value, (bool, int, float, str, type(None))):
        return True
    return isinstance(value, (tuple, frozenset)) and all(_is_literal(v) for v in value)


def _shown(value: object) -> str:
    """``repr``, with a frozenset's members sorted (its own order follows the hash seed)."""
    if isinstance(value, frozenset):
        return f"frozenset({sorted(value, key=repr)!r})"
    return repr(value)


def _option_default(value: object) -> object:
    """A typer ``Option``/``Argument``'s default; any other default as it is."""
    return getattr(value, "default", value) if type(value).__name__ in ("OptionInfo", "ArgumentInfo") else value


def _parameters(function: Callable[..., Any], prefix: str) -> Iterator[tuple[str, object]]:
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):  # a builtin without a signature
        return
    for parameter in signature.parameters.values():
        default = _option_default(parameter.default)
        if parameter.default is not inspect.Parameter.empty and _is_literal(default):
            yield f"{prefix}({parameter.name})", default


def _assigned_here(module: Any) -> set[str]:
    """The names the module's own top level assigns (an import is not an assignment)."""
    file = getattr(module, "__file__", None)
    if file is None:
        return set()
    names: set[str] = set()
    for node in ast.parse(Path(file).read_text(encoding="utf-8")).body:
        targets = (
            node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) else []
        )
        names.update(t.id for t in targets if isinstance(t, ast.Name))
    return names


def public_defaults(name: str) -> dict[str, str]:
    """``{name: repr}`` of the module's public defaults (see the module docstring)."""
    module = importlib.import_module(name)
    own = _assigned_here(module)
    found: dict[str, object] = {}
    for attr, value in vars(module).items():
        if attr.startswith("_"):
            continue
        if attr.isupper() and attr in own and _is_literal(value) and f"{name}.{attr}" not in MACHINE_DEPENDENT:
            found[attr] = value
        if (inspect.isfunction(value) or inspect.isclass(value)) and value.__module__ == name:
            found.update(_parameters(value, attr))
            if inspect.isclass(value):
                for member, item in vars(value).items():
                    if member.startswith("_"):
                        continue
                    if isinstance(item, (staticmethod, classmethod)):
                        item = item.__func__
                    if inspect.isfunction(item):
                        found.update(_parameters(item, f"{attr}.{member}"))
                    elif member.isupper() and _is_literal(item):
                        found[f"{attr}.{member}"] = item
    return {key: _shown(found[key]) for key in sorted(found)}


def command_defaults() -> dict[str, dict[str, str]]:
    """``{"hg-marl CMD": {option: repr}}``: each command's literal option defaults, as ``--help`` shows them."""
    import typer.main

    from hg_marl.training.cli import app

    found: dict[str, dict[str, str]] = {}

    def walk(command: Any, path: str) -> None:
        for name, sub in sorted(getattr(command, "commands", {}).items()):
            walk(sub, f"{path} {name}")
        named = {max(p.opts, key=len): p.default for p in getattr(command, "params", [])}  # --long form
        options = {
            option: _shown(default)
            for option, default in named.items()
            if _is_literal(default) and default is not None and f"{path} {option}" not in MACHINE_DEPENDENT
        }
        if options:
            found[path] = dict(sorted(options.items()))

    walk(typer.main.get_command(app), "hg-marl")
    return found
