"""Values a fresh mutation sample (seed 2026, 16 per module) showed unpinned in the newest modules.

The gate's sample (seed 2015) catches every mutant it draws; another draw of the same
modules left survivors. Each test here states, independently of the code under test,
what one of them changed: the oracle's values under the symmetry reduction equal the
unreduced ones; its off-model warning comes once; a result read from the cache reports
no more seconds than the call took; the result's text leaves out its large mappings;
the belief robot's planner spell ends when the partner acts (its action 0 included), not
when it waits; a probe changes the robot's action; a compiled table refuses a closure
human it cannot compile; the compiled robot's states are built silently by default; the
array guard marks a table whose robot waits patiently as decided by the guard; and a
``goto`` to a place that is not an object names no object.
"""

from __future__ import annotations

import logging
import time
from pathlib import Path

import numpy as np
import pytest
from test_pinned_belief_gate import _members

from hg_marl.agents.compiled import CompileError, compile_human
from hg_marl.agents.compiled_robot import robot_states
from hg_marl.agents.humans import make_human
from hg_marl.agents.models.equivariant import object_slots
from hg_marl.agents.oracle import OracleResult, OracleRobot, oracle_rate
from hg_marl.agents.progress import PATIENCE_AFTER, ArrayProgressGuard
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, Kind, World
from hg_marl.policy import Turn
from hg_marl.training.runner import RunConfig, run
from tests.agents.test_progress import batch_of


def test_the_value_at_a_state_is_the_same_with_and_without_the_symmetry_reduction() -> None:
    world = World("paper2015")
    reduced = oracle_rate(world, "cooperative", symmetry=True, cache=False)
    plain = oracle_rate(world, "cooperative", symmetry=False, cache=False)
    assert reduced.reduced and not plain.reduced
    states = [s for s, v in plain.values.items() if np.isfinite(v)][:200]
    assert len(states) == 200
    for state in states:
        assert reduced.value_at(world, state) == pytest.approx(plain.values[state], abs=1e-9)


def test_the_oracle_robot_warns_once_when_it_leaves_its_model(caplog: pytest.LogCaptureFixture) -> None:
    empty = OracleResult(0.0, float("inf"), 0, 0, 0, 0, True, {}, {}, scenario="paper2015")
    robot = OracleRobot(empty)
    world = World("paper2015")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    with caplog.at_level(logging.WARNING, logger="hg_marl.agents.oracle"):
        robot.act(Turn(world, state, Agent.ROBOT, {}))  # the first state off the (empty) model
        assert [str(state) in r.getMessage() for r in caplog.records] == [True]
        log = run(robot, make_human("cooperative"), RunConfig(scenario="paper2015", duration=60, seed=0)).log
    assert len(log) > 5  # every one of its states is off the model: one warning per run
    assert len([r for r in caplog.records if "no entry" in r.getMessage()]) == 2


def test_a_result_read_from_the_cache_reports_at_most_the_seconds_its_call_took(tmp_path: Path) -> None:
    oracle_rate("paper2015", "lazy", cache=tmp_path)
    t0 = time.perf_counter()
    stored = oracle_rate("paper2015", "lazy", cache=tmp_path)
    took = time.perf_counter() - t0
    assert 0.0 <= stored.seconds <= took


def test_an_oracle_result_prints_without_its_policy_and_values() -> None:
    result = oracle_rate("paper2015", "no_handover", cache=False)
    text = repr(result)
    assert "policy=" not in text and "values=" not in text
    assert f"n_states={result.n_states}" in text


def _belief(tmp_path: Path, world: World) -> BeliefRobot:
    robot = BeliefRobot(population=_members(tmp_path, coop="cooperative"), splits="train", unknown=0.0)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    return robot


@pytest.mark.parametrize(("human", "ends"), [(0, True), (3, True), ("wait", False)])
def test_the_planner_spell_ends_when_the_partner_acts_and_not_when_it_waits(
    tmp_path: Path, human: int | str, ends: bool
) -> None:
    world = World("paper2015")
    robot = _belief(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    wait_h = world.n_actions(Agent.HUMAN) - 1
    seen = wait_h if human == "wait" else int(human)
    assert seen == wait_h or world.actions(Agent.HUMAN)[seen].kind is not Kind.WAIT
    robot._planner_mode = True  # a spell begun at an earlier turn (the partner had stalled)
    robot.act(Turn(world, state, Agent.ROBOT, {}, last_actions=(world.n_actions(Agent.ROBOT) - 1, seen)))
    assert robot.last_decision is not None
    driven = str(robot.last_decision.reason).startswith("partner stalled, the planner drives")
    assert driven is not ends


def test_a_probe_changes_the_robots_action() -> None:
    import re

    config = RunConfig(scenario="forced_coordination", duration=300, seed=0)
    partner = "preference:handover=1.0,shared=-0.5,accept=0.3,p_idle=0.2"  # h_hesitant, held out
    log = run(BeliefRobot(population="populations/hard_layouts.toml", probe=20.0), make_human(partner), config).log
    probes = log.loc[log["reason"].astype(str).str.startswith("probe"), "reason"]
    assert len(probes) > 0
    costs = [float(re.search(r"for (-?[\d.]+) s", x).group(1)) for x in probes]  # type: ignore[union-attr]
    # a probe is another action than the belief's best, so it costs something (the best costs 0)
    assert any(c > 0.0 for c in costs), costs


def test_a_closure_human_that_cannot_be_compiled_is_refused() -> None:
    world = World("paper2015")
    with pytest.raises(CompileError, match="switching"):
        compile_human(world, "cooperative", cache=False, closure=["switching"])


def test_the_compiled_robots_states_are_built_without_a_progress_bar(capfd: pytest.CaptureFixture[str]) -> None:
    keys = robot_states(World("paper2015"))
    assert len(keys) > 0
    assert capfd.readouterr().err == ""


def test_a_table_whose_robot_waits_patiently_is_marked_as_decided_by_the_guard() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    elsewhere = state._replace(robot_at=(state.robot_at + 1) % world.table.n_locations)
    guard = ArrayProgressGuard(world)
    guard.reset_rows(np.arange(1))
    # the robot walks between two places and nothing moves: quiet 1, 2, ... from the second turn
    for t in range(PATIENCE_AFTER + 1):
        guard.apply(batch_of([state if t % 2 == 0 else elsewhere]), np.zeros(1, dtype=np.int64))
    assert bool(guard.waiting[0])
    assert bool(guard.fired[0])


def test_a_goto_to_a_place_that_is_not_an_object_names_no_object() -> None:
    for name in ("paper2015", "roboergosum"):
        world = World(name)
        n = world.n_objects
        for agent in (Agent.ROBOT, Agent.HUMAN):
            slot, remap = object_slots(world, agent)
            for a, (kind, obj, target, _) in enumerate(world.table.specs[agent]):
                if kind is Kind.GOTO and obj < 0 and target >= n:
                    assert slot[a] == -1
                    assert list(remap[a]) == [a] * n


class _Clock:
    """A clock far from 0 that advances 1 ms per reading (and records what it handed out)."""

    def __init__(self) -> None:
        self.read: list[float] = []

    def perf_counter(self) -> float:
        self.read.append(1000.0 + 0.001 * len(self.read))
        return self.read[-1]


@pytest.mark.parametrize("where", ["oracle", "headroom"])
def test_a_result_reports_the_seconds_between_its_first_and_last_readings(
    where: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    import types

    import hg_marl.agents.headroom as headroom_module
    import hg_marl.agents.oracle as oracle_module

    module = oracle_module if where == "oracle" else headroom_module
    clock = _Clock()
    monkeypatch.setattr(module, "time", types.SimpleNamespace(perf_counter=clock.perf_counter))
    if where == "oracle":
        seconds = oracle_rate("paper2015", "no_handover", cache=False).seconds
    else:
        seconds = headroom_module.headroom("paper2015", [("lazy", "lazy")]).seconds
    assert seconds == pytest.approx(clock.read[-1] - clock.read[0], abs=1e-9)
    assert seconds < 1.0


def test_an_off_model_decision_says_the_planner_was_consulted() -> None:
    empty = OracleResult(0.0, float("inf"), 0, 0, 0, 0, True, {}, {}, scenario="paper2015")
    robot = OracleRobot(empty)
    world = World("paper2015")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    robot.act(Turn(world, world.initial_state(np.random.default_rng(0)), Agent.ROBOT, {}))
    assert robot.last_decision is not None
    assert robot.last_decision.expert == "planner" and robot.last_decision.planner_consulted
