"""The habit's view of a state with interchangeable objects put in canonical order.

Why: a tabular habit learns per state, and two states that differ only by *which* of two
interchangeable tapes lies where are the same situation up to a relabelling (the
planner already answers for the canonical state; :class:`~hg_marl.agents.planner.space.Relabel`).
Learning on the canonical state shares every TD step among all its relabellings, so a
state is met (and trusted by the MetaController) up to ``k!`` times sooner for a class
of ``k`` interchangeable objects.

The habit then lives in the canonical labelling: it is asked at the canonical facts,
its Q-values (and sds) are mapped back to the original actions by the relabelling's
action permutation, and the executed action is mapped forward before its TD step. This
is exact for tabular Q-learning: the task is invariant under the relabelling, so
``Q*(s, a) = Q*(canon(s), perm(a))`` and the bootstrapped max is the same on both sides.
"""

from __future__ import annotations

import numpy as np

from hg_marl.core import Agent, State, World

_PERM_LIMIT = 4096
"""Permutations kept (one per distinct relabelling met; k! per class of k objects)."""


class CanonicalView:
    """Canonical facts and the action permutation for each state.

    Args:
        world: the task.
        agent: the seat whose actions are permuted.
    """

    def __init__(self, world: World, agent: Agent) -> None:
        from hg_marl.agents.planner.space import Relabel

        self.world, self.agent = world, agent
        self.relabel = Relabel(world)
        self._perms: dict[tuple[int, ...], tuple[np.ndarray, np.ndarray]] = {}

    def view(self, state: State, facts: np.ndarray) -> tuple[np.ndarray, np.ndarray | None, np.ndarray | None]:
        """``(facts, to_original, to_canonical)`` for ``state``; ``None`` maps when it is already canonical.

        ``to_original[i]`` is the original action that canonical action ``i`` stands for,
        ``to_canonical`` its inverse.
        """
        if not self.relabel.active:
            return facts, None, None
        canonical, orig = self.relabel.canonical(state)
        if orig == tuple(range(len(orig))):
            return facts, None, None
        maps = self._perms.get(orig)
        if maps is None:
            n = self.world.n_actions(self.agent)
            to_original = np.fromiter(
                (self.relabel.action_back(int(self.agent), i, orig) for i in range(n)), dtype=np.intp, count=n
            )
            to_canonical = np.empty(n, dtype=np.intp)
            to_canonical[to_original] = np.arange(n)
            if len(self._perms) >= _PERM_LIMIT:
                self._perms.clear()
            maps = self._perms[orig] = (to_original, to_canonical)
        return self.world.facts(canonical), maps[0], maps[1]
