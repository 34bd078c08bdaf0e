"""Interchangeable objects put in a canonical order: the task's one symmetry.

Objects accepted by the same bins are interchangeable: swapping them maps a state, its
plans and its values onto another's. The planner, the oracle and the belief robot answer
for the canonical state and map actions back through :class:`Relabel`; it depends only on
the world, so it lives in the core (``hg_marl.agents.planner.space`` re-exports it).
"""

from __future__ import annotations

from hg_marl.core.types import Kind, State
from hg_marl.core.world import World


class Relabel:
    """Interchangeable objects (accepted by the same bins) put in a canonical order.

    Two states that differ only by which of two interchangeable objects is where have
    the same optimal plans up to that relabelling, so a planner may answer for the
    canonical state and map the actions back: on ``roboergosum`` the 5,040 layouts are
    140 canonical ones. The canonical state sorts each class's objects by place code.
    """

    def __init__(self, world: World) -> None:
        self.table = world.table
        groups: dict[tuple[int, ...], list[int]] = {}
        for o, bins in enumerate(world.bins_of):
            groups.setdefault(bins, []).append(o)
        self.classes = tuple(tuple(g) for g in groups.values() if len(g) > 1)
        self.active = bool(self.classes)
        """False when no two objects are interchangeable (states are already canonical)."""

    def canonical(self, state: State) -> tuple[State, tuple[int, ...]]:
        """The canonical state and, per object of it, the object of ``state`` it stands for."""
        where = state.where
        orig = list(range(len(where)))
        for members in self.classes:
            for slot, o in zip(members, sorted(members, key=where.__getitem__), strict=True):
                orig[slot] = o
        new_where = tuple(where[o] for o in orig)
        offer_obj = orig.index(state.offer_obj) if state.offer_obj >= 0 else -1
        return State(new_where, state.robot_at, state.offer_by, offer_obj), tuple(orig)

    def action_back(self, agent: int, index: int, orig: tuple[int, ...]) -> int:
        """The action of the original labelling that ``index`` (canonical labelling) stands for."""
        if index < 0:
            return index
        kind, obj, target, _ = self.table.specs[agent][index]
        if obj >= 0:
            obj = orig[obj]
        elif kind is Kind.GOTO and target < len(orig):
            target = orig[target]
        return self.table.action_index(agent, kind, obj, target)
