"""The compiled robot's table lookup and its corrupt cache entry, pinned for the mutation gate.

Expected values by hand: a state whose key is beyond every stored key is not in the table
(it is planned live, as the module says of any missing state); an entry that is not a
readable archive is rebuilt, not an error.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hg_marl.agents.compiled import Packer
from hg_marl.agents.compiled_robot import CompiledRobot, compile_robot, planner_action, robot_cache_key
from hg_marl.core import World
from hg_marl.core.batch import BatchState
from tests.agents.test_oracle import TINY


def test_a_state_beyond_every_stored_key_is_not_found() -> None:
    world = World(TINY)
    packer = Packer(world)
    states = [world.initial_state(np.random.default_rng(seed)) for seed in range(20)]
    by_key = sorted({packer.pack_one(s, -1): s for s in states}.items())
    assert len(by_key) >= 2
    (low_key, _), (_, high) = by_key[0], by_key[-1]
    wait = world.n_actions(0) - 1
    table = {"keys": np.array([low_key], dtype=np.int64), "actions": np.array([wait], dtype=np.int64)}
    robot = CompiledRobot(world, table, "planner")
    out, found = robot.plan(BatchState.of([high]))
    assert found.tolist() == [False]
    assert out.tolist() == [planner_action(world, high)]
    assert robot.fallbacks == 1


def test_a_corrupt_entry_is_rebuilt(tmp_path: Path) -> None:
    world = World(TINY)
    fresh = compile_robot(world, cache=None)
    key = robot_cache_key(world, "planner", fresh.guard.after)
    path = tmp_path / f"{world.scenario.name}-robot-{key[:24]}.npz"
    path.write_bytes(b"not an archive")
    rebuilt = compile_robot(world, cache=tmp_path)
    assert rebuilt.keys.tolist() == fresh.keys.tolist()
    assert rebuilt.actions.tolist() == fresh.actions.tolist()
    with np.load(path, allow_pickle=False) as data:  # the entry was written again, readable
        assert str(data["key"]) == key
