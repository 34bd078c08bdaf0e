"""Helpers shared by the subcommands: parsing ``key=value`` options, clean errors."""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable
from typing import Any, TypeVar

import typer

T = TypeVar("T")


def parse_params(items: Iterable[str] | None, what: str) -> dict[str, Any]:
    """Parse repeated ``key=value`` options; values are read as JSON when they can be."""
    params: dict[str, Any] = {}
    for item in items or ():
        key, sep, value = item.partition("=")
        if not sep or not key:
            raise typer.BadParameter(f"{what} parameter {item!r}: expected key=value")
        try:
            params[key] = json.loads(value)
        except json.JSONDecodeError:
            params[key] = value
    return params


def checked(build: Callable[[], T]) -> T:
    """Run ``build``; turn a ValueError/KeyError (unknown name, bad parameter) into a CLI error."""
    try:
        return build()
    except (ValueError, KeyError, FileNotFoundError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        typer.secho(f"error: {message}", fg=typer.colors.RED, err=True)
        raise typer.Exit(2) from exc
