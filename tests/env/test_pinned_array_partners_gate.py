"""The batched seats' partners over arrays: draws, fall-backs and which partner is built, pinned for the mutation gate.

Expected values worked by hand from ``agents/array_partners.py``'s docstrings, on stand-in
members whose answers the test sets: a population keeps one member per table (its
``member`` array as long as the tables reset so far), a reset of some tables leaves the
others' members alone, and the live members answer only their own tables that were not
found; live robots start each table's actor with a seed drawn from the given generator
over ``[0, 2**63 - 1)``, in row order (the reference is that rule, written out); one
human is that human's compiled table, not a population of one; a robot list is compiled
only when it names one compilable robot (``planner``), other robots stay live without a
warning (the warning is for a scenario over the compiler's budget); the compiled robot
is built without a progress bar and, by default, cached under ``$HG_MARL_CACHE``. Live robots
in the human's seat see each table's clock and tasks solved, as the live env shows them.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.array_partners import CompiledPopulation, LiveRobots, compiled_humans, compiled_robots
from hg_marl.core import Agent, World
from hg_marl.core.batch import BatchState
from hg_marl.policy import Turn


class _Member:
    """A compiled-member stand-in: two table entries; records the tables each fall-back was asked for."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.actions = np.array([0, 1])
        self.outcome = {"p": np.array([0.5, 0.5])}
        self.fallbacks = 0
        self.fell_back_rows: list[list[int]] = []

    def answer(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        return np.zeros(len(seen), dtype=np.int64), np.ones(len(seen), dtype=bool)

    def fall_back(
        self, batch: Any, seen: np.ndarray, rng: np.random.Generator, out: np.ndarray, found: np.ndarray
    ) -> np.ndarray:
        self.fell_back_rows.append(batch.rows.tolist())
        self.fallbacks += len(seen)
        return np.full(len(seen), 7, dtype=np.int64)


def _batch(rows: list[int]) -> BatchState:
    n = len(rows)
    zeros = np.zeros(n, dtype=np.int64)
    return BatchState(np.zeros((n, 3), dtype=np.int64), zeros, zeros, zeros, np.array(rows))


def test_a_population_keeps_one_member_per_table_reset_so_far() -> None:
    population = CompiledPopulation([_Member("a"), _Member("b")])
    rng = np.random.default_rng(0)
    population.reset_rows(np.arange(0), rng)  # no table yet: nothing drawn, nothing grown
    assert len(population.member) == 0
    population.reset_rows(np.arange(4), rng)
    assert len(population.member) == 4
    population.reset_rows(np.array([4, 5]), rng)
    assert len(population.member) == 6


def test_resetting_some_tables_keeps_the_other_tables_members() -> None:
    population = CompiledPopulation([_Member("a"), _Member("b"), _Member("c")])
    population.reset_rows(np.arange(6), np.random.default_rng(0))
    before = population.member.copy()
    population.reset_rows(np.array([1, 3]), np.random.default_rng(1))
    assert len(population.member) == 6
    kept = [0, 2, 4, 5]
    assert population.member[kept].tolist() == before[kept].tolist()


def test_each_live_member_falls_back_only_on_its_own_tables_not_found() -> None:
    """Tables 0, 1 play member a and 2, 3 member b; tables 1 and 3 were found: a falls back on 0, b on 2."""
    a, b = _Member("a"), _Member("b")
    population = CompiledPopulation([a, b])
    population.member = np.array([0, 0, 1, 1])
    out = np.full(4, -1, dtype=np.int64)
    found = np.array([False, True, False, True])
    population.fall_back(_batch([0, 1, 2, 3]), np.full(4, -1), np.random.default_rng(0), out, found)
    assert a.fell_back_rows == [[0]] and b.fell_back_rows == [[2]]
    assert out.tolist() == [7, -1, 7, -1] and population.fallbacks == 2


class _Seeded:
    """A robot stand-in that records the first draw of each generator it is reset with."""

    name = "seeded"

    def __init__(self) -> None:
        self.first_draws: list[float] = []

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.first_draws.append(float(rng.random()))

    def act(self, turn: Turn) -> int:
        return 0


def test_live_robots_are_seeded_from_the_generator_in_row_order() -> None:
    robot = _Seeded()
    live = LiveRobots(World("paper2015"), robot, 3)
    live.reset_rows(np.array([2, 0, 1]), np.random.default_rng(11))
    reference = np.random.default_rng(11)
    expected = [float(np.random.default_rng(int(reference.integers(0, 2**63 - 1))).random()) for _ in range(3)]
    assert robot.first_draws == expected


def test_one_human_is_its_compiled_table_not_a_population_of_one() -> None:
    partner = compiled_humans(World("paper2015"), "lazy", cache=None)
    assert not isinstance(partner, CompiledPopulation)
    assert partner.name == "lazy"


@pytest.mark.parametrize("robot", ["random", ["planner", "random"], ["random", "planner"]])
def test_robots_other_than_one_compilable_name_stay_live_without_a_warning(
    robot: Any, caplog: pytest.LogCaptureFixture
) -> None:
    with caplog.at_level(logging.WARNING, logger="hg_marl.agents.array_partners"):
        partner = compiled_robots(World("paper2015"), robot, 2, cache=None)
    assert isinstance(partner, LiveRobots)
    assert caplog.records == []


def test_the_compiled_planner_is_built_quietly_and_cached_by_default(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capfd: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("HG_MARL_CACHE", str(tmp_path))
    partner = compiled_robots(World("paper2015"), "planner", 2)
    assert not isinstance(partner, LiveRobots)
    assert capfd.readouterr().err == ""  # no progress bar
    assert any(p.is_file() for p in (tmp_path / "partners").rglob("*"))


def test_a_learned_human_given_by_its_spec_is_named_by_that_spec(tmp_path: Path) -> None:
    """An SB3 human plays batched under the name it was asked for (its spec), as a compiled one does."""
    torch = pytest.importorskip("torch")  # an extra: the lowest-versions session has neither
    sb3 = pytest.importorskip("stable_baselines3")
    PPO = sb3.PPO
    from hg_marl.agents.humans.learned import save_sb3_policy
    from hg_marl.agents.views import HumanView

    torch.set_num_threads(1)
    model = PPO("MlpPolicy", HumanView("paper2015", robot="random"), n_steps=16, batch_size=16, seed=0, device="cpu")
    save_sb3_policy(tmp_path / "policy", model, "paper2015", observation="facts")
    spec = f"learned:path={tmp_path / 'policy'}"
    assert compiled_humans(World("paper2015"), spec, cache=None).name == spec


class _Recording:
    """The planner as a robot actor, recording the clock and tasks solved of every turn it is given."""

    name = "recording"

    def __init__(self) -> None:
        from hg_marl.agents.robots import make_robot

        self.inner = make_robot("planner")
        self.seen: list[tuple[float, int]] = []

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.inner.reset(world, agent, rng)

    def act(self, turn: Turn) -> int:
        self.seen.append((turn.clock, turn.tasks_solved))
        return int(self.inner.act(turn))


def test_live_robots_in_the_human_seat_see_each_tables_clock_and_tasks() -> None:
    # A robot's turn opens the next cycle: it sees the clock the human's step ended at and
    # the tasks solved before its own move (a task its move completes is counted after it,
    # as in the live env), so each turn after the first is the previous step's info, less
    # that step's task reward. The first turn comes at the reset: clock 0, no task.
    from hg_marl.agents.vector_envs import human_vector_env

    robots = [_Recording(), _Recording()]
    env = human_vector_env(num_envs=2, robot=robots, compiled=False, continuing=True, max_cycles=None)
    env.reset(seed=0)
    rng = np.random.default_rng(0)
    expected: list[list[tuple[float, int]]] = [[(0.0, 0)], [(0.0, 0)]]
    for _ in range(80):
        masks = env.action_masks()
        _, _, _, _, info = env.step(np.array([rng.choice(np.flatnonzero(m)) for m in masks]))
        for i in range(2):
            expected[i].append(
                (float(info["clock"][i]), int(info["tasks_solved"][i]) - int(info["task_reward"][i] > 0))
            )
    assert [r.seen for r in robots] == expected
    assert all(r.seen[-1][0] > 100.0 and r.seen[-1][1] >= 3 for r in robots)  # the run went far enough to tell
