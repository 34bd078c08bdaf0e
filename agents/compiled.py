"""Compiled partners: a stationary scripted human as an action distribution per reachable state.

A stationary human (every registry human the registry marks stationary: not ``switching``,
``replay`` or the family-out partners that follow a clock or their own history,
``fo_after_waits``, ``fo_bursts``, ``fo_forgetful`` and ``fo_slow_start``; ``learned``
in its numpy kinds, not SB3's, which the batched env runs as one forward pass per step
instead: ``agents/batched_learned.py``)
answers as a function of the mid-cycle state and the robot's action seen
(``StationaryHuman.distribution``). :func:`compile_human` builds the answers with the
model builder (:func:`answer_table`: every mid-cycle state the robot-turn states of the
scenario can reach, whatever the robot does, the oracle's exploration on arrays; the
human answered on arrays, once per canonical key, or live once per key, as the
builder's :class:`~hg_marl.agents.models.AnswerTable` does) and stores them in flat
arrays: sorted packed keys, segment starts, actions and cumulative probabilities.
:class:`CompiledHuman` then answers a whole batch with two ``searchsorted`` calls (the
``ArrayPartner`` protocol of ``hg_marl.envs.batched``). A state outside the table (it
cannot happen for a table compiled for the same scenario and durations, but a caller
may hand any state) falls back to the live human, counted in ``fallbacks``.

Built once per (scenario, durations, human spec) and cached on disk, keyed by the
content of all that plus the code of every module that can change an answer (those this
module and the humans import, found by :mod:`hg_marl.agents.content`); the entry stores
its key and is refused if it does not match. Nothing is written outside a folder the user named:
``cache=FOLDER`` keeps the tables there (``hg-marl train --algo ppo_batched`` uses
``OUT/partners``), ``cache=True`` uses ``$HG_MARL_CACHE/partners`` when that variable is
set and no disk cache otherwise, ``cache=None`` never caches on disk: a large scenario's
table is as large as the oracle's model, so it is built once and then loaded (sizes and
build times: ``docs/batched.md``, compiled partners).
"""

from __future__ import annotations

import io
import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hg_marl.agents import content
from hg_marl.agents.humans.base import HumanError
from hg_marl.agents.humans.registry import HUMANS, make_human
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchedRules, BatchState

if TYPE_CHECKING:
    from hg_marl.agents.models import AnswerTable

MAX_KEYS = 5_000_000
"""The compiler's budget: (mid-cycle state, robot action seen) keys; beyond it, a clear error."""

_KEY_LIMIT = 2**62
OUTCOME_FIELDS = ("where", "robot_at", "offer_by", "offer_obj", "ok", "duration", "facts", "mask")


class CompileError(HumanError):
    """A partner that cannot be compiled, or a scenario over the compiler's budget."""


class Packer:
    """Packs (state, robot action seen) into one int64 per table: mixed-radix digits."""

    def __init__(self, world: World) -> None:
        t = world.table
        self.radix = [t.n_places] * t.n_objects + [t.n_locations, 3, t.n_objects + 1, world.n_actions(Agent.ROBOT) + 1]
        total = 1
        for r in self.radix:
            total *= r
        if total >= _KEY_LIMIT:
            raise CompileError(
                f"scenario: {world.scenario.name!r} has too many states to pack into 64-bit keys "
                f"({t.n_objects} objects, {t.n_places} places): over the compiler's budget"
            )
        weights, w = [], 1
        for r in self.radix:
            weights.append(w)
            w *= r
        self.weights = np.array(weights, dtype=np.int64)
        self.n_objects = t.n_objects

    def pack(self, b: BatchState, seen: np.ndarray) -> np.ndarray:
        """(N,) int64 keys."""
        w, n = self.weights, self.n_objects
        key = b.where @ w[:n]
        key += b.robot_at * w[n] + (b.offer_by + 1) * w[n + 1] + (b.offer_obj + 1) * w[n + 2] + (seen + 1) * w[n + 3]
        return key

    def pack_one(self, state: State, seen: int) -> int:
        """The key of one state."""
        digits = [*state.where, state.robot_at, state.offer_by + 1, state.offer_obj + 1, seen + 1]
        return int(sum(d * int(w) for d, w in zip(digits, self.weights, strict=True)))


def answer_table(
    world: World, human: Any, max_keys: int = MAX_KEYS, progress: bool = False, closure: Sequence[Any] = ()
) -> AnswerTable:
    """Every (mid-cycle state, robot action seen) the human can face, with its distribution, as arrays.

    The model builder's closure (``agents/models/builder.py``, the oracle's exploration):
    robot-turn states from the layout distribution and, breadth-first, from every robot
    action (feasible ones and one failing one: all failing actions lead to the same
    mid-cycle state) followed by every answer of the human and of the ``closure`` humans
    (a switching partner's other phases reach states this one alone never would; only
    ``human``'s answers are kept). The re-drawn tables meet the human after the robot's
    ``wait`` (continuing mode); the completing ``wait`` is followed by the human's move on
    the clean table (episodic mode), asked here as the builder does not go on from it.
    """
    from hg_marl.agents.models import AnswerTable, Budget, OverBudget, StatePacker, build_model
    from hg_marl.agents.models.layouts import layout_distribution

    name = getattr(human, "name", human)
    budget = Budget(None, None, max_keys, subject=f"scenario: {world.scenario.name!r} against {name!r}")
    packer = StatePacker(world)
    tables = [AnswerTable(world, h, packer, budget) for h in (human, *closure)]
    try:
        model = build_model(world, tables, layout_distribution(world), budget=budget, progress=progress)
    except OverBudget as over:
        if over.resource == "machine":  # the machine is short of memory, not the table too big: say so
            raise CompileError(str(over)) from over
        model = None
    table = tables[0]
    if model is not None:
        clean, _ = packer.unpack(model.keys[model.pair_state()[model.pair_terminal]])
        seen = np.full(len(clean), world.table.wait[Agent.ROBOT] if table.uses_robot_action else -1)
        table.ensure(np.unique(packer.pack(clean, seen)))
    if model is None or len(table.keys) > max_keys:
        raise CompileError(
            f"scenario: {world.scenario.name!r} against {name!r} exceeds the compiler's budget of {max_keys} "
            "states (max_keys); use a smaller scenario"
        )
    return table


class CompiledHuman:
    """A stationary human's answers as arrays (the ``ArrayPartner`` protocol).

    Args:
        world: the world it was compiled for.
        human: the live human (the fallback for a state outside the table).
        arrays: ``keys`` (sorted), ``starts``, ``actions``, ``cum`` (see :meth:`from_answers`).
    """

    def __init__(self, world: World, human: Any, arrays: dict[str, np.ndarray], name: str = "") -> None:
        self.world, self.human = world, human
        self.name = name or str(getattr(human, "name", "human"))
        self.uses_robot_action = bool(getattr(human, "uses_robot_action", False))
        self.packer = Packer(world)
        self.keys, self.starts = arrays["keys"], arrays["starts"]
        self.actions, self.cum = arrays["actions"], arrays["cum"]
        self.outcome = {k: arrays[k] for k in OUTCOME_FIELDS}
        """Per entry, the human's answer already applied by ``BatchedRules``: the next state
        (``where``, ``robot_at``, ``offer_by``, ``offer_obj``), ``ok``, ``duration``, and that
        state's ``facts`` and robot ``mask`` (the batched env gathers them instead of
        stepping the rules and computing observations again)."""
        self.widest = int(np.diff(self.starts).max(initial=1))
        """The most actions any state's distribution has (the sampler's loop length)."""
        self.fallbacks = 0
        """Tables answered by the live human because their state was not in the table."""

    @staticmethod
    def arrays_of(world: World, table: AnswerTable) -> dict[str, np.ndarray]:
        """The flat arrays of an answer table; ``cum`` is segment index + cumulative probability.

        Each entry's outcome is computed by ``BatchedRules`` on the whole table at once.
        """
        keys, starts, entries = table.compact()
        actions, probs = entries["actions"], entries["probs"]
        sizes = np.diff(starts)
        cum = np.empty(len(actions))
        for size in np.unique(sizes).tolist():  # per segment: cumsum / sum, last one exactly 1
            if size == 0:
                continue
            seg = np.flatnonzero(sizes == size)
            at = starts[seg][:, None] + np.arange(size)
            p = probs[at]
            c = np.cumsum(p, axis=1) / p.sum(axis=1)[:, None]
            c[:, -1] = 1.0
            cum[at] = seg[:, None] + c
        rules = BatchedRules(world)
        mids, _ = table.packer.unpack(np.repeat(keys, sizes))
        ok, duration, _ = rules.step(mids, Agent.HUMAN, actions)
        return {
            "keys": keys,
            "starts": starts,
            "actions": actions,
            "cum": cum,
            "where": mids.where,
            "robot_at": mids.robot_at,
            "offer_by": mids.offer_by,
            "offer_obj": mids.offer_obj,
            "ok": ok,
            "duration": duration,
            "facts": rules.facts(mids),
            "mask": rules.masks(mids, Agent.ROBOT),
        }

    def lookup(self, b: BatchState, seen: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(segment index, found) per table."""
        keys = self.packer.pack(b, seen if self.uses_robot_action else np.full(len(b), -1, dtype=np.int64))
        idx = np.searchsorted(self.keys, keys)
        idx = np.minimum(idx, len(self.keys) - 1)
        return idx, self.keys[idx] == keys

    def distribution(self, b: BatchState, seen: np.ndarray, i: int) -> list[tuple[int, float]]:
        """Table ``i``'s distribution as the compiled table holds it (tests compare it with the live one)."""
        idx, found = self.lookup(b, seen)
        if not found[i]:
            raise KeyError(f"state {b.state(i)} is not in the compiled table")
        lo, hi = self.starts[idx[i]], self.starts[idx[i] + 1]
        c = self.cum[lo:hi] - idx[i]
        return [
            (int(a), float(p)) for a, p in zip(self.actions[lo:hi], np.diff(np.concatenate([[0.0], c])), strict=True)
        ]

    def answer(self, b: BatchState, seen: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(entry, found) per table: the compiled distribution sampled with ``rng``.

        ``actions[entry]`` is the answer and ``outcome[...][entry]`` its effect where
        ``found``; elsewhere the entry is meaningless (see :meth:`act` for the fallback).
        """
        idx, found = self.lookup(b, seen)
        q = idx + rng.random(len(b))
        start, last = self.starts[idx], self.starts[idx + 1] - 1
        pos = start.copy()
        for j in range(self.widest - 1):  # entries before the drawn one: their cumulative sum is <= q
            at = np.minimum(start + j, last)
            pos += (start + j < last) & (self.cum[at] <= q)
        return pos, found

    def act(self, b: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """One action per table: the compiled distribution sampled with ``rng``, the live human outside it."""
        pos, found = self.answer(b, seen, rng)
        out = self.actions[pos]
        return self.fall_back(b, seen, rng, out, found)

    def fall_back(
        self, b: BatchState, seen: np.ndarray, rng: np.random.Generator, out: np.ndarray, found: np.ndarray
    ) -> np.ndarray:
        """``out`` with the tables not ``found`` answered by the live human (counted in ``fallbacks``)."""
        if not found.all():
            missing = np.flatnonzero(~found)
            self.fallbacks += len(missing)
            for i in missing:
                s = b.state(int(i))
                dist = self.human.distribution(self.world, s, int(seen[i]) if self.uses_robot_action else -1)
                p = np.array([q for _, q in dist])
                out[i] = dist[int(rng.choice(len(dist), p=p / p.sum()))][0] if len(dist) > 1 else dist[0][0]
        return out

    def __len__(self) -> int:
        return len(self.keys)


def code_roots() -> tuple[str, ...]:
    """Where a compiled table's code digest starts: this module and every human's module."""
    return (__name__, *content.registry_targets(HUMANS))


def cache_key(world: World, spec: str, closure: Sequence[str] = ()) -> str:
    """Content key of a compiled table (:func:`hg_marl.agents.content.content_key`).

    Its fields: the scenario and durations, the human's spec and the ``closure`` (the specs
    whose answers also lead on widen the table); the content module adds every file they
    name (a learned policy's header and weights, so retraining into the same folder
    compiles again) and the code reachable from :func:`code_roots`.
    """
    fields = {
        "scenario": repr(world.scenario),
        "durations": repr(world.durations),
        "spec": spec,
        "closure": list(closure),
    }
    return content.content_key("compiled human", fields, code_roots())


def default_cache() -> Path | None:
    """``$HG_MARL_CACHE/partners``, or None when the variable is unset (nothing written then)."""
    root = os.environ.get("HG_MARL_CACHE")
    return Path(root) / "partners" if root else None


def compile_human(
    world: World,
    human: str | Any,
    *,
    cache: Path | str | bool | None = True,
    max_keys: int = MAX_KEYS,
    progress: bool = False,
    closure: Sequence[str | Any] = (),
) -> CompiledHuman:
    """A :class:`CompiledHuman` for ``human`` (a registry spec or a stationary instance) in ``world``.

    Args:
        world: the world (scenario and durations) of the batched env.
        human: ``"cooperative"``, ``"lazy:p_idle=0.5"``... or an instance with ``distribution``.
        cache: True for :func:`default_cache` (``$HG_MARL_CACHE``), a folder, or None/False for no disk cache
            (instances are never cached on disk: only a spec string names their content).
        max_keys: the compiler's budget (:class:`CompileError` beyond it).
        progress: show a progress bar of the keys compiled.
        closure: other humans (specs or instances) whose answers also lead on, so the table
            covers the states a partner switching between them reaches (keyed by their specs).

    Raises:
        CompileError: the human is not stationary, or the scenario is over the budget.
    """
    spec = human if isinstance(human, str) else None
    live = make_human(human) if isinstance(human, str) else human
    if not callable(getattr(live, "distribution", None)):
        raise CompileError(
            f"human: {getattr(live, 'name', live)!r} cannot be compiled: it has no distribution(world, state) "
            "(switching and replay humans are not functions of the state)"
        )
    live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    others = [make_human(h) if isinstance(h, str) else h for h in closure]
    for other in others:
        if not callable(getattr(other, "distribution", None)):
            raise CompileError(f"human: {getattr(other, 'name', other)!r} cannot be compiled (no distribution)")
        other.reset(world, Agent.HUMAN, np.random.default_rng(0))
    if any(not isinstance(h, str) for h in closure):
        spec = None  # an instance in the closure has no content key: no disk cache
    name = spec or str(getattr(live, "name", "human"))
    folder = (
        None if cache is None or cache is False or spec is None else default_cache() if cache is True else Path(cache)
    )
    path = key = None
    if folder is not None:
        assert spec is not None
        key = cache_key(world, spec, tuple(str(h) for h in closure))
        path = folder / f"{world.scenario.name.split(':')[0]}-{key[:24]}.npz"
        if path.exists():
            try:
                with np.load(path, allow_pickle=False) as data:
                    if str(data["key"]) == key:
                        fields = ("keys", "starts", "actions", "cum", *OUTCOME_FIELDS)
                        return CompiledHuman(world, live, {k: data[k] for k in fields}, name)
            except (OSError, ValueError, KeyError):
                pass  # a corrupt or foreign entry is rebuilt
    try:
        table = answer_table(world, live, max_keys, progress, others)
    except CompileError:
        raise
    except ValueError as exc:  # e.g. a learned SB3 policy: no exact distribution
        raise CompileError(f"human: {name!r} cannot be compiled: {exc}") from None
    arrays = CompiledHuman.arrays_of(world, table)
    if path is not None:
        assert key is not None
        save_table(path, key, arrays)
    return CompiledHuman(world, live, arrays, name)


def save_table(path: Path, key: str, arrays: dict[str, np.ndarray]) -> None:
    """A compiled table as one ``.npz`` with its content key, written atomically (no pickle)."""
    from hg_marl.core.atomic import atomic_write

    def write(tmp: Path) -> None:
        buf = io.BytesIO()
        np.savez(buf, key=np.array(key), **arrays)  # type: ignore[arg-type]
        tmp.write_bytes(buf.getvalue())

    atomic_write(path, write)
