"""Values that round 222's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents.meta.base import Expert, PlanProposal
from hg_marl.agents.meta.controller import Decision


def test_a_decision_record_logs_the_executed_action_not_the_plans() -> None:
    # The planner proposed action 2 but the habit's action 5 was executed: the log's
    # "action" is the executed one (5), whoever's plan was consulted; with no plan it is 4.
    plan = PlanProposal.make(2, 6, cost=0.1)
    habit_acted = Decision(Expert.HABIT, 5, plan, "criterion", {"vpi": 0.25})
    assert habit_acted.record == {"expert": str(Expert.HABIT), "action": 5, "reason": "criterion", "vpi": 0.25}
    failed = Decision(Expert.HABIT, 4, PlanProposal.make(1, 6, cost=0.1, success=False), "planner_failed")
    assert failed.record["action"] == 4
    assert Decision(Expert.HABIT, 4, None, "habit_only").record["action"] == 4


def test_the_recurrent_sb3_model_trains_the_epochs_asked(tmp_path: Path) -> None:
    # n_epochs=2 and n_steps=16 differ, so the model's own n_epochs says which one it was given:
    # the config's n_epochs (2), passed to RecurrentPPO as asked.
    pytest.importorskip("sb3_contrib")
    from hg_marl.training.baselines.recurrent_ppo_sb3 import train
    from tests.training.test_recurrent_ppo_sb3 import _config

    result = train(_config(tmp_path, steps=128, n_epochs=2, n_steps=16, history=0))
    assert result.model.n_epochs == 2
    assert result.model.n_steps == 16
