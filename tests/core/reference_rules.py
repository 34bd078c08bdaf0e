"""A reference implementation of the task's rules, written from ``docs/task.md`` alone.

Deliberately naive (one ``if`` per rule, on ``Action`` objects, reach read from the
scenario every time): the compiled :class:`~hg_marl.core.table.RuleTable` must agree
with it on every state and action (``test_table.py``).
"""

from __future__ import annotations

from hg_marl.core import Action, Agent, Kind, Scenario, State


def accepts(scenario: Scenario, b: int, o: int) -> bool:
    """Whether bin ``b`` accepts object ``o`` (an empty bin colour accepts any)."""
    return scenario.bins[b].colour in ("", scenario.object_colours[o])


def bin_reached(scenario: Scenario, state: State, agent: Agent, b: int) -> bool:
    """Whether ``agent`` reaches bin ``b`` in ``state``."""
    reach = scenario.bins[b].reach
    return state.robot_at in reach.robot_from if agent is Agent.ROBOT else reach.human


def throw_bin(scenario: Scenario, state: State, agent: Agent, o: int) -> int:
    """The first bin accepting ``o`` that ``agent`` reaches, or -1."""
    for b in range(len(scenario.bins)):
        if accepts(scenario, b, o) and bin_reached(scenario, state, agent, b):
            return b
    return -1


def goto_reach(scenario: Scenario, state: State, target: int) -> frozenset[int] | None:
    """The robot locations from which ``goto(target)``'s target is reachable (None: not a goto target now)."""
    n, m = len(scenario.objects), len(scenario.spots)
    if target < n:
        spot = state.where[target]
        return scenario.spots[spot].reach.robot_from if spot < m else None
    if target < n + len(scenario.bins):
        return scenario.bins[target - n].reach.robot_from
    return scenario.handover_locations


def feasible(scenario: Scenario, state: State, agent: Agent, action: Action) -> bool:
    """Whether ``action``'s preconditions hold (see ``docs/task.md``)."""
    m, b = len(scenario.spots), len(scenario.bins)
    hand = m + b + int(agent)
    kind, o = action.kind, action.obj
    if kind is Kind.WAIT:
        return True
    if kind is Kind.GOTO:
        reach = goto_reach(scenario, state, action.target)
        return agent is Agent.ROBOT and bool(reach) and state.robot_at not in reach  # type: ignore[operator]
    holding_any = hand in state.where
    if kind is Kind.PICK:
        spot = state.where[o]
        if spot >= m or holding_any:
            return False
        reach = scenario.spots[spot].reach
        return state.robot_at in reach.robot_from if agent is Agent.ROBOT else reach.human
    if kind is Kind.TAKE:
        return state.offer_by == int(agent.other) and state.offer_obj == o and not holding_any
    if state.where[o] != hand:
        return False
    if kind is Kind.THROW:
        return throw_bin(scenario, state, agent, o) >= 0
    if kind is Kind.GIVE:
        return state.robot_at in scenario.handover_locations
    s = action.target
    return agent is Agent.HUMAN and scenario.spots[s].reach.human and s not in state.where


def successor(scenario: Scenario, state: State, agent: Agent, action: Action) -> tuple[State, bool]:
    """The next state and whether the action succeeded."""
    m, b = len(scenario.spots), len(scenario.bins)
    if state.offer_by == int(agent.other) and not (action.kind is Kind.TAKE and action.obj == state.offer_obj):
        state = State(state.where, state.robot_at)  # any other reply lets the offer lapse
    if not feasible(scenario, state, agent, action):
        if state.offer_by == int(agent.other):
            state = State(state.where, state.robot_at)  # a failed take is a reply too
        return state, False
    where = list(state.where)
    o = action.obj
    at, by, obj = state.robot_at, state.offer_by, state.offer_obj
    if action.kind is Kind.PICK:
        where[o] = m + b + int(agent)
    elif action.kind is Kind.THROW:
        where[o] = m + throw_bin(scenario, state, agent, o)
    elif action.kind is Kind.GIVE:
        by, obj = int(agent), o
    elif action.kind is Kind.TAKE:
        where[o] = m + b + int(agent)
        by, obj = -1, -1
    elif action.kind is Kind.PLACE:
        where[o] = action.target
    elif action.kind is Kind.GOTO:
        reach = goto_reach(scenario, state, action.target)
        assert reach
        at = min(reach)
    return State(tuple(where), at, by, obj), True


def is_clean(scenario: Scenario, state: State) -> bool:
    """Every object is in a bin that accepts it."""
    m = len(scenario.spots)
    return all(p >= m and p - m < len(scenario.bins) and accepts(scenario, p - m, o) for o, p in enumerate(state.where))


def facts(scenario: Scenario, state: State) -> list[int]:
    """The paper's fact vector, in ``World.fact_names`` order."""
    m, b, n = len(scenario.spots), len(scenario.bins), len(scenario.objects)
    out: list[bool] = []
    for agent in (Agent.ROBOT, Agent.HUMAN):
        for p in state.where:
            reach = scenario.spots[p].reach if p < m else None
            out.append(
                reach is not None and (state.robot_at in reach.robot_from if agent is Agent.ROBOT else reach.human)
            )
        out += [bin_reached(scenario, state, agent, k) for k in range(b)]
    out += [m <= p < m + b and accepts(scenario, p - m, o) for o, p in enumerate(state.where)]
    out.append(state.robot_at in scenario.handover_locations)
    out += [p == m + b for p in state.where]
    out += [p == m + b + 1 for p in state.where]
    for giver in (0, 1):
        out += [state.offer_by == giver and state.offer_obj == o for o in range(n)]
    return [int(x) for x in out]
