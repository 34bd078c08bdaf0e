"""Survivors of the second mutation sample (seed 2041, 16 mutants per module), pinned.

Each test names the survivor it kills (file:line) and states its expected value worked by
hand from the module's documentation or rules, not read back from the code under test.
"""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

import hg_marl.training.evaluate as ev
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.training.study import Actor, Study


def _run_time(text: str) -> str:
    """``text`` built at run time (as a parser builds it): equal to the literal, not the same object."""
    out = "".join(list(text))
    assert out == text and out is not text
    return out


# -- agents/meta/cost.py ------------------------------------------------------------------


def test_a_wall_habit_decision_with_no_measured_time_costs_nothing() -> None:
    """cost.py:49: in ``"wall"`` mode the habit is charged the measured time, and the
    measured time defaults to none (0 s): a negative charge would run the clock back."""
    from hg_marl.agents.meta.cost import CostModel

    assert CostModel(mode="wall").habit_cost() == 0.0


def test_a_wall_mode_read_at_run_time_charges_the_habit_its_wall_time() -> None:
    """cost.py:51: a mode parsed from text (a config, a command line) is ``"wall"`` by value:
    the habit is charged the measured 0.25 s, not the model's constant 1 ms."""
    from hg_marl.agents.meta.cost import CostModel

    assert CostModel(mode=_run_time("wall")).habit_cost(0.25) == 0.25


def test_a_wall_mode_read_at_run_time_charges_the_planner_its_wall_time() -> None:
    """cost.py:55: as above for the planner: 0.5 s measured, not 0.05 + 10 * 5e-4 s."""
    from hg_marl.agents.meta.cost import CostModel

    assert CostModel(mode=_run_time("wall")).planner_cost(10, 0.5) == 0.5


# -- agents/model_sb3.py ------------------------------------------------------------------


def _dqn_file(tmp_path: Path, lr: float | None = None) -> tuple[Any, Path]:
    pytest.importorskip("stable_baselines3")
    from stable_baselines3 import DQN

    from hg_marl.agents.model_file import save_sb3, world_fields
    from hg_marl.agents.views import RobotView
    from hg_marl.core import Agent, World

    model = DQN("MlpPolicy", RobotView("paper2015"), buffer_size=16, learning_starts=0, seed=0, device="cpu")
    if lr is not None:
        model.policy.optimizer.param_groups[0]["lr"] = lr
    path = save_sb3(model, tmp_path / "model.json", world_fields(World("paper2015"), Agent.ROBOT), observation="facts")
    return model, path


def test_restoring_a_model_file_restores_its_optimizer_by_default(tmp_path: Path) -> None:
    """model_sb3.py:328: ``restore_sb3`` loads "a model file's state dicts" (the optimizer's
    too, which ``save_sb3`` writes): a saved optimizer learning rate of 0.123 comes back
    into a fresh model that names no ``optimizer`` argument."""
    from stable_baselines3 import DQN

    from hg_marl.agents.model_format import load_model_file
    from hg_marl.agents.model_sb3 import restore_sb3
    from hg_marl.agents.views import RobotView

    _, path = _dqn_file(tmp_path, lr=0.123)
    fresh = DQN("MlpPolicy", RobotView("paper2015"), buffer_size=16, learning_starts=0, seed=1, device="cpu")
    assert fresh.policy.optimizer.param_groups[0]["lr"] != 0.123
    restore_sb3(fresh, load_model_file(path))
    assert fresh.policy.optimizer.param_groups[0]["lr"] == 0.123


def test_a_state_without_the_policy_is_refused_even_when_the_optimizer_is_not_restored(tmp_path: Path) -> None:
    """model_sb3.py:332: a header whose saved state keeps the optimizer but drops the policy
    has no weights to load; with ``optimizer=False`` (policy only) it must still be refused
    by name, not load nothing and leave the fresh model's random weights in place."""
    from hg_marl.agents.model_format import load_model_file
    from hg_marl.agents.model_sb3 import build_sb3

    _, path = _dqn_file(tmp_path)
    header = json.loads(path.read_text())
    pairs = header["state"]["$dict"]
    assert [p[0] for p in pairs].count("policy") == 1
    header["state"]["$dict"] = [p for p in pairs if p[0] != "policy"]
    path.write_text(json.dumps(header))
    with pytest.raises(ModelFileError, match=r"model\.json: field 'state' has no policy$"):
        build_sb3(load_model_file(path), optimizer=False)


# -- agents/oracle.py ---------------------------------------------------------------------


def test_a_result_cached_with_the_members_options_answers_a_default_solve(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """oracle.py:157: ``ORACLE_OPTIONS`` (member_models.py) are documented as "the options
    oracle_rate solves members with (its defaults), part of the key": 200,000 sweeps at
    most. A result cached under them (given explicitly here) answers a call with the
    defaults from the cache, with no model built again."""
    import hg_marl.agents.oracle as oracle_module
    from hg_marl.core import World
    from tests.agents.test_oracle import TINY

    world = World(TINY)
    first = oracle_module.oracle_rate(world, "cooperative", max_iterations=200_000, cache=tmp_path)

    def no_build(*args: Any, **kwargs: Any) -> Any:
        raise AssertionError("the default solve built a model instead of reading the cache")

    monkeypatch.setattr(oracle_module, "build_model", no_build)
    again = oracle_module.oracle_rate(world, "cooperative", cache=tmp_path)
    assert again.rate_per_hour == first.rate_per_hour


def test_a_new_oracle_robot_has_taken_no_off_model_decision() -> None:
    """oracle.py:319: ``off_model`` "counts the off-model decisions in the current run":
    a robot that has not played yet has taken none."""
    from hg_marl.agents.oracle import OracleRobot

    assert OracleRobot().off_model == 0


# -- training/baselines/ppo_recurrent.py --------------------------------------------------


def test_a_gae_lambda_over_one_is_refused() -> None:
    """ppo_recurrent.py:103: ``--gae-lambda`` "must lie in [0, 1]": 1.5 is refused."""
    from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig

    with pytest.raises(ConfigError, match="--gae-lambda"):
        RecurrentConfig(gae_lambda=1.5).check()


def _three_steps() -> SimpleNamespace:
    import torch

    col = lambda *v: torch.tensor([[x] for x in v])  # noqa: E731 - one table, three steps
    return SimpleNamespace(rew=col(1.0, 2.0, 3.0), disc=col(0.5, 0.5, 0.5), val=col(10.0, 20.0, 40.0))


# GAE by hand, lambda 0.5, the value after the rollout 80:
#   t=2: delta = 3 + 0.5*80 - 40 = 3;                    A2 = 3
#   t=1: delta = 2 + 0.5*40 - 20 = 2;  A1 = 2 + 0.5*0.5*3 = 2.75
#   t=0: delta = 1 + 0.5*20 - 10 = 1;  A0 = 1 + 0.25*2.75 = 1.6875
# returns = A + V = 11.6875, 22.75, 43


def test_gae_bootstraps_each_step_from_the_next_steps_value() -> None:
    """ppo_recurrent.py:270: the advantages of a three-step buffer, worked by hand above."""
    import torch

    from hg_marl.training.baselines.ppo_recurrent import advantages

    adv, _ = advantages(_three_steps(), torch.tensor([80.0]), 0.5)
    assert adv[:, 0].tolist() == [1.6875, 2.75, 3.0]


def test_gae_returns_are_the_advantages_plus_the_values() -> None:
    """ppo_recurrent.py:273: the returns of the same buffer, worked by hand above."""
    import torch

    from hg_marl.training.baselines.ppo_recurrent import advantages

    _, ret = advantages(_three_steps(), torch.tensor([80.0]), 0.5)
    assert ret[:, 0].tolist() == [11.6875, 22.75, 43.0]


# -- agents/array_partners.py -------------------------------------------------------------


def test_a_schedule_by_time_read_at_run_time_follows_the_clock() -> None:
    """array_partners.py:152: ``by`` parsed from a spec is ``"time"`` by value: phases at
    600 s, a table at 700 s with 0 tasks solved is in phase 1 (``bisect_right``), not 0."""
    from hg_marl.agents.array_partners import CompiledSchedule

    members = [SimpleNamespace(name="cooperative"), SimpleNamespace(name="lazy")]
    schedule = CompiledSchedule(members, [0, 1], [600.0], _run_time("time"))
    schedule.follow(np.array([700.0, 100.0]), np.array([0, 0]))
    assert schedule.member.tolist() == [1, 0]


# -- agents/memory_numpy.py ---------------------------------------------------------------


def test_a_feed_forward_memory_policy_starts_with_a_hidden_state_of_width_zero(tmp_path: Path) -> None:
    """memory_numpy.py:99: "width 0 without a GRU": a feed-forward (mlp) policy has no state."""
    from hg_marl.agents.memory_numpy import NumpyMemoryPolicy
    from hg_marl.agents.memory_policy import MemoryNet, save_memory
    from hg_marl.agents.model_file import world_fields
    from hg_marl.agents.model_format import load_model_file
    from hg_marl.core import Agent, World
    from hg_marl.envs.history import history_size

    world = World("paper2015")
    obs_size = world.n_facts + history_size(2, 5)
    net = MemoryNet(obs_size, world.n_actions(Agent.ROBOT), 12, False)
    path = save_memory(net, tmp_path / "model.json", world_fields(world, Agent.ROBOT), history=2, cap=5)
    assert NumpyMemoryPolicy(load_model_file(path)).initial(3).shape == (3, 0)


# -- training/evaluate.py -----------------------------------------------------------------


def _study(robots: list[Actor], humans: list[Actor]) -> Study:
    return Study(
        "s", Path("s.toml"), tuple(robots), tuple(humans), scenarios=("paper2015",), seeds=(0,), duration=360.0
    )


def test_the_oracle_robot_skips_only_the_humans_it_cannot_model() -> None:
    """evaluate.py:84: the oracle robot meets only stationary humans: with switching (not
    stationary) listed before cooperative, it still meets cooperative."""
    study = _study([Actor("oracle", {}, "oracle")], [Actor("switching", {}, "sw"), Actor("cooperative", {}, "co")])
    assert [(c.robot.label, c.human.label) for c in ev.cells(study)] == [("oracle", "co")]


def test_a_tie_for_the_best_robot_goes_to_the_robot_the_study_lists_first(monkeypatch: pytest.MonkeyPatch) -> None:
    """evaluate.py:164: no oracle rate, two robots with the same mean 30: the reference names
    the one the study lists first ("zeta"), not the alphabetically first ("alpha")."""
    zeta, alpha = Actor("planner", {}, "zeta"), Actor("habit", {}, "alpha")
    study = _study([zeta, alpha], [Actor("switching", {}, "sw")])
    monkeypatch.setattr(ev, "oracle_rate", lambda *a: None)
    plan = ev.cells(study)
    runs = [SimpleNamespace(tasks=1, rate=30.0, key="k") for _ in plan]
    frame = ev.score_table(study, plan, runs, store=None)
    assert set(frame["reference"]) == {"best robot (zeta)"}


def test_an_update_on_equal_advantages_changes_no_weight(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """ppo_recurrent.py:322: advantages are normalised to mean 0 and spread 1, the spread
    guarded by a small epsilon: a minibatch whose advantages are all equal (here all 0: every
    reward what the values predicted) normalises to 0 and prefers no action. With the value
    and entropy terms off (coefficients 0) the loss then has no gradient, so an update
    changes no weight; it must not make them NaN (0 / 0)."""
    import dataclasses

    import torch

    import hg_marl.training.baselines.ppo_recurrent as ppo
    from hg_marl.agents.memory_policy import MemoryNet
    from tests.training.test_ppo_recurrent import Cue, toy_config

    monkeypatch.setattr(ppo, "advantages", lambda buf, nv, lam: (torch.zeros_like(buf.rew), torch.zeros_like(buf.rew)))
    config = dataclasses.replace(
        toy_config("mlp", tmp_path, 1), num_envs=8, steps=8 * 12, ent_coef=0.0, vf_coef=0.0, eval_seconds=3.0
    )
    seen: list[dict[str, Any]] = []

    def keep(steps: int, net: Any) -> None:
        seen.append({k: v.clone() for k, v in net.state_dict().items()})

    ppo.train_recurrent(config, on_update=keep, env=Cue(8))
    torch.manual_seed(config.seed)  # the net as train_recurrent builds it before any update
    initial = MemoryNet(3, 2, config.hidden, False).state_dict()
    (after,) = seen
    assert all(torch.isfinite(v).all() for v in after.values())
    assert all(torch.equal(after[k], initial[k]) for k in initial)
