"""Values that round 240's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import ClassVar

import numpy as np
import pytest
from gymnasium.vector import AutoresetMode

from hg_marl.agents.meta.base import Criterion, Expert, HabitView, PlanProposal
from hg_marl.agents.meta.controller import MetaController
from hg_marl.core.errors import ConfigError
from hg_marl.wrappers.sb3 import BatchedVecEnv
from tests.env.test_pinned_sb3_wrapper_gate import ScriptedBatch


class _NeverPlans(Criterion):
    """A trained habit's criterion that never asks the planner."""

    name: ClassVar[str] = "never_plans"

    def wants_plan(self, habit: HabitView) -> bool:
        return False

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        return Expert.PLANNER


def test_a_habit_only_decision_reports_no_plan_though_one_was_ready() -> None:
    # Decision.plan's docstring: "the planner's proposal if it was consulted, else None". A
    # criterion that does not want a plan never consults it, whether the proposal came ready
    # or as a thunk: the habit's action 2 is executed and no plan is reported.
    n = 5
    habit = HabitView(b"s", np.full(n, 1 / n), 2, np.zeros(n), np.ones(n), 0.0, 0.0, visits=10)
    controller = MetaController(_NeverPlans())
    controller.reset(np.random.default_rng(0))
    ready = PlanProposal.make(4, n, 0.1)
    for plan in (ready, lambda: ready):
        d = controller.decide(habit, plan)
        assert (d.expert, d.action, d.plan, d.reason) == (Expert.HABIT, 2, None, "habit_only")


def test_the_recurrent_sb3_models_header_names_the_facts_observation(tmp_path: Path) -> None:
    pytest.importorskip("sb3_contrib")
    from hg_marl.agents.model_file import load_model_file
    from hg_marl.training.baselines.recurrent_ppo_sb3 import train
    from tests.training.test_recurrent_ppo_sb3 import _config

    # the network reads the facts (plus the history) only, never the mask: the header must say
    # "facts", or a player would build the flat observation (facts + mask) for it
    result = train(_config(tmp_path, steps=64, num_envs=4, history=0))
    assert load_model_file(result.path, seat="robot").header["observation"] == "facts"


def test_the_sb3_adapter_refuses_a_batch_without_autoreset() -> None:
    # SB3's VecEnv resets finished sub-envs itself on the same step: only same_step is accepted,
    # so a batch built with autoreset disabled is refused as well as a next_step one
    with pytest.raises(ConfigError, match=r"^autoreset_mode: "):
        BatchedVecEnv(ScriptedBatch(autoreset_mode=AutoresetMode.DISABLED))


def test_a_checkpoint_every_single_step_is_one_checkpoint_per_rollout() -> None:
    pytest.importorskip("sb3_contrib")
    from hg_marl.training.baselines.hyperparams import Hyperparams
    from hg_marl.training.baselines.train import TrainConfig, checkpoint_every

    # --checkpoint-freq 1 asks for a checkpoint every step; rounded up to whole rollouts of
    # n_steps 256 x 4 envs = 1024 steps, it is 1024, not 0 (0 alone turns checkpoints off)
    hp = Hyperparams("ppo", n_envs=4, kwargs={"n_steps": 256})
    assert checkpoint_every(TrainConfig(algo="ppo", checkpoint_freq=1), hp, 100_000) == 1024
