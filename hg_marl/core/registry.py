"""One registry for every kind of named, parameterised thing: humans, robots, criteria.

A :class:`Registry` maps names to :class:`Entry` objects. An entry's target is a class
(or a ``"module:attr"`` text, imported on first use, so listing a registry imports
nothing heavy), and its parameters and their defaults are read from the target's
signature: the constructor is the one place a default is written. What the signature
cannot say, the entry adds: a one-line description, a line per parameter, and whether
the thing is stationary (has ``distribution(world, state)``).

``registry.make("lazy:p_idle=0.5")`` (or ``registry.make("lazy", p_idle=0.5)``) parses
the spec with the one spec parser (:mod:`hg_marl.core.spec`), types each value by its
default (:func:`~hg_marl.core.spec.bind`) and builds the thing; an unknown name, an
unknown parameter, a bad value or the constructor's own ``ValueError``/``TypeError``
becomes the registry's error type, naming the thing and listing what exists.
"""

from __future__ import annotations

import importlib
import inspect
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any

from hg_marl.core.errors import HgMarlError, SpecError
from hg_marl.core.spec import PYTHON_ONLY, REQUIRED, bind, parse_spec, signature_defaults


@dataclass(frozen=True)
class Param:
    """A parameter as listed: its default (the constructor's; None when required) and what it does."""

    default: Any
    """The constructor's default (``None``: required, or a Python object)."""
    doc: str
    """One line: what it changes."""


@dataclass(frozen=True)
class Entry:
    """A registered thing: a name, what builds it, and what the signature cannot say."""

    name: str
    """Registry name."""
    target: str | Callable[..., Any]
    """The class (or factory) building it, or ``"module:attr"`` to import it on demand."""
    doc: str = ""
    """One line: how it behaves."""
    param_docs: Mapping[str, str] = field(default_factory=dict)
    """A line per parameter (listings); parameters without one are listed with an empty line."""
    stationary: bool = True
    """Whether it has ``distribution(world, state)`` (humans: the oracle can use it)."""

    def factory(self) -> Callable[..., Any]:
        """The class (imported now when the target is a text)."""
        if isinstance(self.target, str):
            module, _, attr = self.target.partition(":")
            factory: Callable[..., Any] = getattr(importlib.import_module(module), attr)
            return factory
        return self.target

    @property
    def module(self) -> str:
        """The module defining the target (read without importing it)."""
        if isinstance(self.target, str):
            return self.target.partition(":")[0]
        return self.target.__module__

    def defaults(self) -> dict[str, Any]:
        """Every parameter with a default typed for :func:`~hg_marl.core.spec.bind` (from the signature)."""
        return signature_defaults(self.factory())

    @property
    def params(self) -> dict[str, Param]:
        """The parameters a spec can set, with the constructor's defaults and their lines."""
        typed = self.defaults()
        out = {}
        for name, p in inspect.signature(self.factory()).parameters.items():
            if name not in typed or typed[name] is PYTHON_ONLY:
                continue
            default = REQUIRED if p.default is p.empty else p.default
            out[name] = Param(list(default) if isinstance(default, tuple) else default, self.param_docs.get(name, ""))
        return out


class Registry(Mapping[str, Entry]):
    """Named entries of one kind, built from specs (see the module docstring).

    Args:
        kind: what the entries are, in messages (``"human"``, ``"robot"``, ``"criterion"``).
        error: the area's error type.
        entries: the entries, or classes with a ``name`` attribute (an entry each).
        list_params: whether an unknown name's message lists each entry's parameters too.
    """

    def __init__(
        self,
        kind: str,
        error: type[HgMarlError],
        entries: Iterable[Entry | type],
        list_params: bool = False,
    ) -> None:
        self.kind, self.error, self.list_params = kind, error, list_params
        self._entries: dict[str, Entry] = {}
        for e in entries:
            entry = e if isinstance(e, Entry) else Entry(str(getattr(e, "name")), e)  # noqa: B009 (a class attribute)
            self._entries[entry.name] = entry

    def __getitem__(self, name: str) -> Entry:
        return self._entries[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._entries)

    def __len__(self) -> int:
        return len(self._entries)

    def listing(self) -> str:
        """What exists, for messages: the names (with their parameters when ``list_params``)."""
        if not self.list_params:
            return ", ".join(self._entries)
        return "; ".join(
            f"{n}({', '.join(f'{k}={p.default!r}' for k, p in e.params.items())})" for n, e in self._entries.items()
        )

    def lookup(self, name: str) -> Entry:
        """The entry called ``name``; an unknown one raises the registry's error listing what exists."""
        entry = self._entries.get(name)
        if entry is None:
            raise self.error(f"unknown {self.kind} {name!r}; available: {self.listing()}")
        return entry

    def make(self, text: str, **params: Any) -> Any:
        """Build from a spec (``"name:k=v,..."``) plus keyword parameters (they win)."""
        try:
            spec = parse_spec(text, self.kind)
        except SpecError as exc:
            raise self.error(str(exc)) from None
        entry = self.lookup(spec.name)
        kwargs = bind(spec, entry.defaults(), params, what=f"{self.kind} {spec.name!r}", error=self.error)
        try:
            return entry.factory()(**kwargs)
        except HgMarlError:
            raise
        except (TypeError, ValueError) as exc:
            raise self.error(f"{self.kind} {spec.name!r}: {exc}") from None
