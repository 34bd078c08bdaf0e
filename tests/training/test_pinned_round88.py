"""The values round 88's missed planted bug changed, pinned after the round.

Round 88 planted 16 bugs in sixteen gated modules, written blind; 15 were caught. The miss
was in the answer tables' shared batch (``KeyBatch.rows``): the rows of a batch that had
already been unpacked kept the robot action seen of *every* key, not of the rows taken.
The expected values below are stated apart from the code under test: the keys are packed
from states and robot actions seen chosen here, so each key's action seen is known by
construction, and the partner is a stub whose answer is a function of that action alone.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.models.answers import AnswerTable, KeyBatch
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchedRules, BatchState


class _SeenEcho:
    """A stationary partner that reads the robot's action: it answers ``(seen + 1) % n`` for sure.

    Not equivariant and without an array form, so an answer table asks it live, key by key.
    """

    uses_robot_action = True

    def __init__(self, n_actions: int) -> None:
        self.n_actions = n_actions

    def distribution(self, world: Any, state: State, seen: int) -> list[tuple[int, float]]:
        return [((seen + 1) % self.n_actions, 1.0)]

    def reset(self, *args: Any) -> None:
        pass


def _seen_keys(world: World, count: int = 30) -> tuple[StatePacker, np.ndarray, np.ndarray]:
    """Distinct sorted keys of ``count`` distinct tables, each packed with a robot action seen chosen
    here (-1, 0, 1, ... in turn), and that action per key (aligned with the sorted keys)."""
    packer = StatePacker(world)
    states = [s for s, _ in layout_distribution(world)][:count]
    assert len(states) == count  # paper2015 deals 36 tables
    seen = np.arange(count, dtype=np.int64) % (world.n_actions(Agent.ROBOT) + 1) - 1
    keys = packer.pack(BatchState.of(states), seen)
    order = np.argsort(keys, kind="stable")
    assert len(np.unique(keys)) == count  # distinct tables: distinct keys
    return packer, keys[order], seen[order]


def test_the_rows_of_an_unpacked_shared_batch_carry_their_own_robot_actions_seen() -> None:
    # Rule (KeyBatch.rows): the rows taken are "the keys at rows"; their unpacking is the
    # unpacking of those keys. The actions seen were chosen when the keys were packed.
    world = World("paper2015")
    packer, keys, seen = _seen_keys(world)
    shared = KeyBatch(packer, BatchedRules(world), keys)
    assert np.array_equal(shared.unpacked[1], seen)  # unpacked before the rows are taken
    rows = np.array([1, 4, 7, 20, 29])
    part = shared.rows(rows)
    assert np.array_equal(part.keys, keys[rows])
    assert part.unpacked[1].tolist() == seen[rows].tolist()
    assert len(part.unpacked[0]) == len(rows)


def test_a_table_lacking_part_of_a_shared_batch_answers_each_key_with_the_action_it_saw() -> None:
    # One table already knows every third key; another lacks them all and unpacks the shared
    # batch first. The first then asks its partner for the rest of the batch: by the stub's rule
    # each key's one answer is (seen + 1) % n with probability 1, seen as packed here.
    world = World("paper2015")
    n_human = world.n_actions(Agent.HUMAN)
    packer, keys, seen = _seen_keys(world)
    ahead = AnswerTable(world, _SeenEcho(n_human), packer)
    fresh = AnswerTable(world, _SeenEcho(n_human), packer)
    assert ahead.answers_live and ahead.canonical is None  # asked live, key by key
    ahead.ensure(keys[::3])
    shared = KeyBatch(packer, BatchedRules(world), keys)
    for table in (fresh, ahead):  # ``fresh`` lacks every key: it unpacks the whole batch
        table.ensure(keys, shared)
    expected = ((seen + 1) % n_human).tolist()
    for table in (ahead, fresh):
        start, size = table.lookup(keys)
        assert size.tolist() == [1] * len(keys)
        assert table.entries["actions"][start].tolist() == expected
        assert table.entries["probs"][start].tolist() == [1.0] * len(keys)
