"""The model builder explores in batches that double from 64 states, pinned for the mutation gate.

Expected by hand: the budget is read before each batch with the states explored so far
and the states known; the i-th batch holds 64 * 2**i states (at most 32,768), or fewer when
fewer are known and not yet explored, so each reading is
``explored[i + 1] = min(explored[i] + 64 * 2**i, known[i])``.
"""

from __future__ import annotations

import itertools
from typing import Any

from hg_marl.agents.models import AnswerTable, Budget, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.core import World


class SpyBudget(Budget):
    """No limits; records the explored count at each exploration check."""

    def __init__(self) -> None:
        super().__init__(None, None, None)
        self.explored: list[tuple[int, int]] = []

    def check(self, phase: str, done: int, total: int | None = None, unit: str = "states", **kw: Any) -> None:
        if phase == "explore" and unit.endswith("known)"):
            known = int(kw["states"])
            self.explored.append((done, known))
        super().check(phase, done, total, unit, **kw)


def test_exploration_batches_double_from_64_states() -> None:
    world = World("paper2015")
    budget = SpyBudget()
    table = AnswerTable(world, stationary_human("cooperative", world), StatePacker(world), budget)
    build_model(world, [table], layout_distribution(world), budget=budget)
    readings = budget.explored[1:]  # the first one comes before the loop
    assert readings[0][0] == 0 and len(readings) >= 4
    for i, ((lo, known), (nxt, _)) in enumerate(itertools.pairwise(readings)):
        assert nxt == min(lo + min(64 * 2**i, 32_768), known), i
    assert any(nxt - lo > 128 for (lo, _), (nxt, _) in itertools.pairwise(readings))
