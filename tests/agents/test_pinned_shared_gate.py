"""Pinned for the mutation gate: the promises of the shared-work change that no other test reached.

Each states its expected value apart from the code under test: progress bars shown only when
asked (the option's documented default), one search per set of equal table keys (what
``TableTransitions`` promises), and transitions read at each table's own positions (the kept
model's, built without the lazy reader).
"""

from __future__ import annotations

from typing import Any, ClassVar

import numpy as np

import hg_marl.agents.compiled_robot as compiled_robot
from hg_marl.agents.models import AnswerTable, StatePacker, build_model, builder
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.core import World
from hg_marl.envs.batched import BatchState
from tests.agents.test_models import mid_states


class Bar:
    """A stand-in for tqdm recording its options (a disabled bar draws nothing)."""

    made: ClassVar[list[Bar]] = []

    def __init__(self, iterable: Any = None, **options: Any) -> None:
        self.iterable, self.options = iterable, options
        Bar.made.append(self)

    def __iter__(self) -> Any:
        return iter(self.iterable)

    def update(self, n: int = 1) -> None:
        pass

    def set_postfix(self, refresh: bool = True, **values: Any) -> None:
        pass

    def close(self) -> None:
        pass


# --- agents/models/builder.py -------------------------------------------------------------


def test_the_builder_shows_no_progress_unless_asked(monkeypatch: Any) -> None:
    Bar.made.clear()
    monkeypatch.setattr(builder, "tqdm", Bar)
    world = World("paper2015")
    build_model(
        world, AnswerTable(world, stationary_human("random", world), StatePacker(world)), layout_distribution(world)
    )
    [bar] = Bar.made
    assert bar.options["disable"] is True


# --- agents/compiled_robot.py -------------------------------------------------------------


def test_the_compiled_robot_shows_no_planning_progress_unless_asked(monkeypatch: Any) -> None:
    Bar.made.clear()
    monkeypatch.setattr(compiled_robot, "tqdm", Bar)
    plans = compiled_robot.enumerate_plans(World("generated:objects=2,seed=4,human_only=0.8"))
    [bar] = Bar.made
    assert bar.options["disable"] is True and len(plans) > 0


# --- agents/models/lazy.py ----------------------------------------------------------------


def _models(world: World, specs: list[str], extra: np.ndarray | None) -> tuple[Any, Any]:
    models = []
    for keep in (True, False):
        packer = StatePacker(world)
        tables = [AnswerTable(world, stationary_human(h, world), packer) for h in specs]
        if extra is not None:
            tables[1].ensure(extra)
        models.append(build_model(world, tables, layout_distribution(world), keep=keep))
    return models[0], models[1]


def test_tables_holding_the_same_keys_are_searched_once() -> None:
    world = World("paper2015")
    kept, lazy = _models(world, ["random", "preference", "preference:handover=-1,shared=1"], None)
    for i in (0, 1, 2):
        for field in ("t_start", "t_next", "t_prob", "t_tau"):
            assert np.array_equal(getattr(kept.chain(i), field), getattr(lazy.chain(i), field)), (i, field)
    assert lazy.lazy is not None and len(lazy.lazy._searched) == 1  # three partners, one set of keys


def test_a_table_with_keys_among_the_others_is_searched_at_its_own_positions() -> None:
    """The second table answered plain keys the model never asks, sorted among those it does:
    the same pair keys sit at other positions in it."""
    world = World("paper2015")
    packer = StatePacker(world)
    asked = np.unique(packer.pack(BatchState.of(mid_states(world, 400))))
    unpacked, _ = packer.unpack(asked + 1)
    valid = np.flatnonzero(packer.pack(unpacked) == asked + 1)  # keys one above a state's that are states too
    extra = np.setdiff1d(asked[valid] + 1, asked)
    kept, lazy = _models(world, ["random", "preference"], extra)
    table_keys = lazy.lazy.tables[1].keys
    assert len(table_keys) > len(lazy.lazy.tables[0].keys) and table_keys[0] < extra.max() < table_keys[-1]
    for i in (0, 1, 0, 1):
        for field in ("t_start", "t_next", "t_prob", "t_tau"):
            assert np.array_equal(getattr(kept.chain(i), field), getattr(lazy.chain(i), field)), (i, field)
    assert len(lazy.lazy._searched) == 2
