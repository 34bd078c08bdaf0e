"""The compiled robot's table lookup and its corrupt cache entry, pinned for the mutation gate.

Expected values by hand: a state whose key is beyond every stored key is not in the table
(it is planned live, as the module says of any missing state); an entry that is not a
readable archive is rebuilt, not an error; the human's answers the states are explored
with are a distribution (uniform over the feasible actions and one failing one, read from
the scalar rules' mask); the code a robot table is keyed by is the planner robot's.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents import content
from hg_marl.agents.compiled import Packer
from hg_marl.agents.compiled_robot import CompiledRobot, any_answer, compile_robot, planner_action, robot_cache_key
from hg_marl.core import Agent, World
from hg_marl.core.batch import BatchState
from tests.agents.test_oracle import TINY
from tests.content_keys import record_content_keys


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


def test_any_answer_is_each_feasible_human_action_and_one_failing_one_uniformly() -> None:
    """Per state, by the scalar rules' mask: the feasible actions in index order, then the first
    infeasible one (standing for them all), each with probability 1 / (their count)."""
    world = World("paper2015")
    rng = np.random.default_rng(3)
    states = [world.initial_state(rng) for _ in range(8)]
    sizes, actions, probs = any_answer(world)(BatchState.of(states))
    at = 0
    for i, state in enumerate(states):
        mask = world.mask(state, Agent.HUMAN)
        expected = [a for a in range(len(mask)) if mask[a]]
        if len(expected) < len(mask):
            expected.append(next(a for a in range(len(mask)) if not mask[a]))
        n = len(expected)
        assert int(sizes[i]) == n, i
        assert actions[at : at + n].tolist() == expected, i
        assert probs[at : at + n].tolist() == pytest.approx([1.0 / n] * n), i
        assert float(probs[at : at + n].sum()) == pytest.approx(1.0)
        at += n
    assert at == len(actions) == len(probs)


def test_a_robot_tables_key_covers_the_planners_code_and_no_humans(monkeypatch: pytest.MonkeyPatch) -> None:
    """The cheap counterpart of ``test_pinned_compiled.py``'s edits of a copy of the sources: the
    modules the key's import walk reaches (the planner robot's own, not a human's), without copying."""
    world = World("paper2015")
    asked = record_content_keys(monkeypatch)
    robot_cache_key(world, "planner", 5, 1000)
    [(kind, fields, roots)] = asked
    assert kind == "compiled robot"
    expected = {"scenario": repr(world.scenario), "durations": repr(world.durations), "spec": "planner", "K": 5}
    assert fields == {**expected, "max_states": 1000}
    keyed, _ = content.code_modules(roots)
    shared = ["hg_marl.core.world", "hg_marl.agents.planner.costs", "hg_marl.agents.compiled"]
    shared += ["hg_marl.agents.models.builder", "hg_marl.agents.content"]
    own = ["hg_marl.agents.compiled_robot", "hg_marl.agents.robots.planner", "hg_marl.agents.robots.base"]
    own += ["hg_marl.agents.partner"]
    assert set(shared + own) <= set(keyed)
    assert not {"hg_marl.agents.humans.lazy", "hg_marl.agents.humans.cooperative"} & set(keyed)


def test_a_frozen_tables_counters_read_k_planned_turns_then_one_stall_move_per_turn() -> None:
    """One table whose state never changes, ``K`` = 3: turns 1-3 are the planner's (no stall
    move), turns 4-6 are stall moves, so after six turns the table has taken 3 stall moves
    (``stall_count``), its last move was one (``stalled``), 3 in all (``stall_moves_taken``);
    a reset zeroes the table's count."""
    world = World(TINY)
    robot = compile_robot(world, cache=None, stall_after=3)
    state = world.initial_state(np.random.default_rng(11))
    robot.reset_rows(np.array([0]), np.random.default_rng(0))
    for turn in range(1, 7):
        robot.act(BatchState.of([state]), np.array([-1]), np.random.default_rng(0))
        assert robot.stall_count.tolist() == [max(0, turn - 3)]
        assert robot.stalled.tolist() == [turn > 3]
    assert robot.stall_moves_taken == 3
    robot.reset_rows(np.array([0]), np.random.default_rng(0))
    assert robot.stall_count.tolist() == [0]
