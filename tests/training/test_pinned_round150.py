"""Values that round 150's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from hg_marl.agents.habit import QLearner, QLearnerConfig
from hg_marl.agents.meta.base import PlanProposal
from hg_marl.agents.meta.controller import MetaController
from hg_marl.training.baselines.recurrent_ppo_sb3 import Sb3RecurrentResult
from hg_marl.training.play.session import PlaySession
from tests.play.reference import person_choice
from tests.play.test_pinned_play_session_gate import ticking
from tests.training.test_pinned_round28 import _view


def test_every_never_updated_state_has_the_prior_sd_past_the_first_table_size() -> None:
    # The tables start with room for 16 states and grow by doubling; a never-updated state "has
    # the prior" whichever it is: with v0 = 4 every action's sd is sqrt(4) = 2, for the 1st state
    # seen as for the 17th (first growth) and the 40th (second growth).
    habit = QLearner(8, 3, QLearnerConfig(uncertainty_prior=4.0))
    states = [np.array([(k >> bit) & 1 for bit in range(8)], dtype=np.int8) for k in range(40)]
    for facts in states:
        habit.state_code(facts)
    assert habit.n_states == 40
    for k in (0, 15, 16, 17, 39):
        assert habit.uncertainty(states[k]).tolist() == [2.0, 2.0, 2.0]


def test_each_untrained_decision_records_its_own_states_visits() -> None:
    # min_visits 3: a habit seen 0 times, then one seen 2 times, are both untrained; each
    # decision's record holds the visits of the state it was made in (0.0, then 2.0), not those
    # of the untrained decision before it.
    mc = MetaController("entropy", min_visits=3)
    mc.reset(np.random.default_rng(0))
    plan = PlanProposal.make(1, 4, 0.01)
    first = mc.decide(_view(0), plan)
    second = mc.decide(_view(2), plan)
    assert first.reason == second.reason == "habit_untrained"
    assert first.record["visits"] == 0.0
    assert second.record["visits"] == 2.0 and second.stats["visits"] == 2.0


def test_a_solved_task_is_stamped_with_the_simulated_clock_when_it_was_solved() -> None:
    # paper2015's task completes on the robot's wait on a clean table: the robot's answer ends the
    # person's move that solves it, so the stamp is the session's clock after that move (simulated
    # seconds, past the clock before it), not a count of cycles.
    session = PlaySession(player="p", seed=0, timer=ticking())
    before = session.clock
    while session.tasks_solved < 1:
        before = session.clock
        session.play(person_choice([c.name for c in session.choices()]))
    assert len(session.solved_at) == 1
    assert before < session.solved_at[0] == session.clock
    assert session.solved_at[0] != float(session.cycle)


def test_a_recurrent_sb3_runs_speed_is_steps_per_second() -> None:
    # 600 steps in 2 s: 300 steps a second; no time measured: NaN, not a division by zero.
    assert Sb3RecurrentResult(None, Path("model.json"), 600, 2.0).steps_per_second == 300.0
    assert math.isnan(Sb3RecurrentResult(None, Path("model.json"), 600, 0.0).steps_per_second)
