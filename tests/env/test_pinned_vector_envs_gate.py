"""The batched seats' default episode: 500 cycles, as the single-table environment's.

Both seats are stepped with ``wait`` only (nothing is ever solved, so only the cycle limit
ends the episode); the table must report truncation at the 500th step and not before.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.vector_envs import human_vector_env, robot_vector_env
from hg_marl.core import Agent, World
from hg_marl.policy import Turn


class Waiter:
    """A partner that only ever waits (live in either seat)."""

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.wait = world.table.wait[agent]

    def act(self, turn: Turn) -> int:
        return int(self.wait)


@pytest.mark.parametrize("seat", [Agent.ROBOT, Agent.HUMAN])
def test_the_default_episode_is_truncated_at_500_cycles(seat: Agent) -> None:
    if seat is Agent.ROBOT:
        env = robot_vector_env(num_envs=1, human="lazy:p_idle=1.0")
    else:
        env = human_vector_env(num_envs=1, robot=Waiter())
    env.reset(seed=0)
    wait = np.array([env.world.table.wait[seat]])
    for step in range(1, 501):
        _, _, terminated, truncated, _ = env.step(wait)
        assert not terminated[0]
        assert bool(truncated[0]) is (step == 500), step


@pytest.mark.parametrize("seat", [Agent.ROBOT, Agent.HUMAN])
@pytest.mark.parametrize("cache", [None, False])
def test_the_compiled_partner_is_cached_under_hg_marl_cache_by_default(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, cache: bool | None, seat: Agent
) -> None:
    """``cache=True`` (the default of both seats) writes the compiled partner (a human, or
    the planner robot) under ``$HG_MARL_CACHE/partners``; ``cache=False`` writes nothing."""
    monkeypatch.setenv("HG_MARL_CACHE", str(tmp_path))
    kwargs = {} if cache is None else {"cache": cache}
    if seat is Agent.ROBOT:
        robot_vector_env(num_envs=1, human="lazy:p_idle=0.5", **kwargs)
    else:
        human_vector_env(num_envs=1, scenario="generated:objects=2,seed=1", **kwargs)
    written = [p.relative_to(tmp_path).parts[0] for p in tmp_path.rglob("*") if p.is_file()]
    assert written == (["partners"] if cache is None else []), written


def test_one_table_by_default() -> None:
    assert robot_vector_env(human="lazy").num_envs == 1
    assert human_vector_env(robot=Waiter()).num_envs == 1
