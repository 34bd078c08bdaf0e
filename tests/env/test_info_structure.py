"""Infos have a fixed structure across a run, so libraries can batch them into replay buffers."""

from __future__ import annotations

from typing import Any

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import hg_marl

# The documented structure (module docstring of hg_marl.envs.table_cleaning), stated here
# independently of the code: key -> Python type; every value is a scalar (shape ()).
EXPECTED = {
    "clock": float,
    "cycle": int,
    "tasks_solved": int,
    "action": str,
    "failed": bool,
    "events": str,
    "effort": float,
    "idle": float,
}


def signature(info: dict[str, Any]) -> dict[str, tuple[type, tuple[int, ...]]]:
    return {k: (type(v), np.shape(v)) for k, v in info.items()}


EXPECTED_SIGNATURE = {k: (t, ()) for k, t in EXPECTED.items()}


@settings(max_examples=15, deadline=None)
@given(
    seed=st.integers(0, 2**16),
    continuing=st.booleans(),
    feasible_only=st.booleans(),
    scenario=st.sampled_from(["paper2015", "roboergosum"]),
)
def test_every_info_value_has_one_type_and_shape_across_a_run(
    seed: int, continuing: bool, feasible_only: bool, scenario: str
) -> None:
    env = hg_marl.env(scenario=scenario, continuing=continuing, max_cycles=60)
    env.reset(seed=seed)
    rng = np.random.default_rng(seed)
    seen = 0
    for agent in env.possible_agents:
        assert signature(env.infos[agent]) == EXPECTED_SIGNATURE  # at reset too
    for agent in env.agent_iter():
        obs, _, terminated, truncated, info = env.last()
        assert signature(info) == EXPECTED_SIGNATURE, agent
        seen += 1
        if terminated or truncated:
            action = None
        elif feasible_only:
            action = int(rng.choice(np.flatnonzero(obs["action_mask"])))
        else:
            action = int(rng.integers(env.action_space(agent).n))
        env.step(action)
    assert seen > 2


def test_parallel_infos_have_the_same_structure() -> None:
    env = hg_marl.parallel_env(max_cycles=30)
    _, infos = env.reset(seed=1)
    rng = np.random.default_rng(1)
    steps = 0
    while env.agents:
        for info in infos.values():
            assert signature(info) == EXPECTED_SIGNATURE
        actions = {a: int(rng.integers(env.action_space(a).n)) for a in env.agents}
        _, _, _, _, infos = env.step(actions)
        steps += 1
    assert steps == 30


def test_events_are_joined_sentences_or_a_tuple_behind_the_flag() -> None:
    names = {"robot": hg_marl.env().unwrapped.action_names("robot")}
    throw = names["robot"].index("throw(tape1)")  # infeasible at the start: the robot holds nothing
    joined, tupled = hg_marl.env(), hg_marl.env(events_tuple=True)
    for env in (joined, tupled):
        env.reset(seed=0)
        env.step(throw)
    assert isinstance(joined.infos["robot"]["events"], str)
    assert joined.infos["robot"]["events"].startswith("robot failed")
    assert tupled.infos["robot"]["events"] == tuple(joined.infos["robot"]["events"].split("; "))
