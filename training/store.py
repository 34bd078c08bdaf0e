"""A results store keyed by content: a finished run is reused only when every input is the same.

A run's **key** is the SHA-256 of a canonical JSON document (:func:`key_document`)
holding everything that determines its result, as a content-addressed build cache
(Bazel, Nix, ccache) keys an action by its inputs and its tool chain:

- the settings (:meth:`Job.key_fields`): the robot's and the human's registry names and
  parameters, the scenario's *content* (the TOML bytes of a built-in or a file, or the
  ``generated:...`` spec, never just a name), the simulated duration, the seed, the
  decision-cost model and the runner's protocol switches;
- the content of every file those settings name (:func:`~hg_marl.agents.content.named_files`):
  any text, also inside a nested ``name:k=v`` spec, that names an existing file, folder
  or model stem is keyed by its text and by the bytes the loaders read (a model header
  *and* the weights it names; a trace; a scenario), so a replaced ``learned:path=``,
  ``replay:path=`` or ``sb3:path=`` file gives a new key;
- the code (:func:`~hg_marl.agents.content.code_digest`): the project modules a
  run can execute, found by a static walk of the import graph from the backends, the
  runner and every registry target (function-level imports included), hashed without
  docstrings and comments; plus the third-party distributions' versions, the Python
  version, the package version and the entry :data:`SCHEMA`.

Any changed input gives a new key, so a changed setting, file or code can never pick up
an old run; nothing else (a label, an output folder, the backend, the number of workers)
enters the key. As in Bazel, inputs must not change *while* a study runs: a file replaced
between its hashing and its reading by a worker is stored under the old content's key.

API (all paths under the store's ``root``)::

    store = Store(root)
    job = Job(robot="hybrid", robot_params={"criterion": "vpi"}, human="lazy", seed=3)
    store.key(job)                  # 64 hex digits
    store.get(job)                  # a StoredRun, or None (missing, damaged or being written)
    with store.claim(job.key()) as held:   # True: this process owns the job until the block ends
        if held and store.get(job, repair=True) is None:   # repair: damaged -> one warning, removed
            store.put(job, run_result)     # atomic, fsynced, files 0644
    stored.summary, stored.tasks, stored.rate, stored.log()
    store.cached("oracle", {...}, compute)  # any other JSON result (oracle rates, training cells)

Layout: ``root/runs/<k[:2]>/<k>/{result.json,log.csv.gz}`` and
``root/cached/<kind>/<k>.json``. Every entry is **sealed** (:func:`seal`): it carries the
SHA-256 of its own canonical JSON, and ``result.json`` (written last) also the log's
SHA-256 and the whole key document, for people asking why a run was made. An entry is
used only when it parses as strict JSON (no ``NaN``/``Infinity``), names its own key,
matches its seal and its log, and its summary holds every field the runner writes
(:func:`hg_marl.training.runner.summarise`), each a finite number. Anything else (a
truncated file, a log without its result, a hand-edited count, a ``NaN``, a missing key)
is reported in one warning line saying what is wrong, removed and run again by whoever
holds the claim (without the claim it may be an entry being written, and is only
skipped). The seal detects damage and edits, not an adversary who recomputes it (that
would take a signing key; a store is as trusted as the folder it lives in).

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
import math
import os
import shutil
import time
from collections.abc import Callable, Iterator, Mapping
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from hg_marl.agents import content
from hg_marl.agents.content import canonical, registry_targets, scenario_content
from hg_marl.training.io import atomic_write, write_json

log = logging.getLogger(__name__)

CLAIM_POLL = 0.2
"""Seconds between looks at a value another process is computing."""

SCHEMA = 2
"""Version of the entry layout; part of every key (2: entries carry their own hash)."""


def _plain_tree(value: Any) -> Any:
    """``value`` as the JSON it is keyed by."""
    return json.loads(canonical(value))


ROOTS = ("hg_marl.training.backends", "hg_marl.training.runner")
"""The modules that play a run; the code digest also starts from every registry target."""


def code_roots() -> tuple[str, ...]:
    """Where the store's code digest starts: :data:`ROOTS` and every human, robot and criterion module."""
    from hg_marl.agents.humans.registry import HUMANS
    from hg_marl.agents.meta.registry import CRITERIA
    from hg_marl.agents.robots.registry import ROBOTS

    return (*ROOTS, *registry_targets(HUMANS, ROBOTS, CRITERIA))


def key_document(kind: str, fields: Mapping[str, Any]) -> dict[str, Any]:
    """Everything a result of ``kind`` made from ``fields`` depends on
    (:func:`hg_marl.agents.content.key_document`), the entry schema and the package version."""
    import hg_marl

    return {**content.key_document(kind, fields, code_roots()), "schema": SCHEMA, "version": hg_marl.__version__}


def content_key(kind: str, fields: Mapping[str, Any]) -> str:
    """The key of a result of ``kind`` made from ``fields``: the SHA-256 of its :func:`key_document`."""
    return hashlib.sha256(canonical(key_document(kind, fields)).encode()).hexdigest()


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
        """The run's settings (:func:`content_key` adds the files they name and the code)."""
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
        data = _read_entry(result, key)
        if isinstance(data, str):
            return data
        problem = _summary_problem(data.get("summary"))
        if problem:
            return problem
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
            "key_document": key_document("run", job.key_fields()),
            "summary": result.summary,
            "log_sha256": _sha256(log_path),
        }
        write_json(folder / "result.json", seal(record))
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
                    write_json(path, seal({"key": key, "kind": kind, "fields": dict(fields), "value": value}))
                    return value
            time.sleep(CLAIM_POLL)

    def _read_cached(self, path: Path, key: str, repair: bool = False) -> tuple[Any] | None:
        if not path.is_file():
            return None
        data = _read_entry(path, key)
        if isinstance(data, dict):
            if "value" in data:
                return (data["value"],)
            data = "incomplete (no 'value')"
        if repair:
            log.warning("store: cached %s %s is %s; computing it again", path.parent.name, key[:12], data)
            path.unlink(missing_ok=True)
        return None


def seal(record: Mapping[str, Any]) -> dict[str, Any]:
    """``record`` with its integrity hash: the SHA-256 of its canonical JSON, under ``sha256``."""
    body = {k: v for k, v in record.items() if k != "sha256"}
    return {**body, "sha256": hashlib.sha256(canonical(body).encode()).hexdigest()}


def _refuse_constant(name: str) -> Any:
    raise ValueError(f"non-finite number {name}")


def _read_entry(path: Path, key: str) -> dict[str, Any] | str:
    """A sealed entry of ``key``, or what is wrong with it (one phrase)."""
    try:
        data = json.loads(path.read_text(), parse_constant=_refuse_constant)
    except (OSError, UnicodeDecodeError, json.JSONDecodeError, RecursionError) as exc:
        return f"corrupt ({path.name} unreadable: {str(exc).splitlines()[0]})"
    except ValueError as exc:  # NaN, Infinity: never written by this store
        return f"non-finite ({path.name} holds a {str(exc).removeprefix('non-finite number ')})"
    if not isinstance(data, dict) or data.get("key") != key:
        return f"corrupt ({path.name} does not describe this key)"
    if not isinstance(data.get("sha256"), str):
        return f"incomplete ({path.name} has no sha256)"
    if seal(data)["sha256"] != data["sha256"]:
        return f"tampered ({path.name} does not match its sha256)"
    return data


@functools.cache
def _summary_template() -> dict[str, Any]:
    """What a run's summary holds: the runner's summary of an empty log (its one definition)."""
    from hg_marl.training.runner import COLUMNS, summarise

    return summarise(pd.DataFrame(columns=list(COLUMNS)), 1.0)


def _summary_problem(summary: Any) -> str | None:
    """Why a stored summary cannot be used (a missing key, a non-number where a number goes), or None."""
    if not isinstance(summary, dict):
        return "incomplete (no summary)"
    for name, template in _summary_template().items():
        if name not in summary:
            return f"incomplete (summary lacks {name!r})"
        value = summary[name]
        number = isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)
        if not number and not (template is None and value is None):
            return f"corrupt (summary {name!r} is {value!r}, not a finite number)"
    return None
