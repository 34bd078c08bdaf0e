"""The SB3 training environments: specs, views, partner parsing and the vector env, pinned for the gate.

Expected values are the module's documented rules, checked on the objects built: episodic
views (``continuing=False``) truncated at ``max_cycles`` (100 by default); the robot seat
holds humans, the human seat robots parsed from ``name:k=v,...`` (values JSON when they
parse, else the stripped text); a population splits on commas, a bare ``key=value``
continuing the previous partner; the vector env's members are seeded ``seed, seed + 1, ...``
(compared with views reset by hand with those seeds). Nothing here trains or is timed.
"""

from __future__ import annotations

from typing import Any

import gymnasium
import numpy as np
import pytest

from hg_marl.agents.views import HumanView, RobotView
from hg_marl.training.baselines.envs import (
    DEFAULT_MAX_CYCLES,
    SEATS,
    EnvSpec,
    _robot,
    check_view,
    make_vec_env,
    split_population,
)


def test_the_defaults_are_the_documented_ones() -> None:
    spec = EnvSpec()
    assert (spec.seat, spec.partners, spec.scenario, spec.observation) == (
        "robot",
        ("cooperative",),
        "paper2015",
        "facts",
    )
    assert (spec.max_cycles, spec.effort_weight) == (100, 0.0)
    assert DEFAULT_MAX_CYCLES == 100 and SEATS == ("robot", "human")


@pytest.mark.parametrize(
    ("changes", "match"),
    [
        ({"seat": "table"}, r"seat must be one of \('robot', 'human'\), got 'table'"),
        ({"partners": ()}, "need at least one partner"),
        ({"max_cycles": 0}, "max_cycles must be positive, got 0"),
    ],
)
def test_a_spec_out_of_range_is_refused(changes: dict[str, Any], match: str) -> None:
    with pytest.raises(ValueError, match=match):
        EnvSpec(**changes)


def test_the_robot_seat_is_an_episodic_robot_view_with_its_humans() -> None:
    view = EnvSpec(partners=("lazy", "no_handover"), max_cycles=7, observation="flat").make()
    assert isinstance(view, RobotView)
    assert view.env.continuing is False and view.env.max_cycles == 7 and view.observation_mode == "flat"
    assert [getattr(p, "name", p) for p in view._partners] == ["lazy", "no_handover"]


def test_the_human_seat_is_an_episodic_human_view_with_its_robots_and_effort_weight() -> None:
    view = EnvSpec(seat="human", partners=("planner", "hybrid"), max_cycles=9, effort_weight=0.25).make()
    assert isinstance(view, HumanView)
    assert view.env.continuing is False and view.env.max_cycles == 9 and view.observation_mode == "facts"
    assert view.effort_weight == 0.25
    assert [type(p).__name__ for p in view._partners] == ["PlannerRobot", "HybridRobot"]


def test_each_view_has_its_own_partners() -> None:
    spec = EnvSpec(seat="human", partners=("planner",))
    assert spec.make()._partners[0] is not spec.make()._partners[0]


def test_a_robot_spec_reads_json_values_and_keeps_other_text_stripped() -> None:
    """``true`` is JSON (a bool), ``entropy`` is not (the text); spaces and empty pieces are dropped."""
    robot = _robot(" hybrid : partner_features= true ,,partner_aware=true, criterion = entropy ")
    assert type(robot).__name__ == "HybridRobot"
    assert robot.partner_features is True and robot.partner_aware is True
    assert type(robot.meta.criterion).__name__ == "EntropyCriterion"
    assert type(_robot("planner")).__name__ == "PlannerRobot"


def test_a_text_value_reaches_the_robot_without_its_spaces() -> None:
    """``path= nofile.json `` is not JSON: the robot is given ``nofile.json``, as its refusal names it."""
    from hg_marl.core.errors import ModelFileError

    with pytest.raises(ModelFileError, match=r"^--model nofile\.json: no such model header \(nofile\.json\)$"):
        _robot("sb3:path= nofile.json ")


def test_a_population_splits_on_commas_and_bare_settings_continue_the_previous_partner() -> None:
    assert split_population("cooperative, lazy:p_idle=0.5,p=1 ,,no_handover") == (
        "cooperative",
        "lazy:p_idle=0.5,p=1",
        "no_handover",
    )
    assert split_population("noisy:t=2") == ("noisy:t=2",)
    # a bare key=value with no partner before it is a (bad) partner of its own, for the registry to refuse
    assert split_population("p_idle=0.5,lazy") == ("p_idle=0.5", "lazy")
    for empty in ("", " , ,"):
        with pytest.raises(ValueError, match="no partner in"):
            split_population(empty)


def test_the_vector_env_seeds_its_members_one_after_another() -> None:
    """Member ``i`` starts from the table a view reset with ``seed + i`` starts from, Monitor-wrapped."""
    from stable_baselines3.common.monitor import Monitor

    spec = EnvSpec(partners=("lazy",), max_cycles=5)
    vec = make_vec_env(spec, 3, seed=40)
    assert vec.num_envs == 3 and all(isinstance(e, Monitor) for e in vec.envs)
    assert vec.envs[0].env is not vec.envs[1].env
    obs = vec.reset()
    for i in range(3):
        alone, _ = spec.make().reset(seed=40 + i)
        assert np.array_equal(obs[i], alone)
    unseeded = make_vec_env(spec, 2)
    assert unseeded.num_envs == 2 and unseeded.reset().shape == obs[:2].shape


class _Unnormalised(gymnasium.Env):
    """An env SB3's checker warns about: a continuous action box over [0, 5], not [-1, 1]."""

    observation_space = gymnasium.spaces.Box(0, 1, (2,), np.float32)
    action_space = gymnasium.spaces.Box(0, 5, (1,), np.float32)

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
        super().reset(seed=seed)
        return np.zeros(2, np.float32), {}

    def step(self, action: Any) -> tuple[Any, float, bool, bool, dict[str, Any]]:
        return np.zeros(2, np.float32), 0.0, True, False, {}


class _UnnormalisedSpec(EnvSpec):
    def make(self) -> Any:
        return _Unnormalised()


def test_check_view_returns_the_checkers_warnings() -> None:
    """No warning on a real view; the checker's warnings, as text, on a view it finds fault with."""
    assert check_view(EnvSpec(observation="dict")) == []
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the caller's filters do not hide the checker's findings
        caught = check_view(_UnnormalisedSpec())
    assert caught and all(isinstance(w, str) for w in caught)
    assert any("symmetric and normalized Box action space" in w for w in caught)


def test_a_spec_is_frozen() -> None:
    """A spec is shared by every environment of a vector env (and checked once): it cannot change after."""
    import dataclasses

    with pytest.raises(dataclasses.FrozenInstanceError):
        EnvSpec().max_cycles = 5
