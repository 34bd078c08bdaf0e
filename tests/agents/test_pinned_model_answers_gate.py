"""The answer table asks the live human once per key (work counted, not timed), and the
canonical layouts are the full deal summed over interchangeable objects.

The first reference is a count: ``live_calls`` after asking for keys already answered
does not grow, and a mix of known and new keys asks only the new ones. The second is a
plain enumeration: every deal ``World.initial_state`` can make (``layout_distribution``)
mapped through ``Relabel.canonical`` and summed, on scenarios whose layout groups draw
fewer objects than they have spots (where ``(m - c)!`` is not 1).
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.models.answers import AnswerTable
from hg_marl.agents.models.layouts import canonical_layouts, layout_distribution
from hg_marl.agents.models.packing import StatePacker
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, World
from hg_marl.envs.batched import BatchState


def test_known_keys_are_not_asked_again() -> None:
    world = World("paper2015")
    human = make_human("cooperative")
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    packer = StatePacker(world)
    table = AnswerTable(world, human, packer, arrays=False)
    states = [s for s, _ in layout_distribution(world)][:12]
    keys = np.unique(packer.pack(BatchState.of(states), np.full(len(states), -1)))
    table.ensure(keys[:8])
    assert table.live_calls == 8 and len(table.keys) == 8
    table.ensure(keys[:8])
    assert table.live_calls == 8 and len(table.keys) == 8
    table.ensure(keys)  # 8 known, 4 new
    assert table.live_calls == 12 and table.keys.tolist() == keys.tolist()


@pytest.mark.parametrize(
    "scenario", ["generated:objects=3,spots=5,bins=1,seed=2", "generated:objects=4,spots=6,bins=2,seed=1"]
)
def test_canonical_layouts_are_the_full_deal_summed_by_symmetry(scenario: str) -> None:
    world = World(scenario)
    relabel = Relabel(world)
    assert relabel.active
    expected: dict[object, float] = {}
    for state, p in layout_distribution(world):
        key = relabel.canonical(state)[0]
        expected[key] = expected.get(key, 0.0) + p
    got = dict(canonical_layouts(world))
    assert got.keys() == expected.keys()
    for state, p in expected.items():
        assert got[state] == pytest.approx(p, rel=1e-12)
    assert sum(got.values()) == pytest.approx(1.0, rel=1e-12)
