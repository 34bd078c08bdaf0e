"""The task's rules: action sets, feasibility, transitions, facts and masks.

:class:`World` binds a scenario to its ground actions and answers every question the
environment, the planner, the humans and the oracle ask about the task, so none of
them can drift from the rules. Transitions are deterministic and pure
(``step(state, agent, index) -> Outcome``); the only random choice, the layout drawn
at reset, takes the caller's ``numpy.random.Generator``.

Rules (DESIGN.md section 2):

- ``pick(o)``: hand empty, ``o`` on a spot the agent reaches.
- ``throw(o)``: holding ``o``, and the bin for ``o``'s colour reachable.
- ``give(o)``: holding ``o``, robot at a handover location; the agent is then offering.
- ``take(o)``: the partner offered ``o`` on its last turn, hand empty. Any other reply
  lets the offer lapse and the giver keeps ``o``.
- ``place(o, s)`` (human): holding ``o``, ``s`` free and within the human's reach.
- ``goto(x)`` (robot): ``x`` (an object on a spot, a bin, the human) is out of reach
  now and reachable from some location; the robot moves to the first such location in
  scenario order.
- ``wait``: always feasible; the robot waiting on a clean table completes the task
  (reward 1).

An infeasible action is legal input: no effect, ``ok=False``, duration ``failed``.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from hg_marl.core.durations import Durations
from hg_marl.core.scenario import Scenario, load_scenario
from hg_marl.core.types import WAIT, Action, Agent, Event, Kind, Outcome, State

_CACHE_LIMIT = 2_000_000


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
        self.n_objects = len(sc.objects)
        self.n_spots = len(sc.spots)
        self.n_bins = len(sc.bins)
        self.hand = (self.n_spots + self.n_bins, self.n_spots + self.n_bins + 1)
        """Place codes of the robot's and the human's hands, indexed by Agent."""
        self.bin_of = sc.bin_of
        self._spot_robot = tuple(s.reach.robot_from for s in sc.spots)
        self._spot_human = tuple(s.reach.human for s in sc.spots)
        self._bin_robot = tuple(b.reach.robot_from for b in sc.bins)
        self._bin_human = tuple(b.reach.human for b in sc.bins)
        self._actions = (self._robot_actions(), self._human_actions())
        self._index = tuple({a: i for i, a in enumerate(acts)} for acts in self._actions)
        self._step_cache: dict[tuple[State, int, int], Outcome] = {}
        self._facts_cache: dict[State, np.ndarray] = {}
        self._mask_cache: tuple[dict[State, np.ndarray], dict[State, np.ndarray]] = ({}, {})

    # ---- action sets -------------------------------------------------------------
    def _robot_actions(self) -> tuple[Action, ...]:
        n = self.n_objects
        acts = [Action(k, o) for k in (Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE) for o in range(n)]
        acts += [Action(Kind.GOTO, -1, t) for t in range(n + self.n_bins + 1)]
        return (*acts, WAIT)

    def _human_actions(self) -> tuple[Action, ...]:
        n = self.n_objects
        acts = [Action(k, o) for k in (Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE) for o in range(n)]
        acts += [Action(Kind.PLACE, o, s) for o in range(n) for s in range(self.n_spots)]
        return (*acts, WAIT)

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
        if agent is Agent.ROBOT:
            return state.robot_at in self._spot_robot[spot]
        return self._spot_human[spot]

    def bin_reachable(self, state: State, agent: Agent, b: int) -> bool:
        """Whether ``agent`` reaches bin ``b`` in ``state``."""
        if agent is Agent.ROBOT:
            return state.robot_at in self._bin_robot[b]
        return self._bin_human[b]

    def holding(self, state: State, agent: Agent) -> int:
        """Index of the object ``agent`` holds, or -1."""
        hand = self.hand[agent]
        for o, p in enumerate(state.where):
            if p == hand:
                return o
        return -1

    def is_clean(self, state: State) -> bool:
        """Every object is in its bin."""
        m = self.n_spots
        return all(p == m + self.bin_of[o] for o, p in enumerate(state.where))

    def goto_destination(self, state: State, target: int) -> int:
        """Where ``goto(target)`` takes the robot from ``state``, or -1 if infeasible."""
        n, b = self.n_objects, self.n_bins
        if target < n:
            spot = state.where[target]
            if spot >= self.n_spots:
                return -1
            reach = self._spot_robot[spot]
        elif target < n + b:
            reach = self._bin_robot[target - n]
        else:
            reach = self.scenario.handover_locations
        if state.robot_at in reach or not reach:
            return -1
        return min(reach)

    # ---- rules -------------------------------------------------------------------
    def feasible(self, state: State, agent: Agent, action: Action) -> bool:
        """Whether ``action``'s preconditions hold for ``agent`` in ``state``."""
        kind, o = action.kind, action.obj
        if kind is Kind.WAIT:
            return True
        if kind is Kind.GOTO:
            return agent is Agent.ROBOT and self.goto_destination(state, action.target) >= 0
        hand = self.hand[agent]
        where = state.where
        if kind is Kind.PICK:
            p = where[o]
            return p < self.n_spots and hand not in where and self.spot_reachable(state, agent, p)
        if kind is Kind.TAKE:
            return state.offer_by == agent.other and state.offer_obj == o and hand not in where
        if where[o] != hand:
            return False
        if kind is Kind.THROW:
            return self.bin_reachable(state, agent, self.bin_of[o])
        if kind is Kind.GIVE:
            return state.robot_at in self.scenario.handover_locations
        # PLACE
        s = action.target
        return agent is Agent.HUMAN and self._spot_human[s] and s not in where

    def apply(self, state: State, agent: Agent, action: Action) -> Outcome:
        """The transition for one agent's action (uncached; see :meth:`step`)."""
        name = agent.label
        objects = self.scenario.objects
        events: list[Event] = []
        if state.offer_by == agent.other and not (action.kind is Kind.TAKE and action.obj == state.offer_obj):
            events.append(Event("let_lapse", name, objects[state.offer_obj]))
            state = state._replace(offer_by=-1, offer_obj=-1)
        if not self.feasible(state, agent, action):
            events.append(Event("failed", name, self.action_name(agent, self.index(agent, action))))
            if state.offer_by == agent.other:  # a failed take is a reply too: the offer lapses
                events.append(Event("let_lapse", name, objects[state.offer_obj]))
                state = state._replace(offer_by=-1, offer_obj=-1)
            return Outcome(state, False, self.durations.failed, 0.0, tuple(events))
        kind, o = action.kind, action.obj
        where = list(state.where)
        reward = 0.0
        if kind is Kind.PICK:
            events.append(Event("picked", name, objects[o], self.place_name(where[o])))
            where[o] = self.hand[agent]
        elif kind is Kind.THROW:
            where[o] = self.n_spots + self.bin_of[o]
            events.append(Event("threw", name, objects[o], self.place_name(where[o])))
        elif kind is Kind.GIVE:
            events.append(Event("offered", name, objects[o]))
            state = state._replace(offer_by=int(agent), offer_obj=o)
        elif kind is Kind.TAKE:
            where[o] = self.hand[agent]
            events.append(Event("took", name, objects[o]))
            state = state._replace(offer_by=-1, offer_obj=-1)
        elif kind is Kind.PLACE:
            where[o] = action.target
            events.append(Event("placed", name, objects[o], self.place_name(action.target)))
        elif kind is Kind.GOTO:
            dest = self.goto_destination(state, action.target)
            state = state._replace(robot_at=dest)
            events.append(Event("moved", name, "", self.scenario.robot_locations[dest]))
        elif agent is Agent.ROBOT and self.is_clean(state):
            reward = 1.0
            events.append(Event("completed", name, "", "task"))
        new = state._replace(where=tuple(where))
        return Outcome(new, True, self.durations.of(kind), reward, tuple(events))

    def step(self, state: State, agent: Agent, index: int) -> Outcome:
        """Memoised :meth:`apply` by action index (the environment's hot path)."""
        key = (state, agent, index)
        out = self._step_cache.get(key)
        if out is None:
            if len(self._step_cache) > _CACHE_LIMIT:
                self._step_cache.clear()
            out = self._step_cache[key] = self.apply(state, agent, self._actions[agent][index])
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
            *(f"isIn({o},{sc.bins[self.bin_of[i]].name})" for i, o in enumerate(sc.objects)),
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

    def compute_facts(self, state: State) -> np.ndarray:
        """The paper's boolean fact vector for ``state`` (a fresh int8 array)."""
        n, b, m = self.n_objects, self.n_bins, self.n_spots
        where = state.where
        out: list[bool] = []
        for agent in (Agent.ROBOT, Agent.HUMAN):
            out += [p < m and self.spot_reachable(state, agent, p) for p in where]
            out += [self.bin_reachable(state, agent, k) for k in range(b)]
        out += [p == m + self.bin_of[o] for o, p in enumerate(where)]
        out.append(state.robot_at in self.scenario.handover_locations)
        out += [p == self.hand[Agent.ROBOT] for p in where]
        out += [p == self.hand[Agent.HUMAN] for p in where]
        for giver in (Agent.ROBOT, Agent.HUMAN):
            out += [state.offer_by == giver and state.offer_obj == o for o in range(n)]
        return np.array(out, dtype=np.int8)

    def facts(self, state: State) -> np.ndarray:
        """Memoised, read-only :meth:`compute_facts`."""
        arr = self._facts_cache.get(state)
        if arr is None:
            arr = self.compute_facts(state)
            arr.flags.writeable = False
            if len(self._facts_cache) > _CACHE_LIMIT:
                self._facts_cache.clear()
            self._facts_cache[state] = arr
        return arr

    def feasible_indices(self, state: State, agent: Agent) -> list[int]:
        """Indices of the actions whose preconditions hold (a lapsing offer considered).

        Enumerates what the agent's hand and reach allow instead of testing every
        action, so it costs O(objects + spots), not O(actions); a property test checks
        it against :meth:`feasible` action by action.
        """
        idx = self._index[agent]
        where = state.where
        held = self.holding(state, agent)
        out: list[int] = []
        if held < 0:
            for o, p in enumerate(where):
                if p < self.n_spots and self.spot_reachable(state, agent, p):
                    out.append(idx[Action(Kind.PICK, o)])
            if state.offer_by == agent.other:
                out.append(idx[Action(Kind.TAKE, state.offer_obj)])
        else:
            if self.bin_reachable(state, agent, self.bin_of[held]):
                out.append(idx[Action(Kind.THROW, held)])
            if state.robot_at in self.scenario.handover_locations:
                out.append(idx[Action(Kind.GIVE, held)])
            if agent is Agent.HUMAN:
                occupied = set(where)
                out += [
                    idx[Action(Kind.PLACE, held, s)]
                    for s in range(self.n_spots)
                    if self._spot_human[s] and s not in occupied
                ]
        if agent is Agent.ROBOT:
            n_targets = self.n_objects + self.n_bins + 1
            out += [idx[Action(Kind.GOTO, -1, t)] for t in range(n_targets) if self.goto_destination(state, t) >= 0]
        out.append(idx[WAIT])
        out.sort()
        return out

    def mask(self, state: State, agent: Agent) -> np.ndarray:
        """Memoised, read-only int8 action mask: 1 where the action is feasible."""
        cache = self._mask_cache[agent]
        arr = cache.get(state)
        if arr is None:
            arr = np.zeros(self.n_actions(agent), dtype=np.int8)
            arr[self.feasible_indices(state, agent)] = 1
            arr.flags.writeable = False
            if len(cache) > _CACHE_LIMIT:
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
