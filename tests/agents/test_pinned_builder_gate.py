"""The model builder explores in batches that double from 64 states, pinned for the mutation gate.

Expected by hand: the budget is read before each batch with the states explored so far
and the states known; the i-th batch holds 64 * 2**i states (at most 32,768), or fewer when
fewer are known and not yet explored, so each reading is
``explored[i + 1] = min(explored[i] + 64 * 2**i, known[i])``. Every known state is expanded
once, so the progress bar's updates (those batch sizes) add up to the model's states.
"""

from __future__ import annotations

import itertools
from typing import Any, ClassVar

import pytest

from hg_marl.agents.models import AnswerTable, Budget, StatePacker, build_model, builder
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


class RecordingBar:
    """A stand-in for tqdm: records the options, each ``update`` and the last postfix."""

    made: ClassVar[list[RecordingBar]] = []

    def __init__(self, **options: Any) -> None:
        self.options = options
        self.updates: list[int] = []
        self.postfix: dict[str, Any] = {}
        self.closed = False
        RecordingBar.made.append(self)

    def update(self, n: int) -> None:
        self.updates.append(n)

    def set_postfix(self, refresh: bool = True, **values: Any) -> None:
        self.postfix = values

    def close(self) -> None:
        self.closed = True


@pytest.mark.parametrize("keep", [True, False])
def test_the_progress_bar_counts_each_state_explored_once(monkeypatch: pytest.MonkeyPatch, keep: bool) -> None:
    """Every known state is expanded exactly once, in batches of at most 64 * 2**i states: the bar's
    updates are those batch sizes and add up to the model's states (``keep=False`` included)."""
    RecordingBar.made.clear()
    monkeypatch.setattr(builder, "tqdm", RecordingBar)
    world = World("paper2015")
    table = AnswerTable(world, stationary_human("cooperative", world), StatePacker(world))
    model = build_model(world, [table], layout_distribution(world), progress=True, keep=keep)
    [bar] = RecordingBar.made
    assert bar.options["disable"] is False and bar.closed
    assert len(bar.updates) >= 4 and model.n > 64 * 2**3
    assert sum(bar.updates) == model.n
    assert all(0 < n <= min(64 * 2**i, 32_768) for i, n in enumerate(bar.updates)), bar.updates
    if keep:
        assert bar.postfix == {"known": model.n}
