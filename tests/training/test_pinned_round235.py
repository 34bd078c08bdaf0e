"""Values that round 235's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from hg_marl.agents import compiled_robot
from hg_marl.agents.compiled_robot import enumerate_plans
from hg_marl.core import Agent, State, World
from hg_marl.training.baselines import ppo_recurrent
from tests.training.test_pinned_round37 import train_clocked


def test_a_budget_of_exactly_the_canonical_states_is_planned_not_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    # paper2015 has 1892 robot-turn states, 328 up to relabelling its interchangeable tapes
    # (tests/env/test_compiled_robot_canonical.py). The budget is "at most max_states" cold plans:
    # 328 is within a budget of 328, so every state gets an answer; a budget of 327 is refused.
    def wait(world: World, state: State) -> int:
        return world.n_actions(Agent.ROBOT) - 1  # any answer: only the budget's bound is pinned here

    monkeypatch.setattr(compiled_robot, "planner_action", wait)
    assert len(enumerate_plans(World("paper2015"), max_states=328)) == 1892
    with pytest.raises(compiled_robot.CompileError, match="over the 327 "):
        enumerate_plans(World("paper2015"), max_states=327)


def test_the_greedy_evaluation_plays_tables_seeded_ten_thousand_past_the_training_seed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The run trains on the tables reset with its seed (3) and reports the greedy rate on tables
    # reset with a held-out seed: 3 + 10,000 = 10,003, the draw every reported rate has used.
    seeds: list[int] = []
    greedy = ppo_recurrent.greedy_rate

    def spy(net: Any, env: Any, seconds: float, seed: int) -> float:
        seeds.append(seed)
        return greedy(net, env, seconds, seed)

    monkeypatch.setattr(ppo_recurrent, "greedy_rate", spy)
    train_clocked(tmp_path, seed=3)
    assert seeds == [10_003]
