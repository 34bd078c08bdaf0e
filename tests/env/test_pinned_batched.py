"""The batched table's episode boundaries and counters, worked by hand on waiting partners.

paper2015's durations: wait 1 s, goto 3 s, a failed action 0.2 s; a cycle lasts the
longer of the two moves. With both seats waiting the clock reads exactly ``k`` after
``k`` cycles, so a budget of a whole number of seconds is *reached*, not passed: the
table must be truncated on that very cycle ("truncate once the clock reaches the
budget"), not one later. The same holds for ``max_cycles``.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.batched import BatchedTable, BatchState

ROBOT_WAIT, HUMAN_WAIT = 17, 30
"""paper2015's wait indices (robot, human)."""
GOTO_HUMAN = 16
"""The robot's goto(human): feasible in the first layout of seed 0, 3 s."""


class Always:
    """A partner that plays one action index on every table."""

    def __init__(self, action: int) -> None:
        self.action = action

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.full(len(batch), self.action, dtype=np.int64)


@pytest.fixture(scope="module")
def world() -> World:
    return World("paper2015")


def _robot_env(world: World, n: int = 1, **kw: object) -> BatchedTable:
    env = BatchedTable(Always(HUMAN_WAIT), n, world, **kw)  # type: ignore[arg-type]
    env.reset(seed=0)
    return env


def _flags(env: BatchedTable, action: int, steps: int) -> list[tuple[bool, bool, float]]:
    out = []
    for _ in range(steps):
        _, _, term, trunc, info = env.step(np.full(env.num_envs, action))
        out.append((bool(term[0]), bool(trunc[0]), float(info["clock"][0])))
    return out


@pytest.mark.parametrize("budget", [3.0, 3])
def test_a_budget_reached_exactly_truncates_on_that_cycle(world: World, budget: float) -> None:
    env = _robot_env(world, max_cycles=None, time_budget=budget)
    # cycles 1..3 end at 1, 2, 3 s: the third reaches the budget; the fourth step is the
    # autoreset (reward 0, flags False, counters zeroed), the fifth starts a new episode
    assert _flags(env, ROBOT_WAIT, 5) == [
        (False, False, 1.0),
        (False, False, 2.0),
        (False, True, 3.0),
        (False, False, 0.0),
        (False, False, 1.0),
    ]


def test_a_budget_between_cycles_truncates_on_the_cycle_that_passes_it(world: World) -> None:
    env = _robot_env(world, max_cycles=None, time_budget=2.5)
    assert [t for _, t, _ in _flags(env, ROBOT_WAIT, 3)] == [False, False, True]


def test_max_cycles_truncates_on_the_last_cycle(world: World) -> None:
    env = _robot_env(world, max_cycles=3)
    assert [t for _, t, _ in _flags(env, ROBOT_WAIT, 4)] == [False, False, True, False]


def test_max_cycles_one_truncates_the_first_cycle(world: World) -> None:
    env = _robot_env(world, max_cycles=1)
    assert [t for _, t, _ in _flags(env, ROBOT_WAIT, 3)] == [True, False, True]


def test_both_limits_together_the_first_reached_wins(world: World) -> None:
    env = _robot_env(world, max_cycles=5, time_budget=2.0)
    assert [t for _, t, _ in _flags(env, ROBOT_WAIT, 2)] == [False, True]
    env = _robot_env(world, max_cycles=2, time_budget=50.0)
    assert [t for _, t, _ in _flags(env, ROBOT_WAIT, 2)] == [False, True]


def test_same_step_autoreset_on_a_budget_boundary(world: World) -> None:
    env = _robot_env(world, max_cycles=None, time_budget=2.0, autoreset_mode="same_step")
    _, _, _, trunc, info = env.step(np.array([ROBOT_WAIT]))
    assert not trunc[0] and "final_info" not in info
    _, _, _, trunc, info = env.step(np.array([ROBOT_WAIT]))
    assert trunc[0] and info["final_info"]["clock"][0] == 2.0 and bool(info["_final_obs"][0])
    _, _, _, trunc, info = env.step(np.array([ROBOT_WAIT]))  # a fresh episode: one cycle on its clock
    assert not trunc[0] and info["clock"][0] == 1.0


def test_human_seat_budget_reached_exactly(world: World) -> None:
    env = BatchedTable(Always(ROBOT_WAIT), 1, world, seat=Agent.HUMAN, max_cycles=None, time_budget=2.0)  # type: ignore[arg-type]
    env.reset(seed=0)
    flags = _flags(env, HUMAN_WAIT, 3)
    assert flags == [(False, False, 1.0), (False, True, 2.0), (False, False, 0.0)]


def test_counters_of_a_wait_a_failure_and_a_goto(world: World) -> None:
    """Effort counts successful non-wait work; idle is the cycle minus one's own work (all of it when waiting)."""
    env = _robot_env(world, max_cycles=None)
    assert not env.action_masks()[0, 0]  # action 0 is infeasible in this layout
    assert env.action_masks()[0, GOTO_HUMAN]
    _, r, _, _, info = env.step(np.array([0]))  # fails: 0.2 s against the human's 1 s wait
    assert (bool(info["failed"][0]), bool(info["human_failed"][0])) == (True, False)
    assert (info["clock"][0], info["effort"][0], info["idle"][0]) == pytest.approx((1.0, 0.0, 0.8))
    assert (info["partner_effort"][0], float(r[0])) == (0.0, 0.0)
    _, _, _, _, info = env.step(np.array([GOTO_HUMAN]))  # 3 s of work; the human waits the whole cycle
    assert not info["failed"][0] and info["human_action"][0] == HUMAN_WAIT
    assert (info["clock"][0], info["effort"][0], info["idle"][0]) == pytest.approx((4.0, 3.0, 0.8))
    assert env.idle[0, 1] == pytest.approx(1.0 + 3.0)  # the human waited through both cycles
    assert env.effort[0, 1] == 0.0 and info["cycle"][0] == 2


def test_a_goto_lands_on_the_budget(world: World) -> None:
    env = _robot_env(world, max_cycles=None, time_budget=3.0)
    _, _, term, trunc, info = env.step(np.array([GOTO_HUMAN]))
    assert (bool(term[0]), bool(trunc[0]), float(info["clock"][0])) == (False, True, 3.0)


def test_one_table_is_a_valid_batch_and_zero_is_not(world: World) -> None:
    assert BatchedTable(Always(HUMAN_WAIT), 1, world).num_envs == 1  # type: ignore[arg-type]
    with pytest.raises(ConfigError, match="num_envs"):
        BatchedTable(Always(HUMAN_WAIT), 0, world)  # type: ignore[arg-type]


def test_tables_keep_their_own_clocks(world: World) -> None:
    """Table 0 works (3 s cycles), table 1 waits (1 s): the budget of 3 s ends both on the same step only by chance."""
    env = _robot_env(world, n=2, max_cycles=None, time_budget=3.0)
    _, _, _, trunc, info = env.step(np.array([GOTO_HUMAN, ROBOT_WAIT]))
    assert trunc.tolist() == [True, False] and info["clock"].tolist() == [3.0, 1.0]
    _, rewards, _, trunc, info = env.step(np.array([ROBOT_WAIT, ROBOT_WAIT]))
    # table 0 is autoreset (its action ignored, reward 0, counters zero); table 1 carries on
    assert trunc.tolist() == [False, False] and info["clock"].tolist() == [0.0, 2.0]
    assert rewards.tolist() == [0.0, 0.0]


def test_a_compiled_humans_move_is_gathered_not_stepped(world: World, monkeypatch: pytest.MonkeyPatch) -> None:
    """A partner with outcome tables hands the next state: the rules step only the learning seat's move.

    Counted work, not time: 12 cycles on 3 tables are 12 calls of the batched rules (the
    robot's moves), where a partner without tables costs one more call per cycle.
    """
    from hg_marl.agents.compiled import compile_human

    human = compile_human(world, "cooperative", cache=None)
    env = BatchedTable(human, 3, world, max_cycles=None)
    env.reset(seed=0)
    calls = []
    step = env.rules.step
    monkeypatch.setattr(env.rules, "step", lambda *a, **k: calls.append(1) or step(*a, **k))
    rng = np.random.default_rng(0)
    for _ in range(12):
        masks = env.action_masks()
        env.step(np.array([rng.choice(np.flatnonzero(m)) for m in masks]))
    assert len(calls) == 12 and human.fallbacks == 0
    calls.clear()
    plain = BatchedTable(Always(HUMAN_WAIT), 3, world, max_cycles=None)  # type: ignore[arg-type]
    plain.reset(seed=0)
    plain_step = plain.rules.step
    monkeypatch.setattr(plain.rules, "step", lambda *a, **k: calls.append(1) or plain_step(*a, **k))
    plain.step(np.full(3, ROBOT_WAIT))
    assert len(calls) == 2
