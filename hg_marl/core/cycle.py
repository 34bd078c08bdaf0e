"""One cycle of the task: the robot's action, then the human's, then the clock. Its one home.

Every environment, view and batched seat runs a cycle through these functions, so the
rules below are written once (``docs/design.md`` lists the homes of the others):

- **A half** (:func:`half`): one agent's action through :meth:`World.step
  <hg_marl.core.World.step>` (the rule table's transition, reward and events); its
  *effort* is its duration when it succeeded and is not a ``wait``, else 0; when it
  solved the table and the run is continuing, the table is re-drawn from the scenario's
  layout distribution with the caller's generator and a ``reset`` event is added.
- **What the human sees** (:func:`seen`): the robot's action index when it succeeded,
  else -1 (a failed action left nothing to see).
- **The clock** (:func:`close`; :class:`Clock` runs it over a run): the agents act in parallel, so a cycle lasts the
  longer of the two actions plus any decision time charged to it; an agent's *idle*
  time is the whole cycle when it waited, else the cycle less its own action.
- **The end of a run** (:func:`truncated`, :meth:`Clock.tick`): after ``max_cycles`` cycles or once the clock
  reaches ``time_budget``.
- **The human's seat** (:func:`seat_reward`, :func:`ends_episode`): the task reward less
  ``effort_weight`` times the seconds of work; episodic play ends when the robot solves
  the table.

:func:`cycle` composes them for a caller that holds both actions. The AEC environment
cannot: its human chooses after seeing the robot's half, so it calls :func:`half` twice
and :func:`close` once, exactly what :func:`cycle` does.

The batched twin (the ``*_batch`` functions) states the same rules over arrays, one
entry per table, for ``hg_marl.envs.batched`` (the batched half is
:meth:`BatchedRules.step <hg_marl.core.batch.BatchedRules.step>`, compiled from the same
rule table). :func:`seat_reward` and :func:`ends_episode` are written with operators that
numpy broadcasts, so one definition serves both. ``tests/core/test_cycle.py`` steps the
twins side by side, and checks that no other module restates the clock update.
"""

from __future__ import annotations

import math
import sys
from typing import Any, NamedTuple

import numpy as np

from hg_marl.core.errors import check_finite
from hg_marl.core.types import Agent, Event, State
from hg_marl.core.world import World

_new: Any = tuple.__new__
"""Builds a result tuple without the named tuple's keyword-handling ``__new__``: a half
is built at every turn of every environment, so its construction is kept to one call."""

RESET_EVENT = Event("reset", "table", "", "new layout")
"""Added to the events of the action that solved the table when the run goes on (continuing)."""


class Half(NamedTuple):
    """One agent's half of a cycle.

    Attributes:
        state: the state after the action (a fresh table when it solved one and the run goes on).
        ok: False when the action's preconditions did not hold (no effect).
        duration: simulated seconds the action took.
        reward: 1.0 when this action solved the table, else 0.0.
        events: what happened, in order (``reset`` last when the table was re-drawn).
        effort: seconds of physical work: the duration of a successful action other than ``wait``.
        waited: whether the action was ``wait``.
    """

    state: State
    ok: bool
    duration: float
    reward: float
    events: tuple[Event, ...]
    effort: float
    waited: bool


class CycleTime(NamedTuple):
    """How a cycle advanced the clock: its length and each agent's idle seconds (robot, human)."""

    length: float
    idle: tuple[float, float]


class Cycle(NamedTuple):
    """A whole cycle: the robot's half, what the human saw of it, the human's half, the time."""

    robot: Half
    seen: int
    human: Half
    time: CycleTime

    @property
    def state(self) -> State:
        """The state at the end of the cycle."""
        return self.human.state

    @property
    def reward(self) -> float:
        """The team's reward of the cycle (only the robot's completing ``wait`` earns one)."""
        return self.robot.reward + self.human.reward


def half(world: World, state: State, agent: Agent, action: int, redraw: np.random.Generator | None = None) -> Half:
    """``agent`` plays ``action`` in ``state``; ``redraw``: the generator of a continuing run, else None."""
    nxt, ok, duration, reward, events = world.step(state, agent, action)
    waited = action == world.table.wait[agent]
    out: Half = _new(Half, (nxt, ok, duration, reward, events, duration if ok and not waited else 0.0, waited))
    return redrawn(world, out, redraw) if reward and redraw is not None else out


def redrawn(world: World, solved: Half, rng: np.random.Generator) -> Half:
    """A half that solved the table, in a run that goes on: a fresh table and a ``reset`` event."""
    return solved._replace(state=world.initial_state(rng), events=(*solved.events, RESET_EVENT))


class Halves:
    """:func:`half` for one world, memoised: the environments' hot path.

    A half without a redraw depends only on the state, the agent and the action, so it
    is kept (the memo is cleared past the world's cache size, as the world's own memos
    are); a redraw, which draws from the caller's generator, is applied afresh each time.
    """

    def __init__(self, world: World) -> None:
        self.world = world
        self._memo: dict[tuple[State, int, int], Half] = {}
        self._get = self._memo.get
        self._limit = world.cache_limit

    def play(self, state: State, agent: Agent, action: int, redraw: np.random.Generator | None = None) -> Half:
        """:func:`half` (same arguments, less the world); hold the bound method on a hot path."""
        out = self._get((state, agent, action))
        if out is None:
            out = self._fill(state, agent, action)
        if redraw is not None and out.reward:
            return redrawn(self.world, out, redraw)
        return out

    def _fill(self, state: State, agent: Agent, action: int) -> Half:
        if len(self._memo) > self._limit:
            self._memo.clear()
        out = self._memo[(state, agent, action)] = half(self.world, state, agent, action)
        return out


def seen(action: int, ok: bool) -> int:
    """What the human sees of the robot's action: its index when it succeeded, else -1."""
    return action if ok else -1


class Clock:
    """The clock of one run, closed cycle after cycle: :func:`close` and :func:`truncated` in place.

    The AEC environment closes a cycle at every other turn; one method call that adds to
    running totals, rather than a result tuple per cycle, keeps that turn as cheap as
    the environment was before the cycle had its own home. :func:`close` is this clock's
    first tick, so the rule is written here once.

    Attributes:
        now: simulated seconds since the start.
        cycles: cycles closed so far.
        idle: idle seconds so far per agent (robot, human).
    """

    __slots__ = ("_budget", "_cap", "cycles", "idle", "now")

    def __init__(self, max_cycles: int | None = None, time_budget: float | None = None) -> None:
        self.now = 0.0
        self.cycles = 0
        self.idle = [0.0, 0.0]
        self._cap = sys.maxsize if max_cycles is None else max_cycles
        self._budget = math.inf if time_budget is None else time_budget

    def tick(self, robot: Half, human: Half, charged: float = 0.0) -> bool:
        """Close a cycle of these halves plus ``charged`` decision time; True when the run is truncated here."""
        d_robot, d_human = robot.duration, human.duration
        length = (d_robot if d_robot > d_human else d_human) + charged
        idle = self.idle
        idle[0] += length if robot.waited else length - d_robot
        idle[1] += length if human.waited else length - d_human
        self.now = now = self.now + length
        self.cycles = cycles = self.cycles + 1
        return cycles >= self._cap or now >= self._budget

    def ends(self, cycles: int, now: float) -> bool:
        """Whether a run with these limits ends after ``cycles`` cycles at ``now`` (as :meth:`tick` says)."""
        return cycles >= self._cap or now >= self._budget


def close(robot: Half, human: Half, charged: float = 0.0) -> CycleTime:
    """The cycle's length (the longer action plus ``charged`` decision time) and idle time per agent."""
    clock = Clock()
    clock.tick(robot, human, charged)
    return _new(CycleTime, (clock.now, (clock.idle[0], clock.idle[1])))


def cycle_length(d_robot: float, d_human: float) -> float:
    """Seconds a cycle of two actions lasts (no decision time): the longer of the two."""
    return max(d_robot, d_human)


def truncated(cycles: int, clock: float, max_cycles: int | None, time_budget: float | None) -> bool:
    """Whether a run ends here for want of cycles or time (None: no such limit)."""
    return Clock(max_cycles, time_budget).ends(cycles, clock)


def cycle(
    world: World,
    state: State,
    robot_action: int,
    human_action: int,
    redraw: np.random.Generator | None = None,
    charged: float = 0.0,
) -> Cycle:
    """One whole cycle from ``state``: the robot's half, then the human's, then the clock.

    ``human_action`` is played in the state the robot's half left (a fresh table when it
    solved one and ``redraw`` is given); ``charged`` is decision time added to the cycle.
    """
    robot = half(world, state, Agent.ROBOT, robot_action, redraw)
    human = half(world, robot.state, Agent.HUMAN, human_action, redraw)
    time = close(robot, human, charged)
    return Cycle(robot, seen(robot_action, robot.ok), human, time)


# ---- the human's seat (scalars and arrays alike) ------------------------------------------
def check_effort_weight(effort_weight: Any) -> float:
    """``effort_weight`` as a float, refused (``ConfigError``) unless a finite number >= 0.

    One check for the scalar view and the batched table: a NaN weight would make every
    reward of the human's seat NaN, and ``NaN < 0`` is false.
    """
    return check_finite(effort_weight, "effort_weight", minimum=0.0)


def seat_reward(task_reward: Any, work: Any, effort_weight: float) -> Any:
    """The human seat's reward: the task reward less ``effort_weight`` times its seconds of work."""
    return task_reward - effort_weight * work


def ends_episode(task_reward: Any, continuing: bool) -> Any:
    """Whether a solved table ends the episode: in episodic play only (arrays: per table)."""
    return (task_reward > 0) & (not continuing)


# ---- the batched twin ------------------------------------------------------------------
def waited_batch(world: World, agent: Agent, actions: np.ndarray) -> np.ndarray:
    """Per table, whether ``agent``'s action is ``wait`` (the rule table's wait index)."""
    return actions == world.table.wait[agent]


def effort_batch(ok: np.ndarray, waited: np.ndarray, duration: np.ndarray) -> np.ndarray:
    """:attr:`Half.effort` per table: the duration of a successful action other than ``wait``."""
    return np.where(ok & ~waited, duration, 0.0)


def seen_batch(actions: np.ndarray, ok: np.ndarray) -> np.ndarray:
    """:func:`seen` per table."""
    return np.where(ok, actions, -1)


def close_batch(
    durations: tuple[np.ndarray, np.ndarray], waited: tuple[np.ndarray, np.ndarray]
) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:  # (robot, human) durations and waits per table
    """:func:`close` per table (no decision time: batched seats charge none): (length, idle per agent)."""
    length = np.maximum(durations[0], durations[1])
    return length, (
        np.where(waited[0], length, length - durations[0]),
        np.where(waited[1], length, length - durations[1]),
    )


def truncated_batch(
    cycles: np.ndarray, clock: np.ndarray, max_cycles: int | None, time_budget: float | None
) -> np.ndarray:
    """:func:`truncated` per table."""
    out = np.zeros(len(cycles), dtype=bool)
    if max_cycles is not None:
        out |= cycles >= max_cycles
    if time_budget is not None:
        out |= clock >= time_budget
    return out
