"""The cycle's one home: worked examples, the AEC environment against ``cycle``, the batched twin.

Also a scan of the code for stray copies of the clock rule (a cycle's length as the
longer of two durations): it lives in ``hg_marl/core/cycle.py``, and the few places
that still restate it are named below, so the list can only shrink.
"""

from __future__ import annotations

import ast
import copy
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hg_marl.core import Agent, State, World
from hg_marl.core.cycle import (
    RESET_EVENT,
    Clock,
    Half,
    Halves,
    close,
    close_batch,
    cycle,
    effort_batch,
    ends_episode,
    half,
    seat_reward,
    seen,
    seen_batch,
    truncated,
    truncated_batch,
)
from hg_marl.envs.table_cleaning import raw_env

ROOT = Path(__file__).resolve().parents[2]


# ---- worked by hand ---------------------------------------------------------------------
def _played(duration: float, waited: bool) -> Half:
    """A half as ``close`` reads it: its duration and whether it was a wait."""
    return Half(State((), 0), True, duration, 0.0, (), 0.0 if waited else duration, waited)


def test_a_cycle_lasts_the_longer_action_and_a_waiter_idles_all_of_it() -> None:
    # robot waits 1 s, human picks 2 s: the cycle lasts 2 s; the robot idles 2, the human 0
    assert close(_played(1.0, True), _played(2.0, False)) == (2.0, (2.0, 0.0))
    # robot throws 3 s, human picks 2 s, 0.5 s of planning charged: 3.5 s; idle 0.5 and 1.5
    assert close(_played(3.0, False), _played(2.0, False), charged=0.5) == (3.5, (0.5, 1.5))


def test_a_run_clock_adds_up_its_cycles_and_stops_at_its_limits() -> None:
    clock = Clock(max_cycles=3, time_budget=None)
    # the two cycles above, in turn: 2 s then 3.5 s; idle robot 2 + 0.5, human 0 + 1.5
    assert not clock.tick(_played(1.0, True), _played(2.0, False))
    assert not clock.tick(_played(3.0, False), _played(2.0, False), charged=0.5)
    assert (clock.now, clock.cycles, clock.idle) == (5.5, 2, [2.5, 1.5])
    assert clock.tick(_played(1.0, False), _played(1.0, False))  # the third cycle is the last
    budget = Clock(time_budget=4.0)
    assert not budget.tick(_played(3.0, False), _played(1.0, False))  # 3 s < 4 s
    assert budget.tick(_played(1.0, False), _played(1.0, True))  # 4 s: the budget is reached


def test_the_human_sees_only_a_successful_robot_action() -> None:
    assert seen(4, True) == 4
    assert seen(4, False) == -1


def test_truncation_by_cycles_or_clock() -> None:
    assert truncated(10, 3.0, 10, None)
    assert not truncated(9, 3.0, 10, None)
    assert truncated(1, 30.0, None, 30.0)
    assert not truncated(1, 29.9, None, 30.0)
    assert not truncated(10**6, 1e9, None, None)


def test_the_human_seat_reward_and_episode_end() -> None:
    assert seat_reward(1.0, 4.0, 0.25) == 0.0
    assert seat_reward(0.0, 2.0, 0.5) == -1.0
    assert ends_episode(1.0, False) and not ends_episode(1.0, True) and not ends_episode(0.0, False)


def test_a_solved_table_is_redrawn_only_when_the_run_goes_on() -> None:
    world = World("paper2015")
    bins = world.n_spots  # the paper's one bin
    clean = world.initial_state(np.random.default_rng(0))._replace(where=(bins,) * world.n_objects)
    wait = world.table.wait[Agent.ROBOT]
    episodic = half(world, clean, Agent.ROBOT, wait)
    assert episodic.reward == 1.0 and episodic.state == clean and RESET_EVENT not in episodic.events
    assert episodic.waited and episodic.effort == 0.0
    rng = np.random.default_rng(3)
    expected = world.initial_state(np.random.default_rng(3))
    going_on = half(world, clean, Agent.ROBOT, wait, rng)
    assert going_on.state == expected and going_on.events[-1] == RESET_EVENT
    halves = Halves(world).play
    assert halves(clean, Agent.ROBOT, wait) == episodic  # memoised without the redraw
    assert halves(clean, Agent.ROBOT, wait, np.random.default_rng(3)) == going_on  # the redraw applied afresh


# ---- the AEC environment runs exactly `cycle` ---------------------------------------------
@pytest.mark.parametrize(("scenario", "continuing"), [("paper2015", True), ("roboergosum", False)])
def test_the_aec_env_steps_as_cycle(scenario: str, continuing: bool) -> None:
    env = raw_env(scenario=scenario, continuing=continuing, max_cycles=None)
    env.reset(seed=1)
    rng = np.random.default_rng(2)
    world = env.world
    solved = 0
    for _ in range(400):
        state, clock = env.world_state, env.clock
        effort, idle = list(env._effort), list(env._idle)
        redraw = copy.deepcopy(env._rng) if continuing else None
        charged = float(rng.integers(0, 3)) / 2
        env.charge_time(charged)
        acts = []
        for agent in Agent:
            mask = env.observe(agent.label)["action_mask"]
            a = int(rng.choice(np.flatnonzero(mask))) if rng.random() < 0.9 else int(rng.integers(len(mask)))
            acts.append(a)
            env.step(a)
        out = cycle(world, state, acts[0], acts[1], redraw, charged)
        solved += out.reward > 0
        assert env.world_state == out.state
        assert env.clock == clock + out.time.length
        assert env._effort == [effort[0] + out.robot.effort, effort[1] + out.human.effort]
        assert env._idle == [idle[0] + out.time.idle[0], idle[1] + out.time.idle[1]]
        for agent, part in zip(("robot", "human"), (out.robot, out.human), strict=True):
            assert env.infos[agent]["events"] == "; ".join(str(e) for e in part.events)
            assert env.infos[agent]["failed"] == (not part.ok)
        if env.terminations["robot"]:
            assert not continuing and out.reward > 0
            env.reset(seed=int(rng.integers(1000)))
    assert solved > 0  # the redraw (or the episode's end) was exercised


# ---- the batched twin ---------------------------------------------------------------------
durations = st.lists(st.sampled_from([0.0, 0.5, 1.0, 2.0, 3.0, 7.25]), min_size=1, max_size=20)


@settings(max_examples=60, deadline=None)
@given(d=st.data())
def test_the_batched_twin_agrees_with_the_scalar_rules(d: st.DataObject) -> None:
    d_r = d.draw(durations)
    n = len(d_r)
    d_h = d.draw(st.lists(st.sampled_from([0.0, 0.5, 2.0, 3.0]), min_size=n, max_size=n))
    flags = st.lists(st.booleans(), min_size=n, max_size=n)
    w_r, w_h, ok = d.draw(flags), d.draw(flags), d.draw(flags)
    acts = d.draw(st.lists(st.integers(0, 17), min_size=n, max_size=n))
    cycles = d.draw(st.lists(st.integers(0, 12), min_size=n, max_size=n))
    length, idle = close_batch((np.array(d_r), np.array(d_h)), (np.array(w_r), np.array(w_h)))
    effort = effort_batch(np.array(ok), np.array(w_r), np.array(d_r))
    shown = seen_batch(np.array(acts), np.array(ok))
    limits = d.draw(st.sampled_from([(None, None), (10, None), (None, 4.0), (3, 2.5)]))
    ends = truncated_batch(np.array(cycles), np.array(d_r), *limits)
    for i in range(n):
        t = close(_played(d_r[i], w_r[i]), _played(d_h[i], w_h[i]))
        assert (length[i], idle[0][i], idle[1][i]) == (t.length, t.idle[0], t.idle[1])
        assert effort[i] == (d_r[i] if ok[i] and not w_r[i] else 0.0)
        assert shown[i] == seen(acts[i], ok[i])
        assert ends[i] == truncated(cycles[i], d_r[i], *limits)


# ---- no stray copy of the clock rule or the reward rule -----------------------------------
KNOWN_COPIES: set[str] = set()
"""Modules that still restate a cycle's length; each should call ``hg_marl.core.cycle``."""

KNOWN_REWARD_COPIES: set[str] = set()
"""Modules that still restate the completing wait; each should call ``RuleTable.solves``."""


def _restates_the_clock(tree: ast.AST) -> bool:
    """A two-argument ``max``/``np.maximum`` of two durations (``d_...``, ``...dur...``)."""
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call) or len(node.args) != 2:
            continue
        name = node.func.id if isinstance(node.func, ast.Name) else getattr(node.func, "attr", "")
        if name not in ("max", "maximum"):
            continue
        names = [ast.unparse(a) for a in node.args]
        if all(n.startswith("d_") or "dur" in n or n in ("d", "dr", "dh") for n in names):
            return True
    return False


def _restates_the_reward(tree: ast.AST) -> bool:
    """An ``and`` of a ``wait`` comparison and an ``is_clean(...)`` call: the completing wait written out."""
    for node in ast.walk(tree):
        if isinstance(node, ast.BoolOp) and isinstance(node.op, ast.And):
            parts = [ast.unparse(v) for v in node.values]
            if any("wait" in p and isinstance(v, ast.Compare) for p, v in zip(parts, node.values, strict=True)) and any(
                "is_clean(" in p for p in parts
            ):
                return True
    return False


def _offenders(restates: Callable[[ast.AST], bool]) -> set[str]:
    found = set()
    for package in ("hg_marl", "agents", "training"):
        for path in sorted((ROOT / package).rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            if not rel.startswith("hg_marl/core/") and restates(ast.parse(path.read_text(encoding="utf-8"))):
                found.add(rel)
    return found


def test_no_module_restates_the_clock_rule() -> None:
    offenders = _offenders(_restates_the_clock)
    assert offenders <= KNOWN_COPIES, "call hg_marl.core.cycle (cycle_length, close) instead of restating it"


def test_no_module_restates_the_reward_rule() -> None:
    offenders = _offenders(_restates_the_reward)
    assert offenders <= KNOWN_REWARD_COPIES, "call RuleTable.solves instead of restating the completing wait"


def test_the_scans_find_a_restated_rule() -> None:
    assert _restates_the_clock(ast.parse("t = max(d_robot, d_human)"))
    assert _restates_the_clock(ast.parse("t = np.maximum(dur[0], dur[1])"))
    assert not _restates_the_clock(ast.parse("t = max(a, b)"))
    assert _restates_the_reward(ast.parse("done = ok and a == wait and table.is_clean(state.where)"))
    assert not _restates_the_reward(ast.parse("done = table.solves(state, agent, a)"))


def test_solves_is_the_robots_wait_on_a_clean_table() -> None:
    world = World("paper2015")
    clean = world.initial_state(np.random.default_rng(0))._replace(where=(world.n_spots,) * world.n_objects)
    messy = world.initial_state(np.random.default_rng(0))
    table = world.table
    assert table.solves(clean, Agent.ROBOT, table.wait[Agent.ROBOT])
    assert not table.solves(clean, Agent.HUMAN, table.wait[Agent.HUMAN])
    assert not table.solves(clean, Agent.ROBOT, 0)
    assert not table.solves(messy, Agent.ROBOT, table.wait[Agent.ROBOT])


def test_a_batched_table_is_truncated_when_its_clock_reaches_the_budget_exactly() -> None:
    # clocks 99.9, 100.0 and 100.1 against a 100 s budget; cycles 9, 10, 11 against 10: each
    # limit is reached at its value (as the scalar rule, which ends a run at clock == budget)
    clocks = np.array([99.9, 100.0, 100.1])
    assert truncated_batch(np.zeros(3, dtype=np.int64), clocks, None, 100.0).tolist() == [False, True, True]
    assert truncated_batch(np.array([9, 10, 11]), np.zeros(3), 10, None).tolist() == [False, True, True]
    assert [truncated(0, float(c), None, 100.0) for c in clocks] == [False, True, True]
