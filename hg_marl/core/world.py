"""The task's world: a scenario bound to its rule table, with names, facts and masks.

:class:`World` binds a scenario to its compiled :class:`~hg_marl.core.table.RuleTable`
(the one place where the rules are written; ``docs/task.md`` states them) and answers
every question the environment, the planner, the humans and the oracle ask about the
task. Transitions are deterministic and pure (``step(state, agent, index) -> Outcome``);
the only random choice, the layout drawn at reset, takes the caller's
``numpy.random.Generator``. An infeasible action is legal input: no effect, ``ok=False``,
duration ``failed``.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from hg_marl.core.durations import Durations
from hg_marl.core.scenario import Scenario, load_scenario
from hg_marl.core.table import RuleTable
from hg_marl.core.types import AGENT_NAMES, Action, Agent, Event, Kind, Outcome, State

CACHE_BYTES = 64 << 20
"""Memory each of a world's four memo tables (transitions, facts, two masks) may hold
before it is cleared, whatever the scenario's size: a cap counted in entries alone lets a
large layout's tables outgrow the machine (the figures: ``docs/benchmarks.md``, memo tables)."""


def cache_entries(n_objects: int, n_facts: int, n_actions: int) -> int:
    """How many entries fit :data:`CACHE_BYTES`, from an upper estimate of an entry's size.

    An entry is a dict slot, a key and an array header (the constant term) plus its payload
    (the fact or mask bytes, or an outcome's next state, 16 bytes per object). The estimate
    is above the size ``tracemalloc`` finds (``docs/benchmarks.md``, memo tables), so the
    tables stay under the cap.
    """
    return max(1_000, CACHE_BYTES // (256 + n_facts + n_actions + 16 * n_objects))


class World:
    """A scenario with its rules. Cheap questions are memoised per state.

    Args:
        scenario: a :class:`Scenario`, a built-in name or a TOML path.
        durations: overrides the scenario's action durations.
    """

    def __init__(self, scenario: Scenario | str = "paper2015", durations: Durations | None = None) -> None:
        self.scenario = load_scenario(scenario)
        self.durations = durations or self.scenario.durations
        sc = self.scenario
        self.table = table = RuleTable(sc, self.durations)
        """The compiled rules (feasibility and transitions by action index)."""
        self.n_objects = table.n_objects
        self.n_spots = table.n_spots
        self.n_bins = table.n_bins
        self.hand = table.hand
        """Place codes of the robot's and the human's hands, indexed by Agent."""
        self.bins_of = table.bins_of
        """Per object, every bin that accepts it (a throw lands in the first one the thrower reaches)."""
        self.bin_of = tuple(bins[0] for bins in table.bins_of)
        """Per object, the first bin that accepts it (names and facts; any of ``bins_of`` will do)."""
        self._actions = table.actions
        self._index = table.index
        self.cache_limit = cache_entries(
            table.n_objects,
            len(self.fact_names),
            max(len(table.actions[Agent.ROBOT]), len(table.actions[Agent.HUMAN])),
        )
        """Entries each memo table may hold before it is cleared (:func:`cache_entries`; the cycle's too)."""
        self._step_cache: dict[tuple[State, int, int], Outcome] = {}
        self._facts_cache: dict[State, np.ndarray] = {}
        self._mask_cache: tuple[dict[State, np.ndarray], dict[State, np.ndarray]] = ({}, {})

    # ---- action sets -------------------------------------------------------------
    def actions(self, agent: Agent) -> tuple[Action, ...]:
        """The agent's ground actions; position = the Discrete action index."""
        return self._actions[agent]

    def n_actions(self, agent: Agent) -> int:
        """Size of the agent's Discrete action space."""
        return len(self._actions[agent])

    def index(self, agent: Agent, action: Action) -> int:
        """Discrete index of ``action`` for ``agent``."""
        return self._index[agent][action]

    def goto_target_name(self, target: int) -> str:
        """Readable name of a GOTO target code."""
        n, b = self.n_objects, self.n_bins
        if target < n:
            return self.scenario.objects[target]
        if target < n + b:
            return self.scenario.bins[target - n].name
        return "human"

    def action_name(self, agent: Agent, index: int) -> str:
        """Readable name, e.g. ``pick(tape1)``, ``place(tape2,mat_shared)``, ``goto(trashbin)``."""
        a = self._actions[agent][index]
        kind = a.kind.name.lower()
        if a.kind is Kind.WAIT:
            return "wait"
        if a.kind is Kind.GOTO:
            return f"goto({self.goto_target_name(a.target)})"
        obj = self.scenario.objects[a.obj]
        if a.kind is Kind.PLACE:
            return f"place({obj},{self.scenario.spots[a.target].name})"
        return f"{kind}({obj})"

    @cached_property
    def action_names(self) -> tuple[tuple[str, ...], tuple[str, ...]]:
        """Readable names of every action index, per agent."""
        return tuple(tuple(self.action_name(ag, i) for i in range(self.n_actions(ag))) for ag in Agent)  # type: ignore[return-value]

    # ---- places ------------------------------------------------------------------
    def place_name(self, place: int) -> str:
        """Readable name of a place code."""
        if place < self.n_spots:
            return self.scenario.spots[place].name
        if place < self.n_spots + self.n_bins:
            return self.scenario.bins[place - self.n_spots].name
        return "robot's hand" if place == self.hand[Agent.ROBOT] else "human's hand"

    def is_in_bin(self, place: int) -> bool:
        """Whether a place code is a bin."""
        return self.n_spots <= place < self.n_spots + self.n_bins

    def spot_reachable(self, state: State, agent: Agent, spot: int) -> bool:
        """Whether ``agent`` reaches ``spot`` in ``state``."""
        return self.table.reach[agent][state.robot_at][spot]

    def bin_reachable(self, state: State, agent: Agent, b: int) -> bool:
        """Whether ``agent`` reaches bin ``b`` in ``state``."""
        if agent is Agent.ROBOT:
            return state.robot_at in self.table.bin_robot[b]
        return self.table.bin_human[b]

    def holding(self, state: State, agent: Agent) -> int:
        """Index of the object ``agent`` holds, or -1."""
        hand = self.hand[agent]
        return state.where.index(hand) if hand in state.where else -1

    def is_clean(self, state: State) -> bool:
        """Every object is in a bin that accepts it."""
        return self.table.is_clean(state.where)

    def goto_destination(self, state: State, target: int) -> int:
        """Where ``goto(target)`` takes the robot from ``state``, or -1 if infeasible."""
        return self.table.goto_destination(state, target)

    # ---- rules -------------------------------------------------------------------
    def feasible(self, state: State, agent: Agent, action: Action) -> bool:
        """Whether ``action``'s preconditions hold for ``agent`` in ``state``."""
        index = self._index[agent].get(action)
        return index is not None and self.table.feasible(state, agent, index)

    def apply(self, state: State, agent: Agent, action: Action) -> Outcome:
        """The transition for one agent's action (uncached; see :meth:`step`)."""
        return self._outcome(state, agent, self._index[agent][action])

    def _outcome(self, state: State, agent: Agent, index: int) -> Outcome:
        """The table's transition with its reward and events (for the environment and logs).

        A reply other than ``take`` of the offered object lets the partner's offer lapse
        first; a failed ``take`` of it is a reply too, so the offer lapses after it.
        """
        table = self.table
        nxt, ok, duration = table.successor(state, agent, index)
        kind, o, target, _ = table.specs[agent][index]
        name = AGENT_NAMES[agent]
        objects = self.scenario.objects
        events: list[Event] = []
        offered = state.offer_by == 1 - agent
        take_reply = kind is Kind.TAKE and o == state.offer_obj
        if offered and not take_reply:
            events.append(Event("let_lapse", name, objects[state.offer_obj]))
        if not ok:
            events.append(Event("failed", name, self.action_names[agent][index]))
            if offered and take_reply:
                events.append(Event("let_lapse", name, objects[state.offer_obj]))
            return Outcome(nxt, False, duration, 0.0, tuple(events))
        reward = 0.0
        if kind is Kind.PICK:
            events.append(Event("picked", name, objects[o], self.place_name(state.where[o])))
        elif kind is Kind.THROW:
            events.append(Event("threw", name, objects[o], self.place_name(nxt.where[o])))
        elif kind is Kind.GIVE:
            events.append(Event("offered", name, objects[o]))
        elif kind is Kind.TAKE:
            events.append(Event("took", name, objects[o]))
        elif kind is Kind.PLACE:
            events.append(Event("placed", name, objects[o], self.place_name(target)))
        elif kind is Kind.GOTO:
            events.append(Event("moved", name, "", self.scenario.robot_locations[nxt.robot_at]))
        elif table.solves(state, agent, index):
            reward = 1.0
            events.append(Event("completed", name, "", "task"))
        return Outcome(nxt, True, duration, reward, tuple(events))

    def step(self, state: State, agent: Agent, index: int) -> Outcome:
        """Memoised transition by action index (the environment's hot path)."""
        key = (state, agent, index)
        out = self._step_cache.get(key)
        if out is None:
            if len(self._step_cache) > self.cache_limit:
                self._step_cache.clear()
            out = self._step_cache[key] = self._outcome(state, agent, index)
        return out

    # ---- observations ------------------------------------------------------------
    @cached_property
    def fact_names(self) -> tuple[str, ...]:
        """Name of each fact in the observation vector, in order."""
        sc = self.scenario
        things = [*sc.objects, *(b.name for b in sc.bins)]
        return (
            *(f"isReachableBy({x},robot)" for x in things),
            *(f"isReachableBy({x},human)" for x in things),
            *(f"isIn({o},{'|'.join(sc.bins[k].name for k in self.bins_of[i])})" for i, o in enumerate(sc.objects)),
            "isReachableBy(human,robot)",
            *(f"hasInHand(robot,{o})" for o in sc.objects),
            *(f"hasInHand(human,{o})" for o in sc.objects),
            *(f"isOffering(robot,{o})" for o in sc.objects),
            *(f"isOffering(human,{o})" for o in sc.objects),
        )

    @property
    def n_facts(self) -> int:
        """Length of the fact vector."""
        return len(self.fact_names)

    @cached_property
    def fact_lookup(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
        """Every fact but the offers as a look-up: ``table[robot_at][fact, place of its object]``.

        Each fact of the paper's vector depends on one object's place and the robot's
        location (a bin's or the human's reachability on the location only, any object
        standing in), so one fancy index computes the vector.
        """
        t, n, b, m = self.table, self.n_objects, self.n_bins, self.n_spots
        n_locs, places = t.n_locations, range(t.n_places)
        rows: list[tuple[int, list[list[bool]]]] = []  # (object, value per location and place)
        for agent in (Agent.ROBOT, Agent.HUMAN):
            for o in range(n):
                rows.append((o, [[p < m and t.reach[agent][at][p] for p in places] for at in range(n_locs)]))
            for k in range(b):
                reached = [at in t.bin_robot[k] if agent is Agent.ROBOT else t.bin_human[k] for at in range(n_locs)]
                rows.append((0, [[reached[at]] * t.n_places for at in range(n_locs)]))
        rows += [(o, [[p in t.done[o] for p in places]] * n_locs) for o in range(n)]
        rows.append((0, [[at in t.handover] * t.n_places for at in range(n_locs)]))
        for hand in self.hand:
            rows += [(o, [[p == hand for p in places]] * n_locs) for o in range(n)]
        lookup = np.array([[values[at] for _, values in rows] for at in range(n_locs)], dtype=np.int8)
        objects = np.array([o for o, _ in rows], dtype=np.intp)
        return lookup, np.arange(len(rows)), objects, len(rows)

    def compute_facts(self, state: State) -> np.ndarray:
        """The paper's boolean fact vector for ``state`` (a fresh int8 array)."""
        lookup, rows, objects, n_fixed = self.fact_lookup
        fixed = lookup[state.robot_at][rows, np.array(state.where, dtype=np.intp)[objects]]
        out = np.zeros(n_fixed + 2 * self.n_objects, dtype=np.int8)
        out[:n_fixed] = fixed
        if state.offer_by >= 0:
            out[n_fixed + state.offer_by * self.n_objects + state.offer_obj] = 1
        return out

    def facts(self, state: State) -> np.ndarray:
        """Memoised, read-only :meth:`compute_facts`."""
        arr = self._facts_cache.get(state)
        if arr is None:
            arr = self.compute_facts(state)
            arr.flags.writeable = False
            if len(self._facts_cache) > self.cache_limit:
                self._facts_cache.clear()
            self._facts_cache[state] = arr
        return arr

    def feasible_indices(self, state: State, agent: Agent) -> list[int]:
        """Sorted indices of the actions whose preconditions hold (see ``RuleTable.feasible_indices``)."""
        return self.table.feasible_indices(state, agent)

    def mask(self, state: State, agent: Agent) -> np.ndarray:
        """Memoised, read-only int8 action mask: 1 where the action is feasible."""
        cache = self._mask_cache[agent]
        arr = cache.get(state)
        if arr is None:
            arr = np.zeros(self.n_actions(agent), dtype=np.int8)
            arr[self.feasible_indices(state, agent)] = 1
            arr.flags.writeable = False
            if len(cache) > self.cache_limit:
                cache.clear()
            cache[state] = arr
        return arr

    # ---- reset -------------------------------------------------------------------
    def initial_state(self, rng: np.random.Generator) -> State:
        """A fresh table drawn from the scenario's layout distribution."""
        sc = self.scenario
        order = rng.permutation(self.n_objects)
        where = [0] * self.n_objects
        k = 0
        for group in sc.layout:
            chosen = rng.choice(len(group.spots), size=group.count, replace=False)
            for c in chosen:
                where[int(order[k])] = group.spots[int(c)]
                k += 1
        start = sc.robot_start[int(rng.integers(len(sc.robot_start)))]
        return State(tuple(where), start)

    def initial_states(self, rng: np.random.Generator, count: int) -> tuple[np.ndarray, np.ndarray]:
        """``count`` tables drawn at once: ``(where (count, objects), robot_at (count,))``.

        The same distribution as :meth:`initial_state` (objects shuffled, dealt to the
        layout groups in order, each group taking an ordered sample of distinct spots, a
        uniform start), drawn with argsorts of uniform keys instead of one call per table;
        a test checks both draw every table of the layout distribution.
        """
        sc = self.scenario
        order = np.argsort(rng.random((count, self.n_objects)), axis=1)
        where = np.zeros((count, self.n_objects), dtype=np.int64)
        rows = np.arange(count)[:, None]
        k = 0
        for group in sc.layout:
            spots = np.array(group.spots, dtype=np.int64)
            chosen = np.argsort(rng.random((count, len(spots))), axis=1)[:, : group.count]
            where[rows, order[:, k : k + group.count]] = spots[chosen]
            k += group.count
        starts = np.array(sc.robot_start, dtype=np.int64)
        return where, starts[rng.integers(len(starts), size=count)]
