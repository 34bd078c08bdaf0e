"""The trace format: JSON lines recording one seat's play, and a recorder for any actor.

A trace file holds one or more episodes. Each episode starts with a header line, then
one line per turn of the recorded seat::

    {"type": "header", "format": "hg_marl.trace", "version": 1, "episode": 0,
     "scenario": "paper2015", "seed": 3, "seat": "human", "actor": "cooperative",
     "fact_names": [...], "action_names": [...], "meta": {}}
    {"type": "step", "step": 0, "clock": 0.0, "tasks_solved": 0, "facts": [0, 1, ...],
     "mask": [1, 0, ...], "action": 17, "action_name": "wait"}

A recording of a person adds, in the header's ``meta``, who played (``player``), when
(``started``, ISO 8601 UTC), the front end and the robot's spec, and on each step line
the ``response_time`` in wall seconds, and an end line closes the episode with its
totals: ``{"type": "end", "clock": 93.4, "tasks_solved": 2, "rewards": 2.0}``.

``facts`` and ``mask`` are the seat's observation (what a learned policy or a person
sees), ``clock`` the simulated seconds at the turn. The same format holds recordings of
people playing the human (write them with :class:`TraceWriter`), replayed by
:class:`~hg_marl.agents.humans.replay.ReplayHuman` or used for behaviour cloning.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from types import TracebackType
from typing import IO, Any

import numpy as np

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.policy import Actor, Turn

FORMAT = "hg_marl.trace"
VERSION = 1


@dataclass
class Episode:
    """One recorded episode: its header and its steps, as read from the file."""

    header: dict[str, Any]
    """The header line (scenario, seed, seat, names, meta)."""
    steps: list[dict[str, Any]] = field(default_factory=list)
    """The step lines, in order."""
    end: dict[str, Any] = field(default_factory=dict)
    """The optional end line (final ``clock``, ``tasks_solved``, ``rewards``); empty if absent."""
    lines: list[int] = field(default_factory=list)
    """File line numbers of the header, each step and the end line (for ``path:line`` messages)."""

    @property
    def actions(self) -> list[int]:
        """The recorded action indices."""
        return [int(s["action"]) for s in self.steps]


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _check_header(record: dict[str, Any], at: str, line: str) -> None:
    if record.get("format") != FORMAT or record.get("version") != VERSION:
        raise ModelFileError(f"{at}: not a {FORMAT} v{VERSION} header: {line.strip()[:80]}")
    scenario = record.get("scenario")
    if not isinstance(scenario, str) or not 0 < len(scenario) <= 1024:
        raise ModelFileError(f"{at}: field 'scenario': expected a scenario name, got {scenario!r}")
    seed = record.get("seed")
    if seed is not None and (not _is_int(seed) or not 0 <= seed < 2**63):
        raise ModelFileError(f"{at}: field 'seed': expected an integer >= 0 or null, got {seed!r}")
    if not isinstance(record.get("actor", ""), str):
        raise ModelFileError(f"{at}: field 'actor': expected a string, got {record.get('actor')!r}")
    meta = record.get("meta", {})
    if not isinstance(meta, dict):
        raise ModelFileError(f"{at}: field 'meta': expected an object, got {type(meta).__name__}")
    for key in ("player", "robot", "started", "front_end"):
        if key in meta and not isinstance(meta[key], str):
            raise ModelFileError(f"{at}: field 'meta.{key}': expected a string, got {meta[key]!r}")
    for key in ("fact_names", "action_names"):
        names = record.get(key)
        if not isinstance(names, list) or not names or not all(isinstance(n, str) for n in names):
            raise ModelFileError(f"{at}: field {key!r}: expected a non-empty list of names")
    if record.get("seat") not in ("robot", "human"):
        raise ModelFileError(f"{at}: field 'seat': expected 'robot' or 'human', got {record.get('seat')!r}")


def _check_step(record: dict[str, Any], header: dict[str, Any], at: str) -> None:
    n_facts, names = len(header["fact_names"]), header["action_names"]
    action = record.get("action")
    if not isinstance(action, int) or isinstance(action, bool) or not 0 <= action < len(names):
        raise ModelFileError(f"{at}: field 'action': expected an action index in [0, {len(names)}), got {action!r}")
    if "action_name" in record and record["action_name"] != names[action]:
        raise ModelFileError(
            f"{at}: field 'action_name' {record['action_name']!r} is not action {action} ({names[action]!r})"
        )
    # Optional in the file (the index is what counts); filled from the header here, so
    # every reader of a step (replay, evaluate, the replay partner) finds it.
    record.setdefault("action_name", names[action])
    for key, size in (("facts", n_facts), ("mask", len(names))):
        values = record.get(key)
        if not isinstance(values, list) or len(values) != size or not all(_is_int(v) and v in (0, 1) for v in values):
            raise ModelFileError(f"{at}: field {key!r}: expected {size} values, each 0 or 1")
    if not _is_int(record.get("step")) or record["step"] < 0:
        raise ModelFileError(f"{at}: field 'step': expected a non-negative integer, got {record.get('step')!r}")
    _check_number(record, "clock", at, 0.0)
    tasks = record.get("tasks_solved", 0)
    if not _is_int(tasks) or tasks < 0:
        raise ModelFileError(f"{at}: field 'tasks_solved': expected an integer >= 0, got {tasks!r}")
    if "response_time" in record:
        _check_number(record, "response_time", at, 0.0, MAX_RESPONSE_TIME)


MAX_RESPONSE_TIME = 86_400.0
"""Longest response time (wall seconds) a step line may carry: one day."""


def _check_number(
    record: dict[str, Any], key: str, at: str, minimum: float | None, maximum: float | None = None
) -> float:
    """A finite number in range (``1e400`` parses as infinity and is refused here)."""
    value = record.get(key, 0.0)
    bad = isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value)
    if bad or (minimum is not None and value < minimum) or (maximum is not None and value > maximum):
        bounds = (
            f" in [{minimum:g}, {maximum:g}]"
            if maximum is not None
            else f" >= {minimum:g}"
            if minimum is not None
            else ""
        )
        raise ModelFileError(f"{at}: field {key!r}: expected a finite number{bounds}, got {value!r}")
    return float(value)


def _check_order(record: dict[str, Any], before: dict[str, Any] | None, at: str) -> None:
    """The clock and the solved-task count never go back; each turn solves at most two tasks.

    A cycle is one robot action and one human action, each of which solves at most one
    task (a ``throw``), so ``tasks_solved`` grows by at most 2 from one turn to the next
    (and from the last turn to the end line).
    """
    clock, tasks = float(record.get("clock", 0.0)), record.get("tasks_solved", 0)
    prev_clock = float(before.get("clock", 0.0)) if before else 0.0
    prev_tasks = int(before.get("tasks_solved", 0)) if before else 0
    if clock < prev_clock:
        raise ModelFileError(f"{at}: field 'clock': {clock:g} is before the previous line's {prev_clock:g}")
    if not prev_tasks <= tasks <= prev_tasks + 2:
        raise ModelFileError(
            f"{at}: field 'tasks_solved': {tasks} after {prev_tasks} on the previous line "
            "(a cycle solves at most 2 tasks and never loses one)"
        )


def _check_end(record: dict[str, Any], episode: Episode, at: str) -> None:
    _check_number(record, "clock", at, 0.0)
    _check_number(record, "rewards", at, None)
    tasks = record.get("tasks_solved", 0)
    if not _is_int(tasks):
        raise ModelFileError(f"{at}: field 'tasks_solved': expected an integer >= 0, got {tasks!r}")
    _check_order(record, episode.steps[-1] if episode.steps else None, at)


MAX_TRACE_BYTES = 64 << 20
"""A trace file may be at most 64 MiB. Read, a trace takes several times its size in
memory (a Python list per step's facts and mask), so the cap bounds what a read holds
while leaving room for far more moves than a person plays (the figures: ``docs/inputs.md``)."""

MAX_DECISION_CHARGE = 60.0
"""Most simulated seconds a robot decision may add to a cycle (its wall time, charged)."""


def trace_paths(path: str | Path) -> list[Path]:
    """A trace file, or every ``*.jsonl`` under a directory (sorted): what ``--traces DIR`` means.

    Raises:
        ConfigError: a missing path, or a directory without trace files.
    """
    path = Path(path)
    if path.is_dir():
        files = sorted(path.rglob("*.jsonl"))
        if not files:
            raise ConfigError(f"{path}: no *.jsonl trace files in this directory")
        return files
    if not path.exists():
        raise ConfigError(f"{path}: no such trace file or directory")
    return [path]


def read_trace(path: str | Path) -> list[Episode]:
    """Parse a trace file into its episodes, checking every line's shape and values.

    Raises:
        ModelFileError (a ValueError): missing, not UTF-8, a line that is not a JSON
            object, an unknown version, a step before any header, or a step whose action,
            facts or mask do not fit its header (``path:line`` named).
    """
    path = Path(path)
    if not path.is_file():
        raise ModelFileError(f"{path}: trace file not found")
    if path.stat().st_size > MAX_TRACE_BYTES:
        raise ModelFileError(f"{path}: larger than {MAX_TRACE_BYTES} bytes")
    episodes: list[Episode] = []
    with path.open(encoding="utf-8") as fh:
        try:
            for number, line in enumerate(fh, 1):
                if not line.strip():
                    continue
                at = f"{path}:{number}"
                try:
                    record = json.loads(line, parse_constant=_no_constant)
                except (json.JSONDecodeError, RecursionError, ValueError) as exc:
                    raise ModelFileError(f"{at}: not a JSON line ({exc})") from None
                if not isinstance(record, dict):
                    raise ModelFileError(f"{at}: expected a JSON object, got {type(record).__name__}")
                kind = record.get("type")
                if kind == "header":
                    _check_header(record, at, line)
                    episodes.append(Episode(record, lines=[number]))
                elif kind == "step":
                    if not episodes:
                        raise ModelFileError(f"{at}: step before any header line")
                    _check_step(record, episodes[-1].header, at)
                    _check_order(record, episodes[-1].steps[-1] if episodes[-1].steps else None, at)
                    episodes[-1].steps.append(record)
                    episodes[-1].lines.append(number)
                elif kind == "end" and episodes and episodes[-1].end:
                    raise ModelFileError(f"{at}: a second end line for the same episode")
                elif kind == "end" and episodes:
                    _check_end(record, episodes[-1], at)
                    episodes[-1].end = record
                    episodes[-1].lines.append(number)
                else:
                    raise ModelFileError(
                        f"{at}: unknown line type {kind!r} (expected 'header', 'step' or 'end' after a header)"
                    )
        except UnicodeDecodeError:
            raise ModelFileError(f"{path}{_undecodable_at(path)}: not UTF-8 text") from None
    if not episodes:
        raise ModelFileError(f"{path}: empty trace (no header line)")
    return episodes


_LINE_END = re.compile(rb"\r\n|\r|\n")
"""What ends a line in text mode (universal newlines), as :func:`read_trace` counts lines."""


def _undecodable_at(path: Path) -> str:
    """``:line`` of the file's first byte that is not UTF-8 (empty if it reads as UTF-8 now).

    Why not the reader's own count: a text file is decoded a chunk ahead of the lines
    read, so the error comes while the line before it, or one many lines before, is the
    last one read.
    """
    data = path.read_bytes()
    try:
        data.decode("utf-8")
    except UnicodeDecodeError as exc:
        return f":{len(_LINE_END.findall(data, 0, exc.start)) + 1}"
    return ""  # changed since the reader failed


def check_episode(episode: Episode, path: str | Path, seat: str | None = None) -> World:
    """Check a read episode against the scenario its header names; return that scenario's world.

    The header's fact and action names must be the scenario's for the recorded seat (a
    trace of another scenario, or crafted names, would be measured or replayed silently
    wrong), and no turn may come later than one cycle after the one before it: the
    scenario's longest action plus :data:`MAX_DECISION_CHARGE`. That bounds a replay's
    simulated time by the number of recorded moves (an end line saying ``"clock": 5e6``
    after three moves would replay for days).

    Raises:
        ModelFileError: naming ``path:line``.
    """
    from hg_marl.core.errors import HgMarlError
    from hg_marl.core.scenario import load_scenario

    h = episode.header
    at = f"{path}:{episode.lines[0] if episode.lines else 1}"
    if seat is not None and h["seat"] != seat:
        raise ModelFileError(f"{at}: field 'seat': {h['seat']!r}; this command reads traces of the {seat} seat")
    try:
        world = World(load_scenario(h["scenario"]))
    except HgMarlError as exc:
        raise ModelFileError(f"{at}: field 'scenario': {exc}") from None
    agent = Agent.ROBOT if h["seat"] == "robot" else Agent.HUMAN
    for key, names in (("fact_names", world.fact_names), ("action_names", world.action_names[agent])):
        if list(h[key]) != list(names):
            raise ModelFileError(
                f"{at}: field {key!r}: not the names of scenario {h['scenario']!r} for the {h['seat']} seat"
            )
    gap = world.durations.longest + MAX_DECISION_CHARGE
    records = [*episode.steps, *([episode.end] if episode.end else [])]
    previous = 0.0
    for k, record in enumerate(records):
        clock = float(record.get("clock", previous))
        if clock - previous > gap:
            line = episode.lines[k + 1] if k + 1 < len(episode.lines) else "?"
            raise ModelFileError(
                f"{path}:{line}: field 'clock': {clock:g} is {clock - previous:g} s after the previous turn, "
                f"longer than a cycle can last ({gap:g} s: the longest action plus {MAX_DECISION_CHARGE:g} s "
                "of robot decision)"
            )
        previous = clock
    return world


def _no_constant(name: str) -> Any:
    raise ValueError(f"{name} is not allowed")


class TraceWriter:
    """Appends episodes and steps to a trace file (also for recording people's play).

    Args:
        path: the file; truncated when the writer opens it.
    """

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self._fh: IO[str] | None = None
        self.episodes = 0
        self._steps = 0

    def _write(self, record: dict[str, Any]) -> None:
        if self._fh is None:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            self._fh = self.path.open("w")
        self._fh.write(json.dumps(record, separators=(",", ":")) + "\n")
        self._fh.flush()

    def header(
        self,
        world: World,
        agent: Agent,
        *,
        seed: int | None = None,
        actor: str = "",
        meta: dict[str, Any] | None = None,
    ) -> None:
        """Start an episode."""
        self._write(
            {
                "type": "header",
                "format": FORMAT,
                "version": VERSION,
                "episode": self.episodes,
                "scenario": world.scenario.name,
                "seed": seed,
                "seat": agent.label,
                "actor": actor,
                "fact_names": list(world.fact_names),
                "action_names": list(world.action_names[agent]),
                "meta": meta or {},
            }
        )
        self.episodes += 1
        self._steps = 0

    def step(self, turn: Turn, action: int, extra: dict[str, Any] | None = None) -> None:
        """Record the seat's observation at ``turn`` and the action it took.

        Args:
            turn: the seat's turn.
            action: the action taken.
            extra: further fields of the step line (a person's ``response_time``).
        """
        self._write(
            {
                "type": "step",
                "step": self._steps,
                "clock": float(turn.clock),
                "tasks_solved": int(turn.tasks_solved),
                "facts": np.asarray(turn.observation["observation"]).astype(int).tolist(),
                "mask": np.asarray(turn.mask).astype(int).tolist(),
                "action": int(action),
                "action_name": turn.world.action_names[turn.agent][action],
                **(extra or {}),
            }
        )
        self._steps += 1

    def end(self, clock: float, tasks_solved: int, rewards: float) -> None:
        """Close the episode with its totals (what a replay must reproduce)."""
        self._write(
            {"type": "end", "clock": float(clock), "tasks_solved": int(tasks_solved), "rewards": float(rewards)}
        )

    def close(self) -> None:
        """Close the file (further writes reopen it, truncating: open a new writer instead)."""
        if self._fh is not None:
            self._fh.close()
            self._fh = None

    def __enter__(self) -> TraceWriter:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()


class TraceRecorder:
    """Wraps any actor and records its play: one episode per :meth:`reset`.

    Args:
        actor: the actor whose decisions are recorded (unchanged).
        path: the trace file to write.
        seed: the environment seed to note in each header (optional, informative).
        meta: free-form data for the headers.
    """

    def __init__(
        self, actor: Actor, path: str | Path, seed: int | None = None, meta: dict[str, Any] | None = None
    ) -> None:
        self.actor = actor
        self.writer = TraceWriter(path)
        self.seed = seed
        self.meta = meta or {}
        self.name = getattr(actor, "name", type(actor).__name__)

    @property
    def last_decision(self) -> dict[str, Any]:
        """The wrapped actor's record of its last decision."""
        return dict(getattr(self.actor, "last_decision", None) or {})

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Reset the wrapped actor and start a new episode in the file."""
        self.actor.reset(world, agent, rng)
        self.writer.header(world, agent, seed=self.seed, actor=str(self.name), meta=self.meta)

    def act(self, turn: Turn) -> int:
        """Act as the wrapped actor and record the step."""
        action = self.actor.act(turn)
        self.writer.step(turn, action)
        return action

    def close(self) -> None:
        """Flush and close the trace file."""
        self.writer.close()


def behaviour_table(episodes: list[Episode]) -> dict[bytes, int]:
    """Behaviour cloning at its simplest: the most frequent recorded action per observation.

    The result is the ``table=`` of :func:`~hg_marl.agents.humans.learned.save_learned_policy`
    (keys: the fact vector as int8 bytes). Ties go to the lowest action index.
    """
    counts: dict[bytes, dict[int, int]] = {}
    for episode in episodes:
        for step in episode.steps:
            key = np.asarray(step["facts"], dtype=np.int8).tobytes()
            per = counts.setdefault(key, {})
            per[int(step["action"])] = per.get(int(step["action"]), 0) + 1
    return {key: min(per, key=lambda a: (-per[a], a)) for key, per in counts.items()}
