"""PettingZoo's own conformance tests, for every built-in scenario and both modes."""

from __future__ import annotations

import functools
import types

import pytest
from pettingzoo.test import api_test, max_cycles_test, parallel_api_test, render_test, seed_test

import hg_marl
from tests.env.seeded_spaces import seeded

SCENARIOS = ["paper2015", "roboergosum", "generated:objects=4,spots=6,locations=3,bins=2,seed=2"]
pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("continuing", [False, True])
def test_api(scenario: str, continuing: bool) -> None:
    api_test(seeded(hg_marl.env(scenario=scenario, continuing=continuing)), num_cycles=300)


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("continuing", [False, True])
def test_parallel_api(scenario: str, continuing: bool) -> None:
    parallel_api_test(seeded(hg_marl.parallel_env(scenario=scenario, continuing=continuing)), num_cycles=300)


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_seed(scenario: str) -> None:
    seed_test(functools.partial(hg_marl.env, scenario=scenario), num_cycles=200)


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_max_cycles(scenario: str) -> None:
    mod = types.SimpleNamespace(
        env=functools.partial(hg_marl.env, scenario=scenario),
        parallel_env=functools.partial(hg_marl.parallel_env, scenario=scenario),
    )
    max_cycles_test(mod)


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_render(scenario: str) -> None:
    # render_test first builds the env with render_mode="human" only to read its
    # metadata; the environment has no human mode (it never opens a window).
    def make(render_mode: str | None = None) -> object:
        return hg_marl.env(scenario=scenario, render_mode=None if render_mode == "human" else render_mode)

    render_test(make)


def test_registered_ids() -> None:
    import pettingzoo

    aec = pettingzoo.make("aec", "hg_marl/TableCleaning-v0", scenario="roboergosum")
    aec.reset(seed=0)
    assert aec.unwrapped.world.scenario.name == "roboergosum"
    par = pettingzoo.make("parallel", "hg_marl/TableCleaning-v0")
    obs, _ = par.reset(seed=0)
    assert set(obs) == {"robot", "human"}
