"""The search space's static tables: which kinds and ground actions can be a next step.

Built once per :class:`~.space.Space` (kept apart so that :mod:`.space` holds what the
search calls per state): for each agent, robot location, object and status, the kinds
that are the next step of an applicable method (:func:`next_kinds`) and the ground
actions among them whose reach holds there, with their symmetry signatures
(:func:`candidate_entries`), split by what the agent's hand must hold for them to pass
(:func:`split_entries`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from hg_marl.core import Agent, Kind

if TYPE_CHECKING:
    from hg_marl.agents.planner.space import Space

Entry = tuple[Kind, int, object, int]
"""A tabulated candidate: (kind, action index, symmetry signature or None, PLACE spot or -1)."""

Rows = tuple[list[list[list[tuple[Entry, ...]]]], ...]
"""``rows[agent][robot_at][o][status]``."""


def next_kinds(space: Space) -> tuple[list[list[list[tuple[Kind, ...]]]], ...]:
    """``next[agent][robot_at][o][status]``: kinds that are a next step of an applicable method."""
    d = space.domain
    out: tuple[list[list[list[tuple[Kind, ...]]]], ...] = ([], [])
    for agent in Agent:
        for at in range(space.n_locs):
            per_o = []
            for o in range(d.n_objects):
                rows = []
                for st in range(d.n_status):
                    kinds: set[Kind] = set()
                    for _, w in d.works(o, st, at):
                        kinds |= w.robot_next if agent is Agent.ROBOT else w.human_next
                    rows.append(tuple(sorted(kinds)))
                per_o.append(rows)
            out[agent].append(per_o)
    return out


def candidate_entries(space: Space) -> Rows:
    """``entries[agent][robot_at][o][status]``: candidate actions whose reach holds there."""
    world, d, table = space.world, space.domain, space.table
    n_spots = world.n_spots
    out: tuple[list[list[list[tuple[Entry, ...]]]], ...] = ([], [])
    for agent in Agent:
        for at in range(space.n_locs):
            per_o = []
            for o in range(world.n_objects):
                per_st = []
                for st in range(d.n_status):
                    entries: list[Entry] = []
                    for kind in space._next[agent][at][o][st]:
                        if kind is Kind.PLACE:
                            for spot in space.place_spots:
                                i = table.action_index(agent, kind, o, spot)
                                entries.append((kind, i, (kind, space.spot_class[spot]), spot))
                            continue
                        i = table.action_index(agent, kind, o)
                        if kind is Kind.PICK:
                            if st < n_spots and table.reach[agent][at][st]:
                                entries.append((kind, i, (kind, space.spot_class[st], space.object_class[o]), -1))
                        elif kind is Kind.THROW:
                            if table.throw_to[agent][at][o] >= 0:
                                entries.append((kind, i, None, -1))
                        elif kind is Kind.GIVE:
                            if table.give_ok[at]:
                                entries.append((kind, i, None, -1))
                        elif kind is Kind.TAKE:
                            entries.append((kind, i, None, -1))
                    per_st.append(tuple(entries))
                per_o.append(per_st)
            out[agent].append(per_o)
    return out


def split_entries(entries: Rows) -> tuple[Rows, Rows, Rows]:
    """``entries`` split into (picks, takes, held), each in its original order.

    Why: a hand holds one object. With it empty only picks and takes can pass; with an
    object in it only that object's place, throw and give (a pick or a take needs the
    hand empty, the others the object in it). The candidates then read the kinds that
    can pass and test no kind per entry.
    """

    def only(test: Callable[[Kind], bool]) -> Rows:
        return tuple(
            [[[tuple(e for e in per_st if test(e[0])) for per_st in per_o] for per_o in per_at] for per_at in rows]
            for rows in entries
        )

    return (
        only(lambda k: k is Kind.PICK),
        only(lambda k: k is Kind.TAKE),
        only(lambda k: k is not Kind.PICK and k is not Kind.TAKE),
    )
