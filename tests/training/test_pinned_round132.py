"""Values that round 132's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import ClassVar

import numpy as np
import pytest

from hg_marl.agents.meta.base import Criterion, Expert, HabitView, PlanProposal
from hg_marl.agents.meta.controller import MetaController
from hg_marl.agents.model_file import save_sb3, world_fields
from hg_marl.agents.robots.sb3 import SB3Robot
from hg_marl.core import Agent
from hg_marl.core.errors import ConfigError
from tests.agents.test_pinned_sb3_robot_gate import STATES, WORLD, _model, _turn
from tests.training.test_pinned_round28 import _view


class _Scored(Criterion):
    """Trusts the habit after 2 visits; each choice it makes is the planner's, its number 0.5."""

    name: ClassVar[str] = "scored"
    min_visits = 2

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        self.stats = {"score": 0.5}
        return Expert.PLANNER


def test_an_untrained_decision_keeps_the_criterions_numbers_and_adds_visits() -> None:
    # The criterion's stats are "the numbers behind the last choice": after a choice that set
    # score 0.5, an untrained state's decision (visits 0 < 2) adds its visits to them, so its
    # record holds both: score 0.5 and visits 0.0.
    mc = MetaController(_Scored())
    mc.reset(np.random.default_rng(0))
    plan = PlanProposal.make(1, 4, 0.01)
    first = mc.decide(_view(5), plan)
    assert first.reason == "criterion" and first.stats == {"score": 0.5}
    untrained = mc.decide(_view(0), plan)
    assert untrained.reason == "habit_untrained" and untrained.expert is Expert.PLANNER
    assert untrained.stats == {"score": 0.5, "visits": 0.0}
    assert untrained.record["score"] == 0.5 and untrained.record["visits"] == 0.0


def test_loading_a_maskable_ppo_file_as_the_recurrent_baseline_is_refused(tmp_path: Path) -> None:
    # load() rebuilds RecurrentPPO models only: any other algorithm's file (here MaskablePPO,
    # not only PPO) is refused with one line naming the algorithm it holds.
    from hg_marl.training.baselines.recurrent_ppo_sb3 import load

    path = save_sb3(_model("maskable"), tmp_path / "model.json", world_fields(WORLD, Agent.ROBOT), observation="facts")
    with pytest.raises(ConfigError, match=r"not a RecurrentPPO model \(algo 'MaskablePPO'\)"):
        load(path)


def test_the_sb3_robot_plays_a_model_on_the_dict_observation() -> None:
    # "dict" is one of the view's three observation modes: the robot accepts it and shows the
    # model {observation: facts, action_mask: mask}, so its greedy actions are SB3's own
    # predictions on that dict (the reference), state by state.
    model = _model("ppo", "dict")
    robot = SB3Robot(model=model, observation="dict")
    assert robot.observation == "dict"
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    for state in STATES:
        obs = {"observation": WORLD.facts(state), "action_mask": WORLD.mask(state, Agent.ROBOT)}
        want, _ = model.predict(obs, deterministic=True)
        assert robot.act(_turn(state)) == int(want)
