"""The rule table's transitions compiled per action index for the search's inner loop.

:meth:`RuleTable.successor_feasible` decodes an action's kind and branches on it for
every edge; the search applies thousands of edges per plan, so :class:`Steps` decodes
each action once into ``(code, object, value, duration)`` and :meth:`Steps.successors`
applies a whole candidate list in one call, with the canonical key and the bound's
sums of each successor (what :class:`~.space.Space` memoises per state). The rules stay
the core's: every value is read from the :class:`RuleTable`, and a test checks
:meth:`Steps.apply` against ``successor_feasible`` on every action of every state of a
seeded walk.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from operator import getitem
from typing import Any

from hg_marl.core import Kind, State
from hg_marl.core.table import RuleTable

SET, TAKE, THROW, GIVE, GOTO, STAY = range(6)
"""Step codes: the object goes to a fixed place (pick, place); a take (the same, and the
offer is answered); a throw (the place depends on where the robot stands); a give; a
goto; nothing moves (wait)."""

_new = tuple.__new__
"""Builds a ``NamedTuple`` without the Python-level ``__new__`` (same value, no frame)."""

Step = tuple[int, int, int, float]
Successor = tuple[int, State, float, Any, tuple[float, ...]]
"""(action, next state, duration, canonical key, the bound's sums)."""


class Steps:
    """Per agent and action index, the action's effect decoded once."""

    def __init__(self, table: RuleTable) -> None:
        self.table = table
        self.rows: tuple[tuple[Step, ...], ...] = tuple(
            tuple(self._decode(table, agent, spec) for spec in table.specs[agent]) for agent in (0, 1)
        )

    @staticmethod
    def _decode(table: RuleTable, agent: int, spec: tuple[Kind, int, int, float]) -> Step:
        kind, o, target, d = spec
        if kind is Kind.PICK:
            return (SET, o, table.hand[agent], d)
        if kind is Kind.PLACE:
            return (SET, o, target, d)
        if kind is Kind.TAKE:
            return (TAKE, o, table.hand[agent], d)
        if kind is Kind.THROW:
            return (THROW, o, -1, d)
        if kind is Kind.GIVE:
            return (GIVE, o, agent, d)
        if kind is Kind.GOTO:
            return (GOTO, -1, target, d)
        return (STAY, -1, -1, d)

    def apply(self, state: State, agent: int, index: int) -> tuple[State, float]:
        """Next state and duration of a feasible action (what ``successor_feasible`` returns)."""
        out = self.successors(state, agent, (index,), lambda s: s, lambda s, k: ())
        return out[0][1], out[0][2]

    def successors(
        self,
        state: State,
        agent: int,
        actions: Iterable[int],
        key_of: Callable[[State], Any],
        sums_of: Callable[[State, Any], tuple[float, ...] | None],
        codes: list[list[int]] | None = None,
        sums: dict[Any, Any] | None = None,
    ) -> list[Successor]:
        """The feasible ``actions`` applied to ``state``, dead ends (no sums) left out.

        With ``codes`` (the space's key terms per object and place) the canonical key is
        computed here, as :meth:`.Space.key` does for a symmetric space, and ``sums`` (the space's
        memo by key) is looked up before ``sums_of`` is called; without them ``key_of``
        and ``sums_of`` are asked.
        """
        table = self.table
        where, at, by, obj = state
        if by >= 0 and by != agent:
            by = obj = -1  # the partner's offer lapses (a take answers it: handled below)
        rows = self.rows[agent]
        throw_to = table.throw_to[agent][at]
        goto_obj = table.goto_obj[at]
        goto_static = table.goto_static[at]
        n = table.n_objects
        memo = sums if sums is not None else {}
        missing = memo  # a sentinel no value can be
        out: list[Successor] = []
        # with ``codes`` the key's multiset is an integer sum above its low bits (see
        # :meth:`.Space.key`), so a successor's is the parent's with one object's term replaced
        parent = sum(map(getitem, codes, where)) if codes is not None else 0
        for a in actions:
            code, o, x, d = rows[a]
            if code <= THROW:  # SET, TAKE, THROW: one object moves
                b, ob = by, obj
                if code == THROW:
                    x = throw_to[o]
                elif code == TAKE:
                    b = ob = -1
                moved = list(where)
                moved[o] = x
                s: State = _new(State, (tuple(moved), at, b, ob))
                if codes is not None:
                    row = codes[o]
                    key = parent - row[where[o]] + row[x] + 4 * at + b + 1
                else:
                    key = key_of(s)
            else:
                a2 = at
                if code == GIVE:
                    b, ob = x, o
                else:
                    b, ob = by, obj
                    if code == GOTO:
                        a2 = goto_obj[where[x]] if x < n else goto_static[x - n]
                s = _new(State, (where, a2, b, ob))
                key = parent + 4 * a2 + b + 1 if codes is not None else key_of(s)
            sm = memo.get(key, missing)
            if sm is missing:
                sm = sums_of(s, key)
            if sm is not None:
                out.append((a, s, d, key, sm))
        return out
