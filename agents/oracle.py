"""The oracle: the optimal robot policy and its reward rate against a known stationary human.

Model. A semi-MDP on the symbolic :class:`~hg_marl.core.State` at the robot's turn
(continuing mode, the paper's protocol). From state ``s`` the robot takes action ``a``;
then the human, whose policy is folded into the dynamics through its exact
``distribution(world, state)``, answers; the cycle lasts ``max(d_robot, d_human)``
simulated seconds (the environment's clock; no decision time). The robot's ``wait`` on a
clean table earns 1, and the table is re-drawn from the scenario's layout distribution
(enumerated exactly with its probabilities by :func:`layout_distribution`), the robot's
location included, before the human's move of that same cycle. Every action of the
action space is modelled: infeasible ones all have the same effect (0.2 s, nothing done,
a pending offer lapses), so one representative stands for them (``failed_actions``).

Solution (why not relative value iteration). Each success is worth exactly 1 and is
followed by a table drawn from a fixed distribution: a regeneration point. By the
renewal-reward theorem the rate of a stationary policy is ``1 / E[T]``, with ``T`` the
time between successes, and no policy can beat the one minimising the expected time to
the next success from every state. So the average-reward problem is a stochastic
shortest-path problem (the Dinkelbach fixed point ``max E[r - rho tau] = 0`` reached in
one solve, no search on ``rho``): value iteration ``V(s) = min_a E[tau + V(s')]`` with
``V = 0`` after the completing ``wait``. States from which the robot cannot make success
certain (e.g. an adversarial human hid an object) are found first by the standard
almost-sure-reachability fixpoint and get ``V = inf``; if the re-drawn table can lead
there, the rate is 0.

Symmetry. Objects accepted by the same bins are interchangeable. When the human is
``equivariant`` (relabelling them in the state relabels its answer: the planner-driven
``cooperative`` and ``noisy``, ``random``), the model keeps one canonical state per
relabelling class (:class:`~hg_marl.agents.planner.space.Relabel`) and draws the
canonical layouts directly (:func:`canonical_layouts`); the rate is the full model's
(tests), the policy is keyed by canonical states (:meth:`OracleResult.action_at` maps
an action back). Humans whose rule picks "the first object" by index (``lazy``,
``no_handover``, ``adversarial``) are not equivariant and get the full model.

Size and budget (``python benchmarks/oracle_budget.py``, each solve in a fresh process
on the shared, loaded 2-core machine, wall seconds). ``paper2015``: under 1 s for every
bundled human. ``roboergosum`` (6 objects, 5,040 layouts, 140 canonical): ``random``
17k states, 3 s; ``cooperative`` 6.5k states, 20-27 s (58 s and 192k states without the
reduction); ``noisy`` 17k states, 48-58 s (353-396 s and 4.5 GB before); ``no_handover``
6 s, ``adversarial`` 7 s, ``lazy`` 17-23 s (251k states, 0.6 GB). Generated 8-object
tables (1.8M layouts): ``random`` 2-3 s with one bin, 36-47 s CPU with two (428k states);
the planner-driven humans need one A* search per mid-cycle state (tens of ms each) and
exceed the budget; the non-equivariant humans' 1.8M layouts are refused before
enumeration. A solve stops with a one-line :class:`OracleTooLarge` naming the
budget beyond ``max_seconds`` (default 60 s of CPU time: a loaded machine does not
change the verdict), ``max_memory`` (4 GB resident),
``max_states`` or the kernel's available memory falling under 512 MB, so a study falls
back to the best robot as reference. The build is pure Python and shows a progress bar
with the states explored and known (``progress=True``, the CLI's default).
"""

from __future__ import annotations

import itertools
import logging
import math
import os
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from tqdm import tqdm

from hg_marl.agents.humans.base import HumanError
from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.planner.space import Relabel
from hg_marl.agents.progress import ProgressGuard
from hg_marl.core import Agent, Durations, Scenario, State, World
from hg_marl.core.scenario import layout_count
from hg_marl.policy import Decision, Turn

logger = logging.getLogger(__name__)

HOUR = 3600.0


class OracleTooLarge(RuntimeError):
    """The reachable model exceeds ``max_states``."""


@dataclass(frozen=True)
class OracleResult:
    """The optimal rate, its policy, and the size of the model."""

    rate_per_hour: float
    """Optimal long-run tasks per simulated hour (0 if no policy can ever complete)."""
    seconds_per_task: float
    """Optimal expected simulated seconds between successes (inf if never)."""
    n_states: int
    """Robot-turn states in the model."""
    n_transitions: int
    """(state, robot action, human reply) transitions."""
    n_layouts: int
    """Distinct tables the re-draw can produce."""
    iterations: int
    """Value-iteration sweeps."""
    converged: bool
    """Whether the sweeps met the tolerance before ``max_iterations``."""
    policy: dict[State, int] = field(repr=False)
    """Optimal robot action index at every robot-turn state of the model."""
    values: dict[State, float] = field(repr=False)
    """Optimal expected seconds to the next success from each state (inf: not certain)."""
    scenario: str = ""
    """Scenario name."""
    human: str = ""
    """The human's name."""
    seconds: float = 0.0
    """Wall time of the build and solve."""
    reduced: bool = False
    """Whether the model holds canonical states only (interchangeable objects in canonical
    order, :class:`~hg_marl.agents.planner.space.Relabel`): then ``policy`` and ``values``
    are keyed by canonical states and the policy's actions are in canonical labelling;
    :meth:`action_at` and :meth:`value_at` answer for any state."""

    def action_at(self, world: World, state: State, relabel: Relabel | None = None) -> int | None:
        """The optimal robot action at ``state`` (any labelling), or None outside the model."""
        if not self.reduced:
            return self.policy.get(state)
        relabel = relabel or Relabel(world)
        key, orig = relabel.canonical(state)
        action = self.policy.get(key)
        return None if action is None else relabel.action_back(Agent.ROBOT, action, orig)

    def value_at(self, world: World, state: State, relabel: Relabel | None = None) -> float:
        """Optimal expected seconds to the next success from ``state`` (inf outside the model)."""
        if self.reduced:
            state = (relabel or Relabel(world)).canonical(state)[0]
        return self.values.get(state, math.inf)


def layout_distribution(world: World) -> list[tuple[State, float]]:
    """Every table ``World.initial_state`` can draw, with its exact probability.

    ``initial_state`` shuffles the objects, deals them to the layout groups in order, and
    each group draws an ordered sample of distinct spots; so each group receives a
    uniformly random subset of the remaining objects, mapped injectively and uniformly
    onto its spots, and the robot starts at a uniform ``robot_start`` location.
    """
    sc = world.scenario
    out: dict[State, float] = {}

    def deal(k: int, left: tuple[int, ...], where: dict[int, int], p: float) -> Iterator[tuple[dict[int, int], float]]:
        if k == len(sc.layout):
            yield where, p
            return
        group = sc.layout[k]
        subsets = list(itertools.combinations(left, group.count))
        spots = list(itertools.permutations(group.spots, group.count))
        q = p / (len(subsets) * len(spots))
        for subset in subsets:
            rest = tuple(o for o in left if o not in subset)
            for chosen in spots:
                yield from deal(k + 1, rest, {**where, **dict(zip(subset, chosen, strict=True))}, q)

    for where, p in deal(0, tuple(range(world.n_objects)), {}, 1.0):
        for start in sc.robot_start:
            state = State(tuple(where[o] for o in range(world.n_objects)), start)
            out[state] = out.get(state, 0.0) + p / len(sc.robot_start)
    return sorted(out.items())


def canonical_layouts(world: World) -> list[tuple[State, float]]:
    """:func:`layout_distribution` up to interchangeable objects, without enumerating every deal.

    Each state is :meth:`Relabel.canonical` of the tables it stands for, with their total
    probability. Per layout group: the class make-up of the dealt subset is
    multivariate-hypergeometric, and given it every assignment of the classes to disjoint
    spot sets is equally likely (``prod n_c! (m - c)! / m!`` each, ``m`` spots, ``c``
    objects). On ``generated:objects=8,bins=2`` that is 3,150 states instead of 1.8M deals.
    """
    sc = world.scenario
    members: dict[tuple[int, ...], list[int]] = {}
    for o, bins in enumerate(world.bins_of):
        members.setdefault(bins, []).append(o)
    classes = list(members.values())
    out: dict[State, float] = {}

    def assignments(spots: tuple[int, ...], sizes: tuple[int, ...]) -> Iterator[tuple[tuple[int, ...], ...]]:
        if not sizes:
            yield ()
            return
        for chosen in itertools.combinations(spots, sizes[0]):
            rest = tuple(x for x in spots if x not in chosen)
            for tail in assignments(rest, sizes[1:]):
                yield (chosen, *tail)

    def compositions(c: int, left: tuple[int, ...]) -> Iterator[tuple[int, ...]]:
        if not left:
            if c == 0:
                yield ()
            return
        for n in range(min(c, left[0]) + 1):
            for tail in compositions(c - n, left[1:]):
                yield (n, *tail)

    def deal(
        k: int, left: tuple[int, ...], places: tuple[tuple[int, ...], ...], p: float
    ) -> Iterator[tuple[tuple[tuple[int, ...], ...], float]]:
        if k == len(sc.layout):
            yield places, p
            return
        group = sc.layout[k]
        c, m = group.count, len(group.spots)
        for comp in compositions(c, left):
            q = math.prod(math.comb(n_left, n) for n_left, n in zip(left, comp, strict=True)) / math.comb(sum(left), c)
            q *= math.prod(math.factorial(n) for n in comp) * math.factorial(m - c) / math.factorial(m)
            rest = tuple(n_left - n for n_left, n in zip(left, comp, strict=True))
            for assign in assignments(group.spots, comp):
                yield from deal(k + 1, rest, tuple(a + b for a, b in zip(places, assign, strict=True)), p * q)

    for places, p in deal(0, tuple(len(m) for m in classes), tuple(() for _ in classes), 1.0):
        where = [0] * world.n_objects
        for objs, spots in zip(classes, places, strict=True):
            for o, spot in zip(objs, sorted(spots), strict=True):
                where[o] = spot
        for start in sc.robot_start:
            state = State(tuple(where), start)
            out[state] = out.get(state, 0.0) + p / len(sc.robot_start)
    return sorted(out.items())


def canonical_layout_count(world: World) -> int:
    """How many (class make-up, spot assignment) deals :func:`canonical_layouts` enumerates, times starts.

    Computed without allocating, so a caller can refuse before enumerating.
    """
    sizes: dict[tuple[int, ...], int] = {}
    for bins in world.bins_of:
        sizes[bins] = sizes.get(bins, 0) + 1
    sc = world.scenario

    def count(k: int, left: tuple[int, ...]) -> int:
        if k == len(sc.layout):
            return 1
        group = sc.layout[k]
        c, m = group.count, len(group.spots)
        total = 0

        def comps(i: int, c_left: int, comp: tuple[int, ...]) -> None:
            nonlocal total
            if i == len(left):
                if c_left == 0:
                    ways = math.perm(m, c) // math.prod(math.factorial(n) for n in comp)
                    total += ways * count(k + 1, tuple(a - b for a, b in zip(left, comp, strict=True)))
                return
            for n in range(min(c_left, left[i]) + 1):
                comps(i + 1, c_left - n, (*comp, n))

        comps(0, c, ())
        return total

    return len(sc.robot_start) * count(0, tuple(sizes.values()))


def _human_policy(human: Any, world: World) -> Any:
    if isinstance(human, str):
        human = make_human(human)
    if not callable(getattr(human, "distribution", None)):
        raise HumanError(
            f"the oracle needs a stationary human with distribution(world, state); {getattr(human, 'name', human)!r} "
            "has none (switching and replay humans are not stationary: run the oracle per phase)"
        )
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    return human


DEFAULT_SECONDS = 60.0
"""The default CPU-time budget (seconds) of one oracle build and solve: CPU, not wall time,
so that whether a solve is refused (and a study stores the refusal) does not depend on
what else the machine runs."""
DEFAULT_MEMORY = 4 * 2**30
"""The default resident memory budget (bytes) of the process during a solve."""


def _rss() -> int:
    """This process's resident memory in bytes (``/proc/self/statm``; peak ``ru_maxrss`` elsewhere)."""
    try:
        with open("/proc/self/statm", encoding="ascii") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        import resource

        return int(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss) * 1024


@dataclass(frozen=True)
class Budget:
    """What one oracle solve may spend: CPU seconds and resident memory (None: no limit).

    Beyond either it stops with :class:`OracleTooLarge` naming the budget, so a caller
    (a study) can fall back to another reference instead of waiting or swapping.
    """

    seconds: float | None = DEFAULT_SECONDS
    memory: int | None = DEFAULT_MEMORY
    start: float = field(default_factory=time.process_time)

    def check(self, world: World, n_states: int, memory: bool = True) -> None:
        """Raise :class:`OracleTooLarge` if the solve is over its budget (``memory``: check it too)."""
        spent = time.process_time() - self.start
        if self.seconds is not None and spent > self.seconds:
            raise OracleTooLarge(
                f"the oracle for {world.scenario.name!r} is over its budget of {self.seconds:g} s of CPU time "
                f"({n_states} states after {spent:.0f} s); raise --max-seconds or use the best robot as reference"
            )
        if memory and self.memory is not None and _rss() > self.memory:
            raise OracleTooLarge(
                f"the oracle for {world.scenario.name!r} is over its budget of {self.memory / 2**30:g} GB "
                f"of memory ({n_states} states); raise --max-memory or use the best robot as reference"
            )


class _Model:
    """The explored semi-MDP in flat arrays (pairs = (state, robot action), contiguous per state)."""

    def __init__(
        self,
        world: World,
        human: Any,
        failed_actions: bool,
        max_states: int,
        progress: bool = False,
        relabel: Relabel | None = None,
        budget: Budget | None = None,
    ) -> None:
        self.world, self.human = world, human
        self.relabel = relabel
        """Set when states are kept in canonical order (an equivariant human)."""
        self.budget = budget or Budget()
        self.progress = progress
        self.failed_actions, self.max_states = failed_actions, max_states
        self.robot_acts, self.human_acts = world.actions(Agent.ROBOT), world.actions(Agent.HUMAN)
        self.index: dict[State, int] = {}
        self.states: list[State] = []
        self.pair_start: list[int] = []
        self.pair_action: list[int] = []
        self.pair_terminal: list[bool] = []
        self.t_pair: list[int] = []
        self.t_next: list[int] = []
        self.t_prob: list[float] = []
        self.t_tau: list[float] = []
        self._answers: dict[tuple[State, int], list[tuple[int, float, float]]] = {}
        """The human's answers at a (mid-cycle state, robot action seen), as (next state's id,
        duration, probability): a mid-cycle state recurs from many robot-turn states, and the
        ids point at states the index holds anyway, so nothing is stored twice."""
        self._uses_robot_action = bool(getattr(human, "uses_robot_action", False))

    def canonical(self, state: State) -> State:
        """The state the model keeps for ``state`` (itself without symmetry reduction)."""
        return state if self.relabel is None else self.relabel.canonical(state)[0]

    def _id(self, state: State) -> int:
        if self.relabel is not None:
            state = self.relabel.canonical(state)[0]
        k = self.index.get(state)
        if k is None:
            if len(self.states) >= self.max_states:
                raise OracleTooLarge(
                    f"the oracle's model of {self.world.scenario.name!r} exceeds max_states={self.max_states} "
                    f"robot-turn states ({self.world.n_objects} objects); raise max_states (memory and minutes "
                    "grow with it) or use a smaller scenario"
                )
            k = self.index[state] = len(self.states)
            self.states.append(state)
        return k

    def replies(self, mid: State, d_robot: float, robot_action: int) -> list[tuple[State, float, float]]:
        """The human's answers at ``mid``: (next robot-turn state, probability, cycle seconds).

        ``robot_action`` is the robot's action of the cycle if it succeeded, else -1: what
        the human sees in the environment (``base.robot_action_of``).
        """
        seen = robot_action if self._uses_robot_action else -1
        out = []
        for h, p in self.human.distribution(self.world, mid, seen):
            if p > 0.0:
                nxt, _, duration = self.world.table.successor(mid, Agent.HUMAN, h)
                out.append((nxt, p, max(d_robot, duration)))
        return out

    def _answer_ids(self, mid: State, robot_action: int) -> list[tuple[int, float, float]]:
        """:meth:`replies` without the cycle's robot part, as state ids, memoised (the explore loop's)."""
        key = (mid, robot_action if self._uses_robot_action else -1)
        answers = self._answers.get(key)
        if answers is None:
            answers = self._answers[key] = [(self._id(nxt), tau, p) for nxt, p, tau in self.replies(mid, 0.0, key[1])]
        return answers

    def robot_options(self, state: State) -> list[int]:
        """The feasible robot actions, plus the first infeasible one standing for them all (``failed_actions``)."""
        feasible = self.world.feasible_indices(state, Agent.ROBOT)
        if self.failed_actions:
            taken = set(feasible)
            failing = next((i for i in range(len(self.robot_acts)) if i not in taken), None)
            if failing is not None:
                feasible.append(failing)
        return feasible

    def build(self, roots: list[State]) -> None:
        for root in roots:
            self._id(root)
        bar = tqdm(
            desc=f"oracle {self.world.scenario.name}: states",
            unit=" states",
            disable=not self.progress,
            file=sys.stderr,
            dynamic_ncols=True,
            leave=False,  # transient: the result (or a refusal) is the one line that stays
        )
        try:
            self._explore(bar)
            bar.update(len(self.states) - bar.n)  # the last, partial block of states
            bar.set_postfix(known=len(self.states))
        finally:
            bar.close()

    def _explore(self, bar: tqdm) -> None:
        """Breadth-first over robot-turn states; the bar shows states explored and known."""
        table = self.world.table
        wait = table.wait[Agent.ROBOT]
        k = 0
        while k < len(self.states):
            if k % 64 == 0:  # a state may cost planner searches: the clock is read often
                self.budget.check(self.world, len(self.states), memory=k % 2048 == 0)
            if k % 2048 == 0:
                bar.update(k - bar.n)
                bar.set_postfix(known=len(self.states), refresh=False)
                if k and k % 16384 == 0:
                    _check_memory(self.world, len(self.states))
            state = self.states[k]
            self.pair_start.append(len(self.pair_action))
            for a in self.robot_options(state):
                pair = len(self.pair_action)
                self.pair_action.append(a)
                mid, ok, duration = table.successor(state, Agent.ROBOT, a)
                terminal = ok and a == wait and table.is_clean(state.where)  # the completing wait
                self.pair_terminal.append(terminal)
                if terminal:
                    continue
                for nxt, d_human, p in self._answer_ids(mid, a if ok else -1):
                    self.t_pair.append(pair)
                    self.t_next.append(nxt)
                    self.t_prob.append(p)
                    self.t_tau.append(duration if duration > d_human else d_human)
            k += 1


_MIN_FREE_BYTES = 512 * 2**20


def _available_bytes() -> int | None:
    """Memory the kernel says is available (Linux ``MemAvailable``), or None if unknown."""
    try:
        with open("/proc/meminfo", encoding="ascii") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        return None
    return None


def _check_memory(world: World, n_states: int) -> None:
    """Refuse before memory runs out: the model grows by about 3 KB per state."""
    free = _available_bytes()
    if free is not None and free < _MIN_FREE_BYTES:
        raise OracleTooLarge(
            f"the oracle's model of {world.scenario.name!r} stopped at {n_states} states: less than "
            f"{_MIN_FREE_BYTES // 2**20} MB of memory left; lower --max-states or use a smaller scenario"
        )


def _certain_states(
    n: int, pair_state: np.ndarray, terminal: np.ndarray, t_pair: np.ndarray, t_next: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """States from which some policy completes with probability 1, and the pairs it may use."""
    n_pairs = len(terminal)
    alive = np.ones(n, dtype=bool)
    while True:
        leaks = np.bincount(t_pair, weights=~alive[t_next], minlength=n_pairs) > 0
        ok = terminal | ~leaks
        reach = np.zeros(n, dtype=bool)
        reach[pair_state[ok & terminal]] = True
        while True:
            hits = np.bincount(t_pair, weights=reach[t_next], minlength=n_pairs) > 0
            grown = reach.copy()
            grown[pair_state[ok & hits]] = True
            if (grown == reach).all():
                break
            reach = grown
        if (reach == alive).all():
            return alive, ok
        alive = reach


def oracle_rate(
    scenario: str | Scenario | World = "paper2015",
    human: Any = "cooperative",
    *,
    durations: Durations | None = None,
    failed_actions: bool = True,
    max_states: int = 1_500_000,
    tolerance: float = 1e-9,
    max_iterations: int = 200_000,
    progress: bool = False,
    symmetry: bool | None = None,
    max_seconds: float | None = DEFAULT_SECONDS,
    max_memory: int | None = DEFAULT_MEMORY,
) -> OracleResult:
    """The optimal tasks per simulated hour against ``human``, and the policy achieving it.

    Args:
        scenario: scenario name / TOML path / Scenario, or a World (then ``durations`` is ignored).
        human: a stationary human: registry name (``"lazy:p_idle=0.5"``) or an instance
            with ``distribution(world, state)``.
        durations: override the scenario's durations.
        failed_actions: also consider deliberately infeasible actions (a 0.2 s no-op);
            True is the exact model of the environment's action space.
        max_states: stop with :class:`OracleTooLarge` beyond this many states.
        tolerance: value-iteration stopping threshold (seconds).
        max_iterations: cap on sweeps (``converged`` says whether it was hit).
        progress: show a progress bar on stderr with the states explored and known.
        symmetry: keep states up to interchangeable objects (canonical order). None: when
            the human says it is ``equivariant`` (its answer at a relabelled state is its
            answer relabelled), the only case where this is exact.
        max_seconds: CPU-time budget of the build and solve in seconds (None: unlimited).
        max_memory: resident-memory budget in bytes (None: unlimited).

    Raises:
        HumanError: the human is not stationary.
        OracleTooLarge: the model exceeds ``max_states`` or the time or memory budget.
    """
    start = time.perf_counter()
    budget = Budget(max_seconds, max_memory)
    world = scenario if isinstance(scenario, World) else World(scenario, durations)
    policy_human = _human_policy(human, world)
    relabel = Relabel(world)
    if symmetry is None:
        symmetry = bool(getattr(policy_human, "equivariant", False))
    if not (symmetry and relabel.active):
        relabel = None
    deals = layout_count(world.scenario) if relabel is None else canonical_layout_count(world)
    if deals > max_states:  # checked before enumerating them (which would take the memory first)
        raise OracleTooLarge(
            f"the oracle's model of {world.scenario.name!r}: {deals} initial layouts to enumerate, over "
            f"max_states={max_states}; raise max_states or use a smaller scenario"
        )
    layouts = layout_distribution(world) if relabel is None else canonical_layouts(world)
    model = _Model(world, policy_human, failed_actions, max_states, progress, relabel, budget)
    wait = world.durations.wait
    wait_index = world.n_actions(Agent.ROBOT) - 1
    first_replies = tqdm(
        layouts,
        desc=f"oracle {world.scenario.name}: layouts",
        unit=" layouts",
        disable=not progress,
        file=sys.stderr,
        leave=False,
    )
    regen: list[tuple[State, float, float]] = []
    for i, (table, q) in enumerate(first_replies):
        budget.check(world, 0, memory=i % 2048 == 0)  # no state explored yet
        regen += [(nxt, q * p, tau) for nxt, p, tau in model.replies(table, wait, wait_index)]
    model.build([s for s, _ in layouts] + [s for s, _, _ in regen])
    n = len(model.states)
    pair_state = np.repeat(np.arange(n), np.diff([*model.pair_start, len(model.pair_action)]))
    terminal = np.array(model.pair_terminal, dtype=bool)
    t_pair, t_next = np.array(model.t_pair, dtype=np.int64), np.array(model.t_next, dtype=np.int64)
    t_prob, t_tau = np.array(model.t_prob), np.array(model.t_tau)
    n_pairs = len(terminal)
    cost = np.bincount(t_pair, weights=t_prob * t_tau, minlength=n_pairs)
    alive, ok = _certain_states(n, pair_state, terminal, t_pair, t_next)
    starts = np.array(model.pair_start, dtype=np.int64)
    values = np.zeros(n)
    iterations, converged = 0, False
    if alive.any():
        for iterations in range(1, max_iterations + 1):
            q = cost + np.bincount(
                t_pair, weights=t_prob * np.where(alive[t_next], values[t_next], 0.0), minlength=n_pairs
            )
            q = np.where(ok, np.where(terminal, 0.0, q), np.inf)
            new = np.where(alive, np.minimum.reduceat(q, starts), 0.0)
            delta = float(np.max(np.abs(new - values)))
            values = new
            if iterations % 64 == 0:
                budget.check(world, n)
            if delta < tolerance:
                converged = True
                break
    values = np.where(alive, values, np.inf)
    q = cost + np.bincount(t_pair, weights=t_prob * np.where(alive[t_next], values[t_next], 0.0), minlength=n_pairs)
    q = np.where(ok, np.where(terminal, 0.0, q), np.inf)
    best = [
        int(model.pair_action[starts[s] + int(np.argmin(q[starts[s] : starts[s + 1] if s + 1 < n else n_pairs]))])
        for s in range(n)
    ]
    index = model.index
    expected = sum(p * (tau + values[index[model.canonical(s)]]) for s, p, tau in regen)
    rate = 0.0 if math.isinf(expected) else HOUR / expected
    result = OracleResult(
        rate_per_hour=rate,
        seconds_per_task=expected,
        n_states=n,
        n_transitions=len(t_pair),
        n_layouts=len(layouts),
        iterations=iterations,
        converged=converged,
        policy=dict(zip(model.states, best, strict=True)),
        values=dict(zip(model.states, values.tolist(), strict=True)),
        scenario=world.scenario.name,
        human=str(getattr(policy_human, "name", type(policy_human).__name__)),
        seconds=time.perf_counter() - start,
        reduced=relabel is not None,
    )
    logger.info(
        "oracle %s vs %s: %.2f tasks/h, %d states, %d iterations, %.1f s",
        result.scenario,
        result.human,
        rate,
        n,
        iterations,
        result.seconds,
    )
    return result


class OracleRobot:
    """A robot that plays the oracle's optimal policy (greedy in its values).

    Off its model (a state the model never reaches: the partner is not the human the
    policy was solved against) it does not wait for a known state to come back: it asks
    the planner (cooperative model) for the robot's next move, under the progress guard
    every robot obeys (:mod:`hg_marl.agents.progress`): when the state has not changed
    for ``K`` of its turns, it takes the guard's feasible move instead, so it never
    repeats a move that changes nothing (a wait, a refused offer) forever. ``off_model``
    counts the off-model decisions in the current run. On its model the policy is played
    as solved (it is optimal there; a wait against a partner who idles is part of it).

    Args:
        result: a computed :class:`OracleResult`; or None to compute one at the first reset
            from ``human`` and the world it is reset in.
        human: the human the policy is optimal against (when ``result`` is None).
    """

    name = "oracle"

    def __init__(self, result: OracleResult | None = None, human: Any = "cooperative") -> None:
        self.result = result
        self.human = human
        self.last_decision: Decision | None = None
        self.off_model = 0
        """Decisions taken at states outside the model in the current run (0 when the
        partner is the human the policy was solved against)."""
        self._planner: Any = None
        self._relabel: Relabel | None = None
        self.progress = ProgressGuard()

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Compute the policy if needed (``rng`` unused: the policy is deterministic)."""
        if agent is not Agent.ROBOT:
            raise ValueError("OracleRobot plays the robot seat only")
        if self.result is None or self.result.scenario != world.scenario.name:
            self.result = oracle_rate(world, self.human)
        self._wait = world.n_actions(Agent.ROBOT) - 1
        self.off_model = 0
        self.progress.reset()
        self._planner = None
        self._relabel = Relabel(world)

    def act(self, turn: Turn) -> int:
        """The optimal action at the turn's state (the planner's move outside the model)."""
        assert self.result is not None
        self.progress.observe(turn.state)
        action = self.result.action_at(turn.world, turn.state, self._relabel)
        if action is not None:
            seconds = self.result.value_at(turn.world, turn.state, self._relabel)
            self.last_decision = Decision("oracle", int(action), stats=(("expected_seconds", float(seconds)),))
            return int(action)
        self.off_model += 1
        if self.off_model == 1:
            logger.warning("oracle policy has no entry for state %s; falling back to the planner", turn.state)
        return self._fallback(turn)

    def _fallback(self, turn: Turn) -> int:
        """The planner's move; the progress guard's move once the state has not changed for ``K`` turns."""
        world, state = turn.world, turn.state
        if self._planner is None or self._planner.world is not world:
            from hg_marl.agents.planner import Planner

            self._planner = Planner(world)
        start = time.perf_counter()
        intent = self._planner.intent(state, Agent.ROBOT)
        action = intent.robot_action if intent.success else self._wait
        reason = "off model: the planner's move"
        if self.progress.stalled:
            action = self.progress.move(world, state)
            reason = "off model: nothing changed for K turns; the progress guard's move"
        self.last_decision = Decision(
            "planner",
            int(action),
            planner_action=int(intent.robot_action) if intent.success else -1,
            planning_time=time.perf_counter() - start,
            planner_success=intent.success,
            planner_consulted=True,
            expected_human_action=int(intent.human_action) if intent.success else -1,
            reason=reason,
        )
        return int(action)
