"""Values that round 185's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.partner import PartnerMonitor
from hg_marl.core import Agent, World
from hg_marl.envs.batched import BatchedTable, BatchState
from tests.env.test_pinned_batched import HUMAN_WAIT, ROBOT_WAIT, Always


def test_the_monitor_refuses_a_stall_count_or_a_block_count_below_one() -> None:
    # "block_after: refusals ... that rule it out", "stall_after: consecutive unmet expectations":
    # both count events, so 0 (blocked or stalled before anything happened) is refused, 1 is the least.
    for block_after, stall_after in ((1, 0), (0, 1), (1, -1)):
        with pytest.raises(ValueError, match="must be positive"):
            PartnerMonitor(block_after=block_after, stall_after=stall_after)
    monitor = PartnerMonitor(block_after=1, stall_after=1)
    assert not monitor.stalled  # no miss yet: 0 >= 1 is False


def test_a_flat_sb3_policy_is_fed_the_facts_then_the_mask(tmp_path: Path) -> None:
    # The flat observation the policy was trained on (HumanView(observation="flat")) is the facts
    # followed by the action mask; the live human must build the same vector: entries 0..F-1 are the
    # facts, F..F+A-1 the mask (by hand, not through the code under test).
    pytest.importorskip("sb3_contrib")
    from tests.env.test_batched_learned import _policy

    world = World("paper2015")
    live = make_human(_policy("ppo-flat", tmp_path / "policy"))
    live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(3))
    facts = world.facts(state).astype(np.int8)
    mask = world.mask(state, Agent.HUMAN).astype(np.int8)
    obs, _ = live.sb3_inputs(facts, mask)
    n_f = world.n_facts
    assert len(obs) == n_f + world.n_actions(Agent.HUMAN)
    assert np.asarray(obs[:n_f]).tolist() == facts.tolist()
    assert np.asarray(obs[n_f:]).tolist() == mask.tolist()


def test_in_the_humans_seat_a_truncated_table_gets_no_robot_move() -> None:
    # max_cycles=2, both seats waiting. Cycle 1 (the human's first step) goes on, so the robot
    # partner moves again: robot_action 17 (its wait). Cycle 2 reaches max_cycles: the table is
    # truncated, the episode is over, and the robot does not move on it: robot_action -1 (no move).
    # The partner is called at reset (1), after cycle 1 (2) and not after cycle 2: 2 calls in all.
    world = World("paper2015")
    calls: list[int] = []

    class Counting(Always):
        def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
            calls.append(len(batch))
            return super().act(batch, seen, rng)

    env = BatchedTable(Counting(ROBOT_WAIT), 1, world, seat=Agent.HUMAN, max_cycles=2)  # type: ignore[arg-type]
    env.reset(seed=0)
    _, _, term, trunc, info = env.step(np.full(1, HUMAN_WAIT))
    assert (bool(term[0]), bool(trunc[0]), int(info["robot_action"][0])) == (False, False, ROBOT_WAIT)
    _, _, term, trunc, info = env.step(np.full(1, HUMAN_WAIT))
    assert (bool(term[0]), bool(trunc[0]), int(info["robot_action"][0])) == (False, True, -1)
    assert float(info["task_reward"][0]) == 0.0
    assert calls == [1, 1]
