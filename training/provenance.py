"""What a stored result depends on besides its settings: the files its specs name and the code that plays it.

Both feed the store's keys (:func:`hg_marl.training.store.content_key`), the way a
content-addressed build cache (Bazel, Nix, ccache) keys an action by the digests of its
input files and of its tool chain rather than by their names or a version number.

**Files** (:func:`named_files`): every text in a key's fields is looked at, inside
tables, lists and ``name:k=v`` specs (so ``switching:humans=cooperative|learned:path=m``
is searched too). A text that names an existing file, a folder holding a model header, or
a model stem (``m`` for ``m.json``) is keyed by its text *and* its content, as Bazel keys an
action by its inputs' paths and digests:

- a model header (``model.json``, ``policy.json``, a checkpoint's ``.json``; a folder
  holding one; its stem; its ``.npz``): the header's bytes and the bytes of the weights
  file it names (what :func:`hg_marl.agents.model_file.load_model_file` reads);
- any other file (a replay trace, a scenario): its bytes;
- a folder without a model header names nothing a loader reads, and is not keyed.

A file's digest is remembered per (path, inode, size, mtime, ctime), Bazel's and
ccache's stat cache, except for a file changed less than :data:`RACY_SECONDS` ago, which
is read again every time (git's rule for "racily clean" entries: a timestamp that
recent cannot tell two writes apart).

**Code** (:func:`code_modules`): the project modules a run can execute, found by a
static walk of the import graph from the modules that play a run (the backends'
``execute``, the runner) and from every registry target (each human's ``module:Class``,
each robot and criterion class). The walk reads every ``import`` statement, the ones
inside functions too, so lazily imported modules (the oracle, SB3 loading) are in; a
parent package is in with its child, since importing the child runs it. Why a static
walk and not ``sys.modules`` after importing the runner: what a process has imported
depends on what else it did first (the CLI, a test session), so the set and with it
every key would differ between ``hg-marl evaluate`` and ``hg-marl reproduce``; and lazy
imports would be missed. Why not a hand list: it goes stale (it missed
``training/backends.py``, which builds the actors). The fingerprint hashes each module's
syntax tree without docstrings, comments or line numbers, so editing documentation
keeps every stored result while any change to code invalidates it (ccache also hashes
what the compiler sees, not the file's bytes). The versions of the third-party
distributions the walk reaches (numpy, pandas, gymnasium, torch, SB3, ...) and the
Python version are part of it, as a Nix derivation's hash covers its dependencies.
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
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

from hg_marl.core.errors import HgMarlError

RACY_SECONDS = 2.0
"""A file modified less than this long ago is hashed again at every look (see the module docstring)."""

ROOTS = ("hg_marl.training.backends", "hg_marl.training.runner")
"""The modules that play a run; the walk also starts from every registry target."""

MAX_DEPTH = 32
"""Nesting depth (tables, lists, specs inside specs) up to which texts are looked at."""

PROJECT = "hg_marl"
"""Top-level package whose modules are fingerprinted by source; others by distribution version."""


# -- files ---------------------------------------------------------------------------------


def _sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


@functools.lru_cache(maxsize=4096)
def _cached_sha256(path: str, stamp: tuple[int, int, int, int]) -> str:
    return _sha256(Path(path))


def file_digest(path: Path) -> str:
    """The SHA-256 of a file's bytes (remembered while its stat stamp is unchanged and not racy)."""
    st = path.stat()
    if time.time() - st.st_mtime < RACY_SECONDS:
        return _sha256(path)
    return _cached_sha256(str(path.resolve()), (st.st_ino, st.st_size, st.st_mtime_ns, st.st_ctime_ns))


def _model_header(path: Path) -> tuple[Path, Path | None] | None:
    """The model header ``path`` denotes (as the model loaders resolve it) and its weights file, or None."""
    from hg_marl.agents.model_file import HEADER_NAMES, weights_file

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
    """The content a path-like text names, as ``{file name: sha256}``, or None when it names nothing.

    A model (header, its folder, stem or weights) is its header and weights; any other
    file is its bytes; a folder without a model header names nothing a loader reads.
    """
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
    """Every text in a JSON-like value, and the parameter values of every ``name:k=v`` spec among them.

    Specs nested deeper than :data:`MAX_DEPTH` are not opened (no registry nests so deep).
    """
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
    """The content of every existing file or folder a text in ``fields`` names, by the text."""
    return {text: found for text in sorted(set(_texts(fields))) if (found := path_content(text)) is not None}


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


def _source_file(name: str) -> tuple[Path, bool] | None:
    """The source file of a project module and whether it is a package (None: not a module)."""
    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError, AttributeError):
        return None
    if spec is None or not spec.origin or not spec.origin.endswith(".py"):
        return None
    return Path(spec.origin), spec.submodule_search_locations is not None


def registry_targets() -> set[str]:
    """The modules the registries build actors from (human targets, robot and criterion classes)."""
    from hg_marl.agents.humans.registry import HUMANS
    from hg_marl.agents.meta.registry import CRITERIA
    from hg_marl.agents.robots.registry import ROBOTS

    return {entry.module for registry in (HUMANS, ROBOTS, CRITERIA) for entry in registry.values()}


def code_modules(roots: tuple[str, ...] | None = None) -> tuple[dict[str, Path], set[str]]:
    """The project modules reachable from ``roots`` (default: :data:`ROOTS` and the registry targets).

    Returns:
        ``{module name: source file}`` of the project's modules, and the top-level names
        of the other (third-party or standard library) modules they import.
    """
    todo = sorted(set(roots) if roots is not None else {*ROOTS, *registry_targets()})
    found: dict[str, Path] = {}
    outside: set[str] = set()
    while todo:
        name = todo.pop()
        if name in found:
            continue
        top = name.partition(".")[0]
        if top != PROJECT:
            outside.add(top)
            continue
        located = _source_file(name)
        if located is None:
            continue
        path, is_package = located
        found[name] = path
        parents = [name.rsplit(".", i)[0] for i in range(1, name.count(".") + 1)]
        tree = ast.parse(path.read_bytes(), filename=str(path))
        todo.extend(m for m in (*parents, *_imports(tree, name, is_package)) if m not in found)
    return found, outside


def _without_docstrings(tree: ast.AST) -> ast.AST:
    """The tree minus every statement that is a bare string (docstrings; they cannot change a result)."""

    def text(s: ast.stmt) -> bool:
        return isinstance(s, ast.Expr) and isinstance(s.value, ast.Constant) and isinstance(s.value.value, str)

    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(body, list):
            node.body = [s for s in body if not text(s)]  # type: ignore[attr-defined]
    return tree


def source_digest(source: bytes, filename: str = "<module>") -> str:
    """SHA-256 of a module's code: its syntax tree without docstrings, comments or positions."""
    tree = _without_docstrings(ast.parse(source, filename=filename))
    return hashlib.sha256(ast.dump(tree, include_attributes=False).encode()).hexdigest()


def _versions(tops: set[str]) -> dict[str, str]:
    """Versions of the installed distributions that provide the top-level modules ``tops``."""
    providers = importlib.metadata.packages_distributions()
    out: dict[str, str] = {}
    for top in sorted(tops - set(sys.stdlib_module_names)):
        for dist in providers.get(top, []):
            try:
                out[dist] = importlib.metadata.version(dist)
            except importlib.metadata.PackageNotFoundError:
                continue
    return out


def fingerprint(modules: Mapping[str, Path], outside: set[str]) -> str:
    """SHA-256 over the modules' code digests, the third-party versions and the Python version."""
    doc = {
        "python": f"{sys.implementation.name}-{sys.version_info[0]}.{sys.version_info[1]}",
        "modules": {name: source_digest(path.read_bytes(), str(path)) for name, path in sorted(modules.items())},
        "libraries": _versions(outside),
    }
    return hashlib.sha256(json.dumps(doc, sort_keys=True).encode()).hexdigest()


@functools.cache
def code_fingerprint() -> str:
    """The fingerprint of the code that plays a run (computed once per process)."""
    return fingerprint(*code_modules())
