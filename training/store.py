"""A results store keyed by content: a finished run is reused only when every input is the same.

A run's **key** is the SHA-256 of a canonical JSON document holding everything that
determines its result (:meth:`Job.key_fields`): the robot's and the human's registry
names and parameters, the scenario's *content* (the TOML text of a built-in or of a
file, or the ``generated:...`` spec, never just a file name), the simulated duration,
the seed, the decision-cost model, the runner's protocol switches, the package version
and a fingerprint of the code that plays the game (:func:`code_fingerprint`: the
sources of ``hg_marl``, ``hg_marl.agents`` and the runner). Any changed input gives a
new key, so a changed setting can never pick up an old run; nothing else (a label, an
output folder, the number of workers) enters the key.

API (all paths under the store's ``root``)::

    store = Store(root)
    job = Job(robot="hybrid", robot_params={"criterion": "vpi"}, human="lazy", seed=3)
    store.key(job)                  # 64 hex digits
    store.get(job)                  # a StoredRun, or None (missing, incomplete or being written)
    with store.claim(job.key()) as held:   # True: this process owns the job until the block ends
        if held and store.get(job, repair=True) is None:   # repair: corrupt -> one warning, removed
            store.put(job, run_result)     # atomic, fsynced, files 0644
    stored.summary, stored.tasks, stored.rate, stored.log()
    store.cached("oracle", {...}, compute)  # any other JSON result (oracle rates, training cells)

Layout: ``root/runs/<k[:2]>/<k>/{result.json,log.csv.gz}`` and
``root/cached/<kind>/<k>.json``; ``result.json`` is written last and holds the log's
SHA-256, so an entry is complete exactly when ``result.json`` parses, names its own key
and matches its log. Anything else (a truncated file, a log without its result, a
changed byte) is reported in one warning line, removed and run again by whoever holds
the claim (without the claim it may be an entry being written, and is only skipped).

Claims: ``root/claims/<k>.lock`` held with an exclusive ``flock``. The kernel drops the
lock when its process dies, so the claim of a killed study is taken over at once (the
file, which records the holder's pid for people, stays behind harmlessly). Whoever takes
a claim checks the store again before running, so two processes on one folder never run
the same job twice. (``flock`` needs a local or lock-aware file system; a multi-node Ray
study keeps its store on the driver's machine, which does all claiming and writing.)
"""

from __future__ import annotations

import contextlib
import fcntl
import functools
import gzip
import hashlib
import io
import json
import logging
import os
import shutil
import time
from collections.abc import Callable, Iterator, Mapping
from dataclasses import asdict, dataclass, field, is_dataclass
from importlib import resources
from pathlib import Path
from typing import Any

import pandas as pd

from hg_marl.training.io import atomic_write, write_json

log = logging.getLogger(__name__)

CLAIM_POLL = 0.2
"""Seconds between looks at a value another process is computing."""

SCHEMA = 1
"""Version of the entry layout; part of every key."""


@functools.cache
def code_fingerprint() -> str:
    """SHA-256 over the sources that decide a run's outcome (game, agents, runner).

    Why not the package version alone: in a working copy the version does not move when
    a rule, a robot or a default changes, and a store that trusted it would hand back
    results of the old code.
    """
    import hg_marl
    import hg_marl.agents
    import hg_marl.training.runner

    digest = hashlib.sha256()
    roots = [Path(hg_marl.__file__).parent, Path(hg_marl.agents.__file__).parent]
    files = sorted(f for r in roots for f in r.rglob("*.py") if "training" not in f.relative_to(r.parent).parts)
    files.append(Path(hg_marl.training.runner.__file__))
    for f in files:
        digest.update(f.name.encode())
        digest.update(f.read_bytes())
    return digest.hexdigest()


def scenario_content(scenario: str) -> str:
    """SHA-256 of what a scenario spec denotes: built-in or file TOML bytes, or the generator spec.

    Raises:
        ScenarioError: an unknown name or a missing file.
    """
    from hg_marl.core.scenario import BUILTIN, ScenarioError

    text = str(scenario)
    if text in BUILTIN:
        data = resources.files("hg_marl.core.scenarios").joinpath(f"{text}.toml").read_bytes()
    elif text == "generated" or text.startswith("generated:"):
        data = text.encode()
    else:
        path = Path(text)
        if not path.is_file():
            raise ScenarioError(f"unknown scenario {text!r}: not a built-in name and not an existing file")
        data = path.read_bytes()
    return hashlib.sha256(data).hexdigest()


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


def _plain_tree(value: Any) -> Any:
    """``value`` as the JSON it is keyed by."""
    return json.loads(canonical(value))


def content_key(kind: str, fields: Mapping[str, Any]) -> str:
    """The key of a result of ``kind`` made from ``fields`` (plus schema, version and code)."""
    import hg_marl

    doc = {"kind": kind, "schema": SCHEMA, "version": hg_marl.__version__, "code": code_fingerprint(), **fields}
    return hashlib.sha256(canonical(doc).encode()).hexdigest()


def default_cost_model() -> dict[str, Any]:
    """The robots' default decision-cost model, as stored in keys."""
    from hg_marl.agents.meta.cost import CostModel

    return asdict(CostModel())


@dataclass(frozen=True)
class Job:
    """One run: a robot with a human on a scenario for a simulated duration, from one seed."""

    robot: str
    """Robot registry name."""
    seed: int
    """Run seed."""
    scenario: str = "paper2015"
    """Scenario: built-in name, ``generated:...`` or a TOML path (keyed by content)."""
    duration: float = 1200.0
    """Simulated seconds."""
    human: str = "cooperative"
    """Human registry name."""
    robot_params: Mapping[str, Any] = field(default_factory=dict)
    """Keyword arguments of ``make_robot``."""
    human_params: Mapping[str, Any] = field(default_factory=dict)
    """Keyword arguments of ``make_human``."""
    label: str = ""
    """A name for people (a condition, a table row); not part of the key."""
    charge_decision_time: bool = True
    """The runner charges decision time to the clock."""

    def key_fields(self) -> dict[str, Any]:
        """Everything that determines this run's result."""
        return {
            "robot": {"name": self.robot, "params": dict(self.robot_params)},
            "human": {"name": self.human, "params": dict(self.human_params)},
            "scenario": scenario_content(self.scenario),
            "duration": float(self.duration),
            "seed": int(self.seed),
            "cost_model": _plain_tree(self.robot_params.get("cost", default_cost_model())),
            "charge_decision_time": self.charge_decision_time,
        }

    def key(self) -> str:
        """The content key of this run."""
        return content_key("run", self.key_fields())

    def describe(self) -> dict[str, Any]:
        """The job as plain JSON (stored beside its result for people)."""
        return {**asdict(self), "robot_params": dict(self.robot_params), "human_params": dict(self.human_params)}


@dataclass(frozen=True)
class StoredRun:
    """A finished run found in the store."""

    key: str
    """Its content key."""
    job: dict[str, Any]
    """The job that made it (plain JSON)."""
    summary: dict[str, Any]
    """The runner's summary (tasks solved, actions, ...)."""
    log_path: Path
    """Its per-decision log (gzipped CSV)."""

    @property
    def tasks(self) -> float:
        """Tasks solved."""
        return float(self.summary["tasks_solved"])

    @property
    def rate(self) -> float:
        """Tasks per simulated hour."""
        return self.tasks * 3600.0 / float(self.summary["duration"])

    def log(self) -> pd.DataFrame:
        """The per-decision log."""
        return pd.read_csv(self.log_path)


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


class Store:
    """Content-addressed results under one folder (see the module docstring)."""

    def __init__(self, root: str | Path) -> None:
        self.root = Path(root)

    def key(self, job: Job) -> str:
        """The job's content key."""
        return job.key()

    def entry(self, key: str) -> Path:
        """The folder of a run's entry."""
        return self.root / "runs" / key[:2] / key

    def get(self, job: Job, key: str | None = None, *, repair: bool = False) -> StoredRun | None:
        """The stored run of ``job``, or None.

        Args:
            job: the run.
            key: its key, when already computed.
            repair: the caller holds the job's claim, so an incomplete entry cannot be one
                being written right now: report it in one warning line and remove it.
                Without the claim an incomplete entry is only skipped.
        """
        key = key or job.key()
        folder = self.entry(key)
        if not folder.exists():
            return None
        problem = self._check(folder, key)
        if isinstance(problem, StoredRun):
            return problem
        if repair:
            log.warning("store: entry %s (%s) is %s; it will be run again", key[:12], job.label or job.robot, problem)
            shutil.rmtree(folder, ignore_errors=True)
        return None

    def _check(self, folder: Path, key: str) -> StoredRun | str:
        result, log_path = folder / "result.json", folder / "log.csv.gz"
        if not result.is_file():
            return "partial (no result.json)"
        try:
            data = json.loads(result.read_text())
        except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
            return f"corrupt (result.json unreadable: {str(exc).splitlines()[0]})"
        if not isinstance(data, dict) or data.get("key") != key or not isinstance(data.get("summary"), dict):
            return "corrupt (result.json does not describe this key)"
        if not log_path.is_file() or _sha256(log_path) != data.get("log_sha256"):
            return "corrupt (log missing or changed)"
        return StoredRun(key, data.get("job", {}), data["summary"], log_path)

    def put(self, job: Job, result: Any, key: str | None = None) -> StoredRun:
        """Store a finished ``RunResult`` of ``job``: the log first, then ``result.json``."""
        key = key or job.key()
        folder = self.entry(key)
        buffer = io.BytesIO()
        with gzip.GzipFile(fileobj=buffer, mode="wb", mtime=0) as gz:
            gz.write(result.log.to_csv(index=False).encode())
        log_path = atomic_write(folder / "log.csv.gz", lambda tmp: tmp.write_bytes(buffer.getvalue()))
        record = {
            "key": key,
            "job": job.describe(),
            "key_fields": job.key_fields(),
            "summary": result.summary,
            "log_sha256": _sha256(log_path),
        }
        write_json(folder / "result.json", record)
        return StoredRun(key, record["job"], dict(result.summary), log_path)

    @contextlib.contextmanager
    def claim(self, key: str) -> Iterator[bool]:
        """Hold the claim on ``key`` for the block: yields False when another live process holds it."""
        claims = self.root / "claims"
        claims.mkdir(parents=True, exist_ok=True)
        path = claims / f"{key}.lock"
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                yield False
                return
            os.ftruncate(fd, 0)
            os.write(fd, f"{os.getpid()}\n".encode())
            yield True
        finally:
            os.close(fd)

    def cached(self, kind: str, fields: Mapping[str, Any], compute: Callable[[], Any]) -> Any:
        """A JSON result of ``kind`` keyed by ``fields``: read from the store, or computed once and stored.

        The computation runs under the key's claim, so two processes asking for the same
        value compute it once (the second waits for the first's result).
        """
        key = content_key(kind, fields)
        path = self.root / "cached" / kind / f"{key}.json"
        while True:
            found = self._read_cached(path, key)
            if found is not None:
                return found[0]
            with self.claim(key) as held:
                if held:
                    found = self._read_cached(path, key, repair=True)
                    if found is not None:
                        return found[0]
                    value = compute()
                    write_json(path, {"key": key, "kind": kind, "fields": dict(fields), "value": value})
                    return value
            time.sleep(CLAIM_POLL)

    def _read_cached(self, path: Path, key: str, repair: bool = False) -> tuple[Any] | None:
        if not path.is_file():
            return None
        try:
            data = json.loads(path.read_text())
            if isinstance(data, dict) and data.get("key") == key and "value" in data:
                return (data["value"],)
        except (OSError, UnicodeDecodeError, json.JSONDecodeError):
            pass
        if repair:
            log.warning("store: cached %s %s is corrupt; computing it again", path.parent.name, key[:12])
            path.unlink(missing_ok=True)
        return None
