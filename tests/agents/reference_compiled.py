"""The compiled partners' Python enumeration, kept as the reference of the array builder's tables.

``compile_human`` once enumerated the (mid-cycle state, robot action seen) keys one state
at a time; it now reads them from the model builder (``agents/compiled.py:
answer_table``). ``tests/env/test_compiled_tables.py`` requires the same keys, answers and
cumulative probabilities.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Sequence
from typing import Any

import numpy as np

from hg_marl.agents.compiled import MAX_KEYS, CompileError, Packer
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.core import Agent, State, World


def enumerate_answers(
    world: World, human: Any, max_keys: int = MAX_KEYS, progress: bool = False, closure: Sequence[Any] = ()
) -> dict[tuple[State, int], list[tuple[int, float]]]:
    """Every (mid-cycle state, robot action seen) the human can face, with its distribution.

    Robot-turn states come from the layout distribution and, breadth-first, from every
    robot action (feasible ones and one failing one: all failing actions lead to the same
    mid-cycle state) followed by every answer of the human. The completing ``wait`` is
    followed by the human's move on the clean table (episodic mode) and by the re-drawn
    tables (continuing mode), both enumerated. ``closure``: other humans whose answers
    also lead on (a switching partner's other phases reach states this one alone never
    would); only ``human``'s own answers are stored.
    """
    table = world.table
    uses = bool(getattr(human, "uses_robot_action", False))
    n_robot = world.n_actions(Agent.ROBOT)
    wait = table.wait[Agent.ROBOT]
    layouts = [s for s, _ in layout_distribution(world)]
    answers: dict[tuple[State, int], list[tuple[int, float]]] = {}
    seen_states: set[State] = set(layouts)
    queue: deque[State] = deque(layouts)

    def answer(mid: State, seen: int, expand: bool) -> None:
        key = (mid, seen if uses else -1)
        dist = answers.get(key)
        if dist is None:
            if len(answers) >= max_keys:
                raise CompileError(
                    f"scenario: {world.scenario.name!r} against {getattr(human, 'name', human)!r} exceeds the "
                    f"compiler's budget of {max_keys} states (max_keys); use a smaller scenario"
                )
            dist = answers[key] = [(h, p) for h, p in human.distribution(world, mid, key[1]) if p > 0.0]
        if expand:
            moves = {h for h, _ in dist}
            for other in closure:
                other_seen = seen if getattr(other, "uses_robot_action", False) else -1
                moves.update(h for h, p in other.distribution(world, mid, other_seen) if p > 0.0)
            for h in sorted(moves):
                nxt, _, _ = table.successor(mid, Agent.HUMAN, h)
                if nxt not in seen_states:
                    seen_states.add(nxt)
                    queue.append(nxt)

    for layout in layouts:  # continuing mode: the re-drawn table meets the human after the robot's wait
        answer(layout, wait, True)
    while queue:
        state = queue.popleft()
        feasible = table.feasible_indices(state, Agent.ROBOT)
        taken = set(feasible)
        failing = next((i for i in range(n_robot) if i not in taken), None)
        for a in [*feasible, *([failing] if failing is not None else [])]:
            mid, ok, _ = table.successor(state, Agent.ROBOT, a)
            terminal = ok and table.solves(state, Agent.ROBOT, a)
            answer(mid, a if ok else -1, not terminal)
    return answers


def reference_arrays(world: World, answers: dict[tuple[State, int], list[tuple[int, float]]]) -> dict[str, np.ndarray]:
    """Sorted keys, starts, actions and ``cum`` as the Python compiler computed them, one key at a time."""
    packer = Packer(world)
    items = sorted((packer.pack_one(s, seen), d) for (s, seen), d in answers.items())
    keys = np.array([k for k, _ in items], dtype=np.int64)
    sizes = np.array([len(d) for _, d in items], dtype=np.int64)
    starts = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    actions = np.array([h for _, d in items for h, _ in d], dtype=np.int64)
    cum = np.empty(len(actions))
    for i, (_, dist) in enumerate(items):
        p = np.array([q for _, q in dist])
        c = np.cumsum(p) / p.sum()
        c[-1] = 1.0
        cum[starts[i] : starts[i + 1]] = i + c
    return {"keys": keys, "starts": starts, "actions": actions, "cum": cum}


def reference_robot_states(world: World) -> set[State]:
    """The compiled robot's states as its Python enumeration visited them (before the builder)."""
    table = world.table
    n_human = world.n_actions(Agent.HUMAN)
    known: set[State] = set()
    queue: deque[State] = deque()

    def reach(state: State) -> None:
        if state not in known:
            known.add(state)
            queue.append(state)

    def answers(mid: State) -> None:
        feasible = table.feasible_indices(mid, Agent.HUMAN)
        taken = set(feasible)
        failing = next((i for i in range(n_human) if i not in taken), None)
        for h in [*feasible, *([failing] if failing is not None else [])]:
            reach(table.successor(mid, Agent.HUMAN, h)[0])

    layouts = [s for s, _ in layout_distribution(world)]
    for layout in layouts:
        reach(layout)
    for layout in layouts:  # continuing mode: the re-drawn table meets the human first
        answers(layout)
    while queue:  # every feasible robot action
        state = queue.popleft()
        for a in table.feasible_indices(state, Agent.ROBOT):
            mid, ok, _ = table.successor(state, Agent.ROBOT, a)
            if ok and table.solves(state, Agent.ROBOT, a):
                continue
            answers(mid)
    return known
