"""Values that round 250's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.models import AnswerTable, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.builder import Dynamics, Model
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.solve import solve
from hg_marl.core import World
from hg_marl.core.errors import HumanError


def test_a_non_stationary_human_is_refused_saying_switching_and_replay_humans_are_not_stationary() -> None:
    # the refusal tells the user why: a switching human changes its rule mid-run, so it is not stationary
    with pytest.raises(HumanError, match="switching and replay humans are not stationary"):
        stationary_human("switching", World("paper2015"))


def test_a_reduced_model_gathers_no_transitions_for_no_pairs() -> None:
    # the transitions of no pairs are none: one segment start (0) and empty arrays, as the kept model's
    world = World("paper2015")
    packer = StatePacker(world)
    table = AnswerTable(world, stationary_human("random", world), packer)
    model = build_model(world, [table], layout_distribution(world), keep=False)
    starts, nxt, probs, taus = model.gather(0, np.zeros(0, dtype=np.int64))
    assert starts.tolist() == [0]
    assert len(nxt) == len(probs) == len(taus) == 0


def test_a_pair_that_may_fall_into_a_trap_costs_infinite_seconds_and_is_never_chosen() -> None:
    # Three states drawn by hand: state 0 has pair 0 (1 s, to state 1 or the trap state 2 at 1/2
    # each) and pair 1 (4 s, to state 1 for sure); state 1 has the completing wait (pair 2);
    # state 2 has only pair 3, which loops on it. Pair 0 may end in the trap: its expected
    # seconds are infinite, though 1 s + 0 (state 1) + 0 (the trap's value, read as 0) would
    # be finite and less than pair 1's 4 s. So q = [inf, 4, 0, inf] and state 0 takes pair 1;
    # the trap's pairs are all infinite and its first pair (3) is named. Re-draw to state 0
    # costs 2 s: 2 + 4 = 6 s per task.
    dynamics = Dynamics(
        t_start=np.array([0, 2, 3, 3, 4]),  # the completing wait (pair 2) has no transitions
        t_next=np.array([1, 2, 1, 2]),
        t_prob=np.array([0.5, 0.5, 1.0, 1.0]),
        t_tau=np.array([1.0, 1.0, 4.0, 1.0]),
        regen_next=np.array([0]),
        regen_prob=np.array([1.0]),
        regen_tau=np.array([2.0]),
    )
    model = Model(
        packer=None,
        keys=np.array([10, 11, 12]),
        pair_start=np.array([0, 2, 3, 4]),
        pair_action=np.arange(4) + 2,
        pair_terminal=np.array([False, False, True, False]),
        dynamics=[dynamics],
        n_layouts=1,
    )
    solution = solve(model)
    assert solution.q.tolist() == [np.inf, 4.0, 0.0, np.inf]
    assert solution.best_pair.tolist() == [1, 2, 3]
    assert solution.seconds_per_task == 6.0
