"""Partners of a batched seat over arrays (the ``ArrayPartner`` protocol of ``hg_marl.envs.array_partner``).

The robot's seat plays compiled humans (``agents/compiled.py``; a list is a
:class:`CompiledPopulation`, a ``switching`` human a :class:`CompiledSchedule`; a
learned SB3 human, which cannot be compiled, answers every table with one forward pass
of its policy, ``agents/batched_learned.py``). The human's seat plays the ``planner``
robot compiled (``agents/compiled_robot.py``: its plans per robot-turn state, with an
array stall rule in place of its history-dependent partner monitor) and other robots
live, one per table (:class:`LiveRobots`).
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from typing import Any

import numpy as np

from hg_marl.agents.humans.registry import resolve_human
from hg_marl.agents.partner_specs import as_list, make_robot_actor
from hg_marl.core import Agent, World
from hg_marl.policy import Actor

logger = logging.getLogger(__name__)


class LiveRobots:
    """Robot actors playing the human's batched seat, one per table (the ``ArrayPartner`` protocol).

    Each table has its own actor (a robot may keep state between turns); the turn it sees
    carries the state, the facts and mask, the clock and the tasks solved, but no events
    or reward: robots that learn from those (``habit``, ``hybrid``) do not fit a batched
    seat, deterministic ones (``planner``, ``random``) do.
    """

    def __init__(self, world: World, robot: str | Actor | Sequence[str | Actor], num_envs: int) -> None:
        self.world = world
        specs = as_list(robot)
        self.name = str(getattr(specs[0], "name", specs[0]))
        self.specs = specs
        # a name builds one actor per table; an instance is shared by the tables it plays
        self.actors = [make_robot_actor(specs[i % len(specs)]) for i in range(num_envs)]
        self._clock: np.ndarray = np.zeros(num_envs)
        self._tasks: np.ndarray = np.zeros(num_envs, dtype=np.int64)

    def follow(self, clock: np.ndarray, tasks_solved: np.ndarray) -> None:
        """Every table's clock and tasks solved (``FollowsClock``), for the turns the robots see."""
        self._clock, self._tasks = clock, tasks_solved

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Start the actors of tables ``rows`` with generators drawn from ``rng``."""
        for i in rows:
            self.actors[int(i)].reset(self.world, Agent.ROBOT, np.random.default_rng(int(rng.integers(2**63 - 1))))

    def act(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """Each table's robot acts on its own turn."""
        from hg_marl.policy import Turn

        out = np.empty(len(batch), dtype=np.int64)
        rows = getattr(batch, "rows", np.arange(len(batch)))
        for j in range(len(batch)):
            state = batch.state(j)
            obs = {"observation": self.world.facts(state), "action_mask": self.world.mask(state, Agent.ROBOT)}
            row = int(rows[j])
            turn = Turn(
                self.world, state, Agent.ROBOT, obs, clock=float(self._clock[row]), tasks_solved=int(self._tasks[row])
            )
            out[j] = int(self.actors[row].act(turn))
        return out


class CompiledPopulation:
    """Compiled humans as one partner: a member drawn per table at each of its resets (``ArrayPartner``)."""

    def __init__(self, members: Sequence[Any]) -> None:
        self.members = list(members)
        self.name = "+".join(m.name for m in self.members)
        self.member: np.ndarray = np.zeros(0, dtype=np.int64)
        if all(hasattr(m, "answer") for m in self.members):
            # the members' tables end to end: an entry of member k is offset by the entries before it
            sizes = [len(m.actions) for m in self.members]
            self.offset = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
            self.actions = np.concatenate([m.actions for m in self.members])
            self.outcome = {k: np.concatenate([m.outcome[k] for m in self.members]) for k in self.members[0].outcome}

    def answer(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(entry in the joined tables, found) per table: each table's member answers."""
        who = self.member[batch.rows]
        pos = np.zeros(len(batch), dtype=np.int64)
        found = np.zeros(len(batch), dtype=bool)
        for k, member in enumerate(self.members):
            sel = np.flatnonzero(who == k)
            if len(sel):
                p, f = member.answer(self._part(batch, sel), seen[sel], rng)
                pos[sel], found[sel] = p + self.offset[k], f
        return pos, found

    def fall_back(
        self, batch: Any, seen: np.ndarray, rng: np.random.Generator, out: np.ndarray, found: np.ndarray
    ) -> np.ndarray:
        """The live members answer the tables not found (counted per member)."""
        who = self.member[batch.rows]
        for k, member in enumerate(self.members):
            sel = np.flatnonzero((who == k) & ~found)
            if len(sel):
                out[sel] = member.fall_back(self._part(batch, sel), seen[sel], rng, out[sel], found[sel])
        return out

    @staticmethod
    def _part(batch: Any, sel: np.ndarray) -> Any:
        from hg_marl.envs.batched import BatchState

        return BatchState(
            batch.where[sel], batch.robot_at[sel], batch.offer_by[sel], batch.offer_obj[sel], batch.rows[sel]
        )

    @property
    def fallbacks(self) -> int:
        """Live answers over all members."""
        return sum(m.fallbacks for m in self.members)

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Draw tables ``rows``' members uniformly."""
        if len(self.member) <= int(rows.max(initial=-1)):
            self.member = np.concatenate(
                [self.member, np.zeros(int(rows.max()) + 1 - len(self.member), dtype=np.int64)]
            )
        self.member[rows] = rng.integers(len(self.members), size=len(rows))

    def act(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """Each table's member answers (one batched look-up per member)."""
        who = self.member[batch.rows]
        out = np.empty(len(batch), dtype=np.int64)
        for k, member in enumerate(self.members):
            sel = np.flatnonzero(who == k)
            if len(sel):
                out[sel] = member.act(self._part(batch, sel), seen[sel], rng)
        return out


class CompiledSchedule(CompiledPopulation):
    """A ``switching`` human over compiled members: each table's phase read from its own clock.

    The phase of a table is ``bisect_right(at, clock)`` (or of its tasks solved with
    ``by="tasks"``), exactly :meth:`SwitchingHuman.phase_at`'s rule, applied to the whole
    batch at once; a phase's member answers from its compiled table. A member that
    appears in several phases is compiled once (``phase_member`` maps phase -> member).
    """

    def __init__(self, members: Sequence[Any], phase_member: Sequence[int], at: Sequence[float], by: str) -> None:
        super().__init__(members)
        self.name = "switching(" + ",".join(members[k].name for k in phase_member) + ")"
        self.phase_member = np.asarray(phase_member, dtype=np.int64)
        self.at = np.asarray(at, dtype=float)
        self.by = by

    def follow(self, clock: np.ndarray, tasks_solved: np.ndarray) -> None:
        """Each table's member from its clock (or tasks solved), before the partner moves."""
        value = clock if self.by == "time" else tasks_solved.astype(float)
        self.member = self.phase_member[np.searchsorted(self.at, value, side="right")]

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Nothing to draw: the phase follows the clock, which the reset set to 0."""


def _compiled_schedule(world: World, human: Any, cache: Any, progress: bool) -> CompiledSchedule:
    from hg_marl.agents.compiled import compile_human

    keys: dict[Any, int] = {}
    unique: list[Any] = []
    phase_member = []
    for spec, live in zip(human.specs, human.humans, strict=True):
        key = spec if spec is not None else id(live)
        if key not in keys:
            keys[key] = len(unique)
            unique.append(spec if spec is not None else live)
        phase_member.append(keys[key])
    # each member's table covers the states the other phases lead to (a switch mid-episode)
    members = [
        compile_human(world, h, cache=cache, progress=progress, closure=[o for o in unique if o is not h])
        for h in unique
    ]
    return CompiledSchedule(members, phase_member, human.at, human.by)


def compiled_humans(
    world: World, human: str | Actor | Sequence[str | Actor], cache: Any = True, progress: bool = False
) -> Any:
    """One compiled human, a :class:`CompiledPopulation` for a list, a :class:`CompiledSchedule` for a switching one.

    A learned SB3 human cannot be compiled (no exact distribution); it plays as a
    :class:`~hg_marl.agents.batched_learned.BatchedLearned` (one forward pass of its
    policy per step over all tables), alone or as a member of a population.
    """
    from hg_marl.agents.humans.switching import SwitchingHuman

    if isinstance(human, SwitchingHuman):
        return _compiled_schedule(world, human, cache, progress)
    members = [_batched_member(world, h, cache, progress) for h in as_list(human)]
    return members[0] if len(members) == 1 else CompiledPopulation(members)


def _batched_member(world: World, human: str | Actor, cache: Any, progress: bool) -> Any:
    """A human as an array partner: a learned SB3 policy batched, any other compiled (a spec keeps its cache key)."""
    from hg_marl.agents.batched_learned import BatchedLearned, is_sb3_learned
    from hg_marl.agents.compiled import compile_human
    from hg_marl.agents.humans.registry import parse_human

    live: Any = human
    if isinstance(human, str):
        live = resolve_human(human) if parse_human(human)[0] == "learned" else None
    if is_sb3_learned(live):
        return BatchedLearned(world, live, name=human if isinstance(human, str) else None)
    return compile_human(world, human, cache=cache, progress=progress)


def compiled_robots(
    world: World, robot: str | Actor | Sequence[str | Actor], num_envs: int, cache: Any = True, progress: bool = False
) -> Any:
    """A compiled robot when every spec is a compilable name (``"planner"``), else :class:`LiveRobots`.

    A scenario over the compiler's budget (``roboergosum``) keeps live robots, with a warning.
    """
    from hg_marl.agents.compiled import CompileError
    from hg_marl.agents.compiled_robot import COMPILABLE, compile_robot

    specs = as_list(robot)
    if all(isinstance(s, str) for s in specs) and len(set(specs)) == 1 and specs[0] in COMPILABLE:
        try:
            return compile_robot(world, str(specs[0]), cache=cache, progress=progress)
        except CompileError as exc:  # over the budget (a large scenario): live robots, said once
            logger.warning("%s; the human's seat uses live robots", exc)
    return LiveRobots(world, robot, num_envs)
