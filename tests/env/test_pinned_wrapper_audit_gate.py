"""The mask audit's counts at the edges of the action range and over several audits, pinned for the mutation gate.

Expected values from the spec sheet of ``hg_marl/wrappers/audit.py``: every action a live
agent sends is counted in ``sent``, and in ``infeasible`` unless it is an index of the
agent's real mask that the mask allows; an index outside ``0..A-1`` (negative, or ``A``
and above) is infeasible whatever the mask says, and the env still refuses it with its
own ``InvalidActionError``; a finished agent's steps are not counted; ``audit_totals``
adds the counts of every live audit. paper2015: the robot's last action (17) is ``wait``;
with seed 3, after the robot waits, the human's action 0 (``pick(tape1)``) is feasible
(the raw env's own mask is asserted, not the audit's).
"""

from __future__ import annotations

import numpy as np
import pytest

import hg_marl
from hg_marl.envs import InvalidActionError
from hg_marl.wrappers import AUDITS, audit_totals, audit_v0

ROBOT_WAIT = 17  # paper2015: the robot's last action
N_ROBOT = 18


@pytest.mark.parametrize("index", [-1, N_ROBOT, N_ROBOT + 1, 100])
def test_an_index_outside_the_actions_is_counted_infeasible_and_the_env_refuses_it(index: int) -> None:
    env = audit_v0(hg_marl.env())
    env.reset(seed=0)
    with pytest.raises(InvalidActionError, match="out of range"):
        env.step(index)
    assert env.sent["robot"] == 1 and env.infeasible["robot"] == 1


def test_action_zero_feasible_in_the_real_mask_is_not_counted_infeasible() -> None:
    env = audit_v0(hg_marl.env())
    env.reset(seed=3)
    env.step(ROBOT_WAIT)
    assert env.unwrapped.observe("human")["action_mask"][0] == 1  # the raw env: pick(tape1) is feasible
    env.step(0)
    assert env.sent == {"robot": 1, "human": 1} and env.infeasible == {"robot": 0, "human": 0}


def test_a_truncated_agents_refused_step_is_not_counted() -> None:
    """After one cycle of ``max_cycles=1`` both agents are truncated (not terminated); a non-None step is refused."""
    env = audit_v0(hg_marl.env(max_cycles=1))
    env.reset(seed=0)
    env.step(ROBOT_WAIT)
    env.step(int(np.flatnonzero(env.observe("human")["action_mask"])[-1]))
    assert env.truncations["robot"] and not env.terminations["robot"]
    with pytest.raises(ValueError, match="only valid action is None"):
        env.step(0)
    assert env.sent == {"robot": 1, "human": 1} and env.infeasible == {"robot": 0, "human": 0}


def test_totals_add_the_counts_of_every_live_audit() -> None:
    """Three audits: robot sends 3, 1 and 2 (infeasible 1, 1, 2 of them): totals 6 sent, 4 infeasible."""
    AUDITS.clear()
    audits = [audit_v0(hg_marl.env()) for _ in range(3)]
    for audit, (sent, infeasible) in zip(audits, [(3, 1), (1, 1), (2, 2)], strict=True):
        audit.sent["robot"], audit.infeasible["robot"] = sent, infeasible
    assert audit_totals() == ({"robot": 6, "human": 0}, {"robot": 4, "human": 0})
