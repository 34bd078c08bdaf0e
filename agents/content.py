"""Content keys: the one home of what a stored or cached result is keyed by.

Every result kept for reuse (the results store's runs and cached values, the compiled
partners and robot, the oracle's results) is keyed by :func:`content_key`: the SHA-256 of
a canonical JSON document (:func:`key_document`) holding the settings that made it, the
content of every file those settings name (:func:`named_files`) and a digest of the code
that computes it (:func:`code_digest`), as a content-addressed build cache (Bazel, Nix,
ccache) keys an action by the digests of its input files and of its tool chain rather
than by their names or a version number. A changed setting, named file or module gives a
new key, so an old result is never picked up; anything else keeps the key.

**Files** (:func:`named_files`): every text in the settings is looked at, inside tables,
lists and ``name:k=v`` specs (so ``switching:humans=cooperative|learned:path=m`` is
searched too). A text that names an existing file, a folder holding a model header, or a
model stem (``m`` for ``m.json``) is keyed by its text *and* by the bytes the loaders read:

- a model (a header, its folder, stem or ``.npz``): the header's bytes and those of the
  weights file it names (what :func:`hg_marl.agents.model_file.load_model_file` reads);
- any other file (a replay trace, a scenario): its bytes;
- a folder without a model header names nothing a loader reads, and is not keyed.

A scenario given by name is keyed by what the name denotes (:func:`scenario_content`: the
bundled TOML's bytes, a file's bytes, or the ``generated:`` spec). A file's digest is
remembered per (path, inode, size, mtime, ctime), Bazel's and ccache's stat cache, except
for a file changed less than :data:`RACY_SECONDS` ago, which is read again every time
(git's rule for "racily clean" entries: a timestamp that recent cannot tell two writes
apart).

**Code** (:func:`code_digest`): the project modules a result can execute, found by a static
walk of the import graph from the modules the caller names (its *roots*: the module that
computes the result and every registry target it may build by name). The walk reads every
``import`` statement, the ones inside functions too, so lazily imported modules are in; a
parent package is in with its child, since importing the child runs it. So the list of
keyed sources is derived, never written by hand (a hand list goes stale: the store's once
missed ``training/backends.py``, which builds the actors), and a module no root reaches
never changes a key. Why a static walk and not ``sys.modules``: what a process has
imported depends on what else it did first, so keys would differ between commands. Each
module is hashed as its syntax tree without docstrings, comments or positions, so editing
documentation keeps every result while any change to code invalidates it (ccache also
hashes what the compiler sees). The versions of the third-party distributions the walk
reaches and the Python version are part of it, as a Nix derivation's hash covers its
dependencies. It is computed once per process and set of roots (the code a process runs
is the code it imported when it started).
"""

from __future__ import annotations

import ast
import functools
import hashlib
import importlib.metadata
import importlib.util
import json
import os
import sys
import time
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import asdict, is_dataclass
from importlib import resources
from pathlib import Path
from typing import Any

from hg_marl.agents.model_format import HEADER_NAMES, weights_file
from hg_marl.core.errors import HgMarlError
from hg_marl.core.registry import Registry

RACY_SECONDS = 2.0
"""A file modified less than this long ago is hashed again at every look (see the module docstring)."""

MAX_DEPTH = 32
"""Nesting depth (tables, lists, specs inside specs) up to which texts are looked at."""

PROJECT = "hg_marl"
"""Top-level package whose modules are keyed by source; others by their distribution's version."""


# -- canonical documents ------------------------------------------------------------------


def canonical(value: Any) -> str:
    """Canonical JSON (sorted keys, no spaces): equal inputs, equal text."""
    return json.dumps(value, sort_keys=True, separators=(",", ":"), default=_plain, allow_nan=False)


def _plain(value: Any) -> Any:
    if is_dataclass(value) and not isinstance(value, type):
        return asdict(value)
    if isinstance(value, tuple | set | frozenset):
        return sorted(value) if isinstance(value, set | frozenset) else list(value)
    if isinstance(value, Path):
        return str(value)
    raise TypeError(f"not a JSON value: {value!r}")


def key_document(kind: str, fields: Mapping[str, Any], roots: Iterable[str]) -> dict[str, Any]:
    """Everything a result of ``kind`` made from ``fields`` depends on: the fields, the content of every
    file they name, and the digest of the code reachable from the modules ``roots``."""
    return {"kind": kind, "code": code_digest(roots), "files": named_files(fields), **fields}


def content_key(kind: str, fields: Mapping[str, Any], roots: Iterable[str]) -> str:
    """The key of a result of ``kind`` made from ``fields`` by the code of ``roots``: SHA-256 of its document."""
    return hashlib.sha256(canonical(key_document(kind, fields, roots)).encode()).hexdigest()


# -- files ---------------------------------------------------------------------------------


def _sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _stamp(path: Path) -> tuple[int, int, int, int] | None:
    """The stat stamp a cached digest of ``path`` is valid for; None while the file is racily new."""
    st = path.stat()
    if time.time() - st.st_mtime < RACY_SECONDS:
        return None
    return (st.st_ino, st.st_size, st.st_mtime_ns, st.st_ctime_ns)


@functools.lru_cache(maxsize=4096)
def _cached_sha256(path: str, stamp: tuple[int, int, int, int]) -> str:
    return _sha256(Path(path))


def file_digest(path: Path) -> str:
    """The SHA-256 of a file's bytes (remembered while its stat stamp is unchanged and not racy)."""
    stamp = _stamp(path)
    return _sha256(path) if stamp is None else _cached_sha256(str(path.resolve()), stamp)


def _model_header(path: Path) -> tuple[Path, Path | None] | None:
    """The model header ``path`` denotes (as the model loaders resolve it) and its weights file, or None."""
    if path.is_dir():
        header = next((path / n for n in HEADER_NAMES if (path / n).is_file()), None)
    else:
        header = path.with_suffix(".json") if path.suffix in ("", ".npz") else path
    if header is None or header.suffix != ".json" or not header.is_file():
        return None
    try:
        data = json.loads(header.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError, RecursionError):
        return None
    if not isinstance(data, dict) or "file" not in data:
        return None
    try:
        weights: Path | None = weights_file(header, data)
    except HgMarlError:  # a header the loader refuses: its own bytes are the content
        weights = None
    return header, weights


def path_content(text: str) -> dict[str, str] | None:
    """The content a path-like text names, as ``{file name: sha256}``, or None when it names nothing."""
    if not text or len(text) > 4096 or "\0" in text:
        return None
    path = Path(text)
    try:
        model = _model_header(path)
        if model is not None:
            header, weights = model
            out = {header.name: file_digest(header)}
            if weights is not None and weights.is_file():
                out[weights.name] = file_digest(weights)
            return out
        return {path.name: file_digest(path)} if path.is_file() else None
    except (OSError, ValueError):
        return None


def _texts(value: Any, depth: int = 0) -> Iterator[str]:
    """Every text in a JSON-like value, and the parameter values of every ``name:k=v`` spec among them."""
    from hg_marl.core.spec import parse_spec

    if depth > MAX_DEPTH:
        return
    if isinstance(value, Mapping):
        for item in value.values():
            yield from _texts(item, depth + 1)
    elif isinstance(value, list | tuple):
        for item in value:
            yield from _texts(item, depth + 1)
    elif isinstance(value, str | os.PathLike):
        text = os.fspath(value)
        yield text
        if ":" not in text and "|" not in text and not text.startswith("["):
            return
        try:
            parsed: Any = json.loads(text)
        except (ValueError, RecursionError):
            parsed = None
        if isinstance(parsed, list | dict):
            yield from _texts(parsed, depth + 1)
            return
        if "|" in text:
            yield from _texts(text.split("|"), depth + 1)
        try:
            raw = parse_spec(text).raw
        except HgMarlError:
            return
        for item in raw.values():
            if len(item) < len(text):
                yield from _texts(item, depth + 1)


def named_files(fields: Mapping[str, Any]) -> dict[str, dict[str, str]]:
    """The content of every existing file or model a text in ``fields`` names, by the text."""
    return {text: found for text in sorted(set(_texts(fields))) if (found := path_content(text)) is not None}


def scenario_content(scenario: str) -> str:
    """SHA-256 of what a scenario spec denotes (:func:`hg_marl.core.scenario.resolve_scenario`).

    Raises:
        ScenarioError: an unknown name or a missing file.
    """
    from hg_marl.core.scenario import resolve_scenario

    kind, what = resolve_scenario(str(scenario))
    if kind == "file":
        return file_digest(Path(what))
    data = (
        resources.files("hg_marl.core.scenarios").joinpath(f"{what}.toml").read_bytes() if kind == "builtin" else what
    )
    return hashlib.sha256(data if isinstance(data, bytes) else data.encode()).hexdigest()


# -- code ----------------------------------------------------------------------------------


def _imports(tree: ast.AST, name: str, is_package: bool) -> set[str]:
    """Every module an import statement anywhere in ``tree`` may load (function-level ones included)."""
    package = name if is_package else name.rpartition(".")[0]
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            module = node.module or ""
            base = importlib.util.resolve_name("." * node.level + module, package) if node.level else module
            out.add(base)
            out.update(f"{base}.{alias.name}" for alias in node.names)  # `from package import submodule`
    return out


def source_file(name: str) -> tuple[Path, bool] | None:
    """The source file of a module and whether it is a package (None: not a Python source module)."""
    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError, AttributeError):
        return None
    if spec is None or not spec.origin or not spec.origin.endswith(".py"):
        return None
    return Path(spec.origin), spec.submodule_search_locations is not None


def _without_docstrings(tree: ast.AST) -> ast.AST:
    """The tree minus every statement that is a bare string (docstrings; they cannot change a result)."""

    def text(s: ast.stmt) -> bool:
        return isinstance(s, ast.Expr) and isinstance(s.value, ast.Constant) and isinstance(s.value.value, str)

    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(body, list):
            node.body = [s for s in body if not text(s)]  # type: ignore[attr-defined]
    return tree


def module_digest(source: bytes, filename: str = "<module>") -> str:
    """SHA-256 of a module's code: its syntax tree without docstrings, comments or positions."""
    tree = _without_docstrings(ast.parse(source, filename=filename))
    return hashlib.sha256(ast.dump(tree, include_attributes=False).encode()).hexdigest()


def _read_module(path: Path, name: str, is_package: bool) -> tuple[frozenset[str], str]:
    source = path.read_bytes()
    imports = _imports(ast.parse(source, filename=str(path)), name, is_package)
    return frozenset(imports), module_digest(source, str(path))


@functools.lru_cache(maxsize=4096)
def _cached_module(
    path: str, name: str, is_package: bool, stamp: tuple[int, int, int, int]
) -> tuple[frozenset[str], str]:
    return _read_module(Path(path), name, is_package)


def _module(path: Path, name: str, is_package: bool) -> tuple[frozenset[str], str]:
    """A module's imports and code digest (remembered per stat stamp, as :func:`file_digest`)."""
    stamp = _stamp(path)
    if stamp is None:
        return _read_module(path, name, is_package)
    return _cached_module(str(path), name, is_package, stamp)


def code_modules(roots: Iterable[str]) -> tuple[dict[str, str], set[str]]:
    """The project modules reachable from ``roots`` by import statements, and what lies outside.

    Returns:
        ``{module name: code digest}`` of the project's modules, and the top-level names of
        the other (third-party or standard library) modules they import.
    """
    todo = sorted(set(roots))
    found: dict[str, str] = {}
    outside: set[str] = set()
    while todo:
        name = todo.pop()
        if name in found:
            continue
        top = name.partition(".")[0]
        if top != PROJECT:
            outside.add(top)
            continue
        located = source_file(name)
        if located is None:
            continue
        path, is_package = located
        imports, found[name] = _module(path, name, is_package)
        parents = [name.rsplit(".", i)[0] for i in range(1, name.count(".") + 1)]
        todo.extend(m for m in (*parents, *sorted(imports)) if m not in found)
    return found, outside


@functools.lru_cache(maxsize=64)
def _versions(tops: frozenset[str]) -> tuple[tuple[str, str], ...]:
    """Versions of the installed distributions that provide the top-level modules ``tops``."""
    providers = importlib.metadata.packages_distributions()
    out: dict[str, str] = {}
    for top in sorted(tops - set(sys.stdlib_module_names)):
        for dist in providers.get(top, []):
            try:
                out[dist] = importlib.metadata.version(dist)
            except importlib.metadata.PackageNotFoundError:
                continue
    return tuple(sorted(out.items()))


_DIGESTS: dict[tuple[Any, tuple[str, ...]], str] = {}


def code_digest(roots: Iterable[str]) -> str:
    """SHA-256 over the code digests of the modules reachable from ``roots``, the third-party
    distributions' versions and the Python version.

    Computed once per process and set of roots: the code a process runs is the code it
    imported, and a study keys thousands of results. :func:`forget_code` drops what was
    computed (tests that edit a copy of the sources call it).
    """
    memo = (source_file, tuple(sorted(set(roots))))
    found = _DIGESTS.get(memo)
    if found is None:
        found = _DIGESTS[memo] = _code_digest(memo[1])
    return found


def forget_code() -> None:
    """Forget the code digests computed so far (the next :func:`code_digest` walks the sources again)."""
    _DIGESTS.clear()


def _code_digest(roots: tuple[str, ...]) -> str:
    modules, outside = code_modules(roots)
    doc = {
        "python": f"{sys.implementation.name}-{sys.version_info[0]}.{sys.version_info[1]}",
        "modules": modules,
        "libraries": dict(_versions(frozenset(outside))),
    }
    return hashlib.sha256(canonical(doc).encode()).hexdigest()


def registry_targets(*registries: Registry, names: Iterable[str] | None = None) -> tuple[str, ...]:
    """The modules the ``registries`` build their entries from (only the entries ``names`` when given).

    The caller passes its registries: this module imports none, so the code it keys is only
    what each caller's roots reach.
    """
    wanted = None if names is None else set(names)
    return tuple(
        sorted(
            {
                entry.module
                for registry in registries
                for name, entry in registry.items()
                if wanted is None or name in wanted
            }
        )
    )
