"""Values that round 113's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

import hg_marl
from hg_marl.agents.partner import PartnerMonitor
from hg_marl.training.play.stats import PlayStats, resemblance
from hg_marl.wrappers import audit_v0
from tests.env.test_pinned_wrapper_audit_gate import ROBOT_WAIT


def test_the_monitor_counts_every_fallback_the_robot_took() -> None:
    # ``fallbacks`` counts the robot's fallbacks: three calls of fell_back() are 3, and each
    # re-arms the monitor at stall_after // 2 = 4 // 2 = 2 misses.
    monitor = PartnerMonitor(block_after=2, stall_after=4)
    for taken in (1, 2, 3):
        monitor.fell_back()
        assert monitor.fallbacks == taken
        assert monitor.misses == 2
    monitor.reset()
    assert monitor.fallbacks == 0


def test_resemblance_is_the_mean_distance_over_the_games_not_their_sum() -> None:
    # Profiles (pick, place, give, take, throw, wait shares, then acceptance or 0), by hand:
    # game 1: person waits only, no offer (0,0,0,0,0,1,0); scripted takes only, accepts (0,0,0,1,0,0,1):
    #   L1 = |0 - 1| take + |1 - 0| wait + |0 - 1| acceptance = 3.
    # game 2: both wait only; the person had no offer (0), the scripted human accepted all (1): L1 = 1.
    # The mean over the two games is (3 + 1) / 2 = 2 (their sum would be 4).
    person = [
        PlayStats("p", "planner", moves=2, tasks=1, handover_acceptance=None, shares={"wait": 1.0}),
        PlayStats("p", "planner", moves=3, tasks=1, handover_acceptance=None, shares={"wait": 1.0}),
    ]
    scripted = [
        PlayStats("s", "planner", moves=2, tasks=1, handover_acceptance=1.0, shares={"take": 1.0}),
        PlayStats("s", "planner", moves=3, tasks=1, handover_acceptance=1.0, shares={"wait": 1.0}),
    ]
    assert resemblance(person, {"s": scripted}) == {"s": 2.0}


def test_the_audit_counts_every_action_each_agent_sent() -> None:
    # Three whole cycles of waits (the robot's ``wait`` and the human's last feasible action):
    # each agent sent 3 actions, none of them ruled out by its real mask.
    env = audit_v0(hg_marl.env())
    env.reset(seed=0)
    for _ in range(3):
        env.step(ROBOT_WAIT)
        env.step(int(np.flatnonzero(env.observe("human")["action_mask"])[-1]))
    assert env.sent == {"robot": 3, "human": 3}
    assert env.infeasible == {"robot": 0, "human": 0}
