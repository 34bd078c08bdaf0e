"""A compiled robot partner for the human's batched seat: the ``planner`` robot as arrays.

Why. The human's batched seat (``agents/views.py: human_vector_env``) otherwise steps one
live robot actor per table in a Python loop (:class:`~hg_marl.agents.views.LiveRobots`),
which caps it at the planner's speed. The planner robot replans from the state at every
decision, so its choice is a function of the robot-turn state (a cold
``Planner(world).plan(state, to_move=Agent.ROBOT)`` and its proposal, ``plan_proposal``:
the plan's first robot action, ``wait`` when no plan is found), except for its partner
handling (:mod:`hg_marl.agents.partner`), which depends on history. The state function is
compiled; the partner handling is replaced by an array rule (below).

Compilation. :func:`enumerate_plans` visits, with the model builder
(:func:`robot_states`), every robot-turn state reachable from the
layout distribution (``layout_distribution``, and each layout after the human's move: the
continuing mode's re-drawn table meets the human first) under every feasible robot action (a
superset of the robot's own compiled action and every stall move it may take, which are
feasible non-wait actions; the budget is checked before any planning), followed by
every human answer (every feasible human action and one failing one: a learner may send
any index). Each state is planned once by a fresh planner (a warm planner's cached plan
suffixes may break ties differently from a cold search, so the table holds the cold
answer, the one a test recomputes independently). The packed keys
(:class:`~hg_marl.agents.compiled.Packer`) are stored sorted with the actions; a batch is
answered by one ``searchsorted``. A state outside the table (a reset to a given state of
another scenario's reach, say) is planned live and counted in :attr:`CompiledRobot.fallbacks`.

The stall rule (the project's rule that no robot waits forever on a partner who leaves
the task solvable) is the progress guard every robot obeys, in its array form
(:class:`~hg_marl.agents.progress.ArrayProgressGuard`). Per table, ``unchanged`` counts
the consecutive robot turns at which the state equals the state at that table's previous
robot turn (the robot's move and the human's answer together changed nothing: the robot
waited, or offered an object that lapsed, while the human did nothing useful). When ``unchanged >= stall_after`` (``K``,
default :data:`STALL_AFTER` = 12, the guard's ``PROGRESS_AFTER``), the
robot takes, instead of the planner's action, the ``(m mod n)``-th feasible non-wait
action in index order, where ``n`` is the number of such actions and ``m`` the stall moves
this table took since its reset (so a stall that comes back tries the next move, as the
oracle's off-model fallback does); ``wait`` only when nothing else is feasible. A stall
move that changes the state resets the count at the next turn; one that does not is
followed by the next option at once. A table reset zeroes both counters. So a partner
who only waits sees the robot wait at most ``K`` cycles in a row before it moves: the
move comes at the ``K + 1``-th cycle of an unchanged state.

Difference from the live planner. The live planner obeys the same guard and, on top of
it, a monitor of *unmet expectations* (the plan expected a non-wait human action the human
did not do, or no plan was found), which stalls after 4 of them and then drops the count
to 2; it also blocks human actions refused twice (the planner then plans with a restricted
model) and draws that monitor's stall move uniformly with the robot's generator. The
compiled robot has no blocked actions (its plans always assume the cooperative model) and
no monitor, only the guard. Against a partner who follows the plans both act alike;
against one who refuses, the live robot may find a detour sooner.

Cost: one cold plan per robot-turn state, paid once, after which a batch is one lookup
instead of a planner per table (its build time and speed-up, measured by
``benchmarks/batched_throughput.py --human-seat``: ``docs/batched.md``). A scenario with
more robot-turn states than :data:`MAX_STATES` (``roboergosum``) is planned once per state
up to relabelling interchangeable objects (:func:`canonical_plans`). Cached on disk like
the compiled humans, only in a folder the user names (``cache=FOLDER``, or ``$HG_MARL_CACHE``).
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import numpy as np
from tqdm import tqdm

from hg_marl.agents import content
from hg_marl.agents.compiled import CompileError, Packer, default_cache, save_table
from hg_marl.agents.models.packing import StatePacker
from hg_marl.agents.models.partners import Alone, Shared
from hg_marl.agents.progress import PROGRESS_AFTER, ArrayProgressGuard
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchedRules, BatchState

STALL_AFTER = PROGRESS_AFTER
"""Unchanged robot turns in a row after which the compiled robot takes a stall move (the progress guard's K)."""

MAX_STATES = 50_000
"""The compiler's budget of cold plans; beyond it, a clear error.

A scenario with at most this many robot-turn states gets one cold plan per state. A larger
one (``roboergosum``: 530,036) gets one per state up to relabelling interchangeable
objects (17,160 there), if those fit (:func:`canonical_plans`); beyond that it is refused
and its human seat keeps live robots. ``max_states=`` moves the budget."""

MAX_ENUMERATED = 2_000_000
"""Robot-turn states the compiler enumerates at most (before planning any)."""

COMPILABLE = ("planner",)
"""Robot specs that are compiled (the plain planner: its plans are a function of the state)."""


def planner_action(world: World, state: State) -> int:
    """The planner robot's proposal at ``state`` from a cold planner (the compiled answer)."""
    from hg_marl.agents.meta.cost import CostModel
    from hg_marl.agents.robots.base import make_planner, plan_proposal

    result = make_planner(world).plan(state, to_move=Agent.ROBOT)
    return plan_proposal(result, world.n_actions(Agent.ROBOT), Agent.ROBOT, CostModel()).action


def robot_states(world: World, max_states: int = MAX_STATES, progress: bool = False) -> np.ndarray:
    """The packed keys, sorted, of every robot-turn state the human's seat can reach against the compiled robot.

    The model builder's closure (``agents/models/builder.py``): from the layouts, every
    feasible robot action (a superset of the compiled action and the stall moves; the
    completing ``wait`` ends the task, the table is re-drawn: a layout), then every human
    answer (every feasible human action and one failing one: a learner may send any
    index), answered on arrays by :func:`any_answer`. The re-drawn table meets the human first.
    """
    from hg_marl.agents.models import AnswerTable, Budget, OverBudget, StatePacker, build_model
    from hg_marl.agents.models.layouts import layout_distribution

    budget = Budget(None, None, max_states, subject=f"scenario: {world.scenario.name!r}")
    packer = StatePacker(world)
    table = AnswerTable(world, None, packer, budget, batch=any_answer(world))
    try:
        model = build_model(
            world, table, layout_distribution(world), failed_actions=False, budget=budget, progress=progress
        )
    except OverBudget:
        model = None
    if model is None or model.n > max_states:
        raise CompileError(
            f"scenario: {world.scenario.name!r} has over {max_states} robot-turn states for the compiled "
            "planner (max_states); use compiled=False for live robots"
        )
    return np.sort(model.keys)


def any_answer(world: World) -> Any:
    """Every feasible human action and the first infeasible one (standing for all: nothing happens), on arrays."""
    rules = BatchedRules(world)

    def answers(b: BatchState, shared: Shared | None = None, /) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        mask = (shared or Alone(rules, b)).mask
        fails = ~mask.all(axis=1)
        rows, actions = np.nonzero(mask)
        rows = np.concatenate([rows, np.flatnonzero(fails)])
        actions = np.concatenate([actions, np.argmin(mask[fails], axis=1)])
        order = np.argsort(rows, kind="stable")  # per state: the feasible ones in index order, then the failing one
        sizes = np.bincount(rows, minlength=len(b))
        return sizes, actions[order], 1.0 / sizes[rows[order]]

    return answers


def enumerate_plans(world: World, max_states: int = MAX_STATES, progress: bool = False) -> dict[State, int]:
    """Every robot-turn state of :func:`robot_states`, with its planner action.

    The states are planned once the set is known, so the budget is checked before the first
    search: each state's cold answer when there are at most ``max_states``, else
    :func:`canonical_plans`.
    """
    keys = robot_states(world, max(max_states, MAX_ENUMERATED), progress)
    b, _ = StatePacker(world).unpack(keys)
    if len(b) > max_states:
        return canonical_plans(world, b, max_states, progress)
    plans: dict[State, int] = {}
    for i in tqdm(range(len(b)), desc="compile planner", unit=" states", disable=not progress, file=sys.stderr):
        state = b.state(i)
        plans[state] = planner_action(world, state)
    return plans


def canonical_plans(world: World, b: BatchState, max_states: int, progress: bool = False) -> dict[State, int]:
    """The cold answer at each state's canonical relabelling, mapped back to the state's objects.

    The planner's problem is the same up to relabelling interchangeable objects (same kind,
    same bins: :class:`~hg_marl.core.relabel.Relabel`), so an optimal plan at the canonical
    state, its objects mapped back, is an optimal plan at the state: the cost is the same.
    Where the state's own cold search would pick another object of the same class at equal
    cost (the search breaks ties by object index), the table holds the canonical one; every
    state that is its own canonical relabelling gets exactly its cold answer. Refused, before
    any search, when the canonical states are more than ``max_states``.
    """
    from hg_marl.agents.models.equivariant import actions_back, canonical_copy, object_slots

    packer = StatePacker(world)
    canon, orig = canonical_copy(packer, b)
    keys = packer.pack(canon, np.full(len(b), -1, dtype=np.int64))
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    if len(first) > max_states:
        raise CompileError(
            f"scenario: {world.scenario.name!r} has {len(b)} robot-turn states, {len(first)} up to relabelling "
            f"interchangeable objects, over the {max_states} cold plans of the compiled planner (max_states); "
            "use compiled=False for live robots"
        )
    bar = tqdm(first, desc="compile planner (canonical)", unit=" states", disable=not progress, file=sys.stderr)
    planned = np.array([planner_action(world, canon.state(int(i))) for i in bar], dtype=np.int64)
    slot, remap = object_slots(world, Agent.ROBOT)
    back = actions_back(slot, remap, planned[inverse.ravel()], orig, np.arange(len(b)))
    return {b.state(i): int(back[i]) for i in range(len(b))}


class CompiledRobot:
    """The planner robot's actions as sorted arrays, with the stall rule per table (``ArrayPartner``).

    Args:
        world: the world it was compiled for.
        arrays: ``keys`` (sorted packed states) and ``actions``.
        stall_after: ``K`` of the stall rule (module docstring).
    """

    def __init__(
        self, world: World, arrays: dict[str, np.ndarray], name: str = "planner", stall_after: int = STALL_AFTER
    ) -> None:
        if stall_after < 1:
            raise CompileError(f"stall_after: expected a positive number of turns, got {stall_after}")
        self.world, self.name, self.stall_after = world, name, int(stall_after)
        self.packer = Packer(world)
        self.keys, self.actions = arrays["keys"], arrays["actions"]
        self.wait = int(world.table.wait[Agent.ROBOT])
        self.fallbacks = 0
        """Tables answered by a live planner because their state was not in the table."""
        self.guard = ArrayProgressGuard(world, self.stall_after)
        """The stall rule: the project's one progress guard, array form (:mod:`hg_marl.agents.progress`)."""

    @property
    def unchanged(self) -> np.ndarray:
        """Per table, the consecutive robot turns at which the state had not changed."""
        return self.guard.unchanged

    @property
    def stall_count(self) -> np.ndarray:
        """Per table, the stall moves taken since its reset."""
        return self.guard.moves

    @property
    def stalled(self) -> np.ndarray:
        """Per table, whether its last robot move was a stall move."""
        return self.guard.fired

    @property
    def stall_moves_taken(self) -> int:
        """Stall moves over all tables (the rule fired)."""
        return self.guard.moves_taken

    def __len__(self) -> int:
        return len(self.keys)

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Tables ``rows`` start afresh: no previous state, no stall count (``rng`` unused: a deterministic rule)."""
        self.guard.reset_rows(rows)

    def plan(self, batch: BatchState) -> tuple[np.ndarray, np.ndarray]:
        """(planner action, found) per table, without the stall rule; tables not found are planned live."""
        keys = self.packer.pack(batch, np.full(len(batch), -1, dtype=np.int64))
        idx = np.minimum(np.searchsorted(self.keys, keys), max(len(self.keys) - 1, 0))
        found = self.keys[idx] == keys if len(self.keys) else np.zeros(len(batch), dtype=bool)
        out = self.actions[idx] if len(self.keys) else np.full(len(batch), self.wait, dtype=np.int64)
        if not found.all():
            missing = np.flatnonzero(~found)
            self.fallbacks += len(missing)
            for i in missing:
                out[i] = planner_action(self.world, batch.state(int(i)))
        return out, found

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """The planner's action per table, a stall move where the stall rule fires (module docstring)."""
        out, _ = self.plan(batch)
        return self.guard.apply(batch, out)


def robot_cache_key(world: World, spec: str, stall_after: int, max_states: int = MAX_STATES) -> str:
    """Content key of a compiled robot (:func:`hg_marl.agents.content.content_key`): scenario,
    durations, spec, the rule's ``K``, the budget (it decides between each state's own cold
    answer and :func:`canonical_plans`) and the code reachable from this module (the table is
    built by :func:`planner_action`, so the live robot's own module is not code it runs)."""
    fields = {
        "scenario": repr(world.scenario),
        "durations": repr(world.durations),
        "spec": spec,
        "K": stall_after,
        "max_states": max_states,
    }
    return content.content_key("compiled robot", fields, (__name__,))


def compile_robot(
    world: World,
    robot: str = "planner",
    *,
    cache: Path | str | bool | None = True,
    max_states: int = MAX_STATES,
    stall_after: int = STALL_AFTER,
    progress: bool = False,
) -> CompiledRobot:
    """A :class:`CompiledRobot` for ``robot`` (``"planner"``) in ``world``.

    Args:
        world: the world (scenario and durations) of the batched env.
        robot: the robot spec; only the plain ``"planner"`` is a function of the state.
        cache: True for ``$HG_MARL_CACHE/partners`` (no disk cache when unset), a folder, or None/False.
        max_states: the compiler's budget of cold plans (:data:`MAX_STATES`; :class:`CompileError` beyond it).
        stall_after: ``K`` of the stall rule.
        progress: show a progress bar of the states planned.

    Raises:
        CompileError: a robot that is not compiled, or a scenario over the budget.
    """
    if robot not in COMPILABLE:
        raise CompileError(f"robot: {robot!r} cannot be compiled (only {', '.join(COMPILABLE)}); use live robots")
    folder = None if cache is None or cache is False else default_cache() if cache is True else Path(cache)
    path = key = None
    if folder is not None:
        key = robot_cache_key(world, robot, stall_after, max_states)
        path = folder / f"{world.scenario.name.split(':')[0]}-robot-{key[:24]}.npz"
        if path.exists():
            try:
                with np.load(path, allow_pickle=False) as data:
                    if str(data["key"]) == key:
                        return CompiledRobot(
                            world, {k: data[k] for k in ("keys", "actions")}, robot, stall_after=stall_after
                        )
            except (OSError, ValueError, KeyError):
                pass  # a corrupt or foreign entry is rebuilt
    plans = enumerate_plans(world, max_states, progress)
    packer = Packer(world)
    items = sorted((packer.pack_one(s, -1), a) for s, a in plans.items())
    arrays = {
        "keys": np.array([k for k, _ in items], dtype=np.int64),
        "actions": np.array([a for _, a in items], dtype=np.int64),
    }
    if path is not None:
        assert key is not None
        save_table(path, key, arrays)
    return CompiledRobot(world, arrays, robot, stall_after=stall_after)
