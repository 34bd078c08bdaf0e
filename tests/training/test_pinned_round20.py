"""The values round 20's missed planted bugs changed, pinned after the round.

Round 20 planted 14 bugs in the same fourteen newest modules as round 19, after their
documented promises had been pinned (``tests/agents/test_pinned_promises_a.py``, ``_b.py``);
11 were caught. The three missed, each with its expected value stated independently:

- the belief robot's planner spell also ends when a task is solved (new evidence), not
  only when the partner acts;
- the headroom's state count is its model's states: with the cooperative partner alone,
  the oracle's count on the unreduced model of the same table and partner (1,418 pairs of
  a state and an action would be more);
- a disk cache entry of a compiled partner that lacks one of its arrays is rebuilt, as a
  corrupt one is (the module's rule), and written back whole.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hg_marl.agents.compiled import compile_human
from hg_marl.agents.headroom import headroom
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, World
from hg_marl.envs.batched import BatchState
from hg_marl.policy import Turn
from tests.population_files import train_members


def test_the_planner_spell_ends_when_a_task_is_solved(tmp_path: Path) -> None:
    world = World("paper2015")
    robot = BeliefRobot(population=train_members(tmp_path, coop="cooperative"), splits="train", unknown=0.0)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    waits = (world.n_actions(Agent.ROBOT) - 1, world.n_actions(Agent.HUMAN) - 1)
    for reward, driven in ((0.0, True), (1.0, False)):
        robot._planner_mode = True  # a spell begun at an earlier turn; both waited since
        robot.act(Turn(world, state, Agent.ROBOT, {}, reward=reward, last_actions=waits))
        assert robot.last_decision is not None
        assert str(robot.last_decision.reason).startswith("partner stalled, the planner drives") is driven


def test_the_headrooms_state_count_is_its_models_states() -> None:
    result = headroom("paper2015", [("c", "cooperative")])
    # one partner, the cooperative model: the joint model is the oracle's unreduced one
    assert result.n_states == oracle_rate("paper2015", "cooperative", symmetry=False, cache=False).n_states


def test_a_cached_table_missing_an_array_is_rebuilt_and_written_whole(tmp_path: Path) -> None:
    world = World("paper2015")
    first = compile_human(world, "lazy", cache=tmp_path)
    (entry,) = tmp_path.glob("*.npz")
    with np.load(entry, allow_pickle=False) as data:
        whole = {k: data[k] for k in data.files}
    np.savez(entry, **{k: v for k, v in whole.items() if k != "cum"})
    again = compile_human(world, "lazy", cache=tmp_path)
    states = BatchState.of([world.initial_state(np.random.default_rng(seed)) for seed in range(5)])
    seen = np.full(5, -1)
    for i in range(5):
        assert again.distribution(states, seen, i) == first.distribution(states, seen, i)
    with np.load(entry, allow_pickle=False) as data:
        assert sorted(data.files) == sorted(whole)
