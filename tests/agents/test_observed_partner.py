"""The observed partner: its estimate worked by hand, its surprises, and the exact best response to it.

The robot-level expectations come from the oracle solved against the test's own partner
(the exact best response: an independent reference), never from the robot under test.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.base import Distribution, StationaryHuman, deterministic, first_feasible, index_of
from hg_marl.agents.humans.family_out import helpful
from hg_marl.agents.observed_partner import ObservedPartner, ObservedSolver
from hg_marl.agents.oracle import OracleRobot, oracle_rate
from hg_marl.agents.planner.space import Relabel
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import RobotError
from hg_marl.training.runner import RunConfig, run

HARD = "populations/hard_layouts.toml"


class LastFirst(StationaryHuman):
    """Clears the objects from the highest index down, touching only that one (a habit no member has).

    Holding an object: clears it as the helpful rule does. Otherwise: takes the target if it
    is offered, picks it if it can, else waits. Stationary.
    """

    name = "last_first"

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        left = [o for o in range(len(state.where)) if state.where[o] not in world.table.done[o]]
        wait = world.n_actions(Agent.HUMAN) - 1
        if not left:
            return deterministic(wait)
        target = max(left)
        if world.holding(state, Agent.HUMAN) >= 0 or (state.offer_by == int(Agent.ROBOT) and state.offer_obj == target):
            return deterministic(helpful(world, state))
        pick = first_feasible(world, state, [index_of(world, Kind.PICK, target)])
        return deterministic(pick if pick >= 0 else wait)


def _count_expansions(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """A list that gets one entry per state the observed solver expands (its one-step rule wrapped)."""
    import hg_marl.agents.observed_partner as module

    calls: list[int] = []
    real = module.expand

    def counted(*args: Any) -> Any:
        calls.append(1)
        return real(*args)

    monkeypatch.setattr(module, "expand", counted)
    return calls


def _last_first_at_the_start() -> tuple[World, ObservedPartner, Relabel, State]:
    """``forced_coordination``'s table of seed 0, and an observed partner over LastFirst that has seen nothing."""
    world = World("forced_coordination")
    partner = ObservedPartner()
    partner.base = LastFirst()
    return world, partner, Relabel(world), world.initial_state(np.random.default_rng(0))


def first_state(world: World) -> tuple[State, int, list[int]]:
    """The first table of seed 0, the robot's wait, and the human's feasible answers to it."""
    state = world.initial_state(np.random.default_rng(0))
    wait = world.n_actions(Agent.ROBOT) - 1
    mid = world.step(state, Agent.ROBOT, wait).state
    return mid, wait, world.feasible_indices(mid, Agent.HUMAN)


def test_estimate_worked_by_hand_on_a_scripted_history() -> None:
    world = World("forced_coordination")
    mid, wait, feasible = first_state(world)
    n = len(feasible)
    assert n >= 2
    a, b = feasible[0], feasible[1]
    model = ObservedPartner(weight=0.5, forget=0.8)  # no base: uniform over the feasible answers
    assert model.predict(world, mid, wait, a) == pytest.approx(1 / n)
    # One answer a: p(a) = (1 + 0.5 / n) / 1.5, any other answer (0.5 / n) / 1.5.
    model.update(world, mid, wait, a)
    assert model.predict(world, mid, wait, a) == pytest.approx((1 + 0.5 / n) / 1.5)
    assert model.predict(world, mid, wait, b) == pytest.approx((0.5 / n) / 1.5)
    # Then b: a's count forgotten to 0.8, b's 1; total 1.8 + 0.5.
    model.update(world, mid, wait, b)
    assert model.predict(world, mid, wait, a) == pytest.approx((0.8 + 0.5 / n) / 2.3)
    assert model.predict(world, mid, wait, b) == pytest.approx((1 + 0.5 / n) / 2.3)
    # Another robot action at the same state has learnt nothing; without a robot action the
    # key is the failed move's (-1), and an answer that is not feasible has probability 0.
    assert model.predict(world, mid, -1, a) == pytest.approx(1 / n)
    model.update(world, mid, -1, b)
    assert dict(model.distribution(world, mid)) == dict(model.distribution(world, mid, -1))
    assert dict(model.snapshot().distribution(world, mid)) == {b: 1.0}
    infeasible = next(h for h in range(world.n_actions(Agent.HUMAN)) if h not in feasible)
    assert model.predict(world, mid, wait, infeasible) == 0.0
    # Over a base that answers one thing: an answer the base never gives keeps its own count,
    # (1 + 0.5 * 0) / 1.5, and the base's answer gets the pseudo-count, 0.5 / 1.5.
    based = ObservedPartner()
    based.base = LastFirst()
    expected = LastFirst().distribution(world, mid, wait)[0][0]
    other = next(h for h in feasible if h != expected)
    based.update(world, mid, wait, other)
    assert dict(based.distribution(world, mid, wait)) == pytest.approx({expected: 1 / 3, other: 2 / 3})
    # The snapshot answers as the partner was seen (its counts alone) and is stationary.
    snap = dict(model.snapshot().distribution(world, mid, wait))
    assert snap == pytest.approx({a: 0.8 / 1.8, b: 1 / 1.8})


def test_a_surprise_is_an_answer_given_less_than_half_the_mass() -> None:
    world = World("forced_coordination")
    mid, wait, feasible = first_state(world)
    a, b = feasible[0], feasible[1]
    model = ObservedPartner()
    model.update(world, mid, wait, a)  # 1 / n < 0.5 under the uniform base: a surprise
    assert model.version == 1 and model.surprised[(mid, wait)] == 1
    model.update(world, mid, wait, a)  # now (1 + 0.5 / n) / 1.5 > 0.5: expected
    assert model.version == 1
    model.update(world, mid, wait, b)  # b had (0.5 / n) / 2.3: a surprise, and a contradiction
    assert model.version == 2 and model.surprised[(mid, wait)] == 2
    # Two repeats, one contradicted: under MIN_REPEATS (5), 1 >= 0.1 * 5 is not stationary.
    assert model.repeats == pytest.approx(0.98 + 1) and model.contradictions == pytest.approx(1.0)
    assert not model.stationary()
    # After a, a, b the counts are a 1.8 * 0.8 = 1.44 and b 1: a again has 1.44 of 2.44, over
    # half, not contradicted. The counts are then a 2.152 and b 0.8: b has 0.8 of 2.952, under
    # half, contradicted.
    model.update(world, mid, wait, a)
    assert model.contradictions == pytest.approx(0.98 * 1.0)
    model.update(world, mid, wait, b)
    assert model.contradictions == pytest.approx(0.98 * 0.98 + 1.0)
    # Exactly half the earlier answers is not a contradiction: never forgetting, a then b
    # (contradicted) then a again, which has 1 of 2.
    even = ObservedPartner(forget=1.0)
    for answer in (a, b, a):
        even.update(world, mid, wait, answer)
    assert even.contradictions == pytest.approx(0.98)
    # The threshold: under 10% of the repeats, counted as at least 5.
    model.repeats, model.contradictions = 1.0, 0.49
    assert model.stationary()
    model.contradictions = 0.5
    assert not model.stationary()
    model.repeats, model.contradictions = 20.0, 1.99
    assert model.stationary()
    model.reset()
    assert model.stationary() and model.version == 0 and not model.counts


def test_bad_settings_are_refused() -> None:
    for kwargs in (
        {"weight": 0.0},
        {"weight": -1.0},
        {"weight": float("nan")},
        {"forget": 0.0},
        {"forget": -0.5},
        {"forget": 1.5},
    ):
        with pytest.raises(ValueError, match="observed partner"):
            ObservedPartner(**kwargs)
    assert ObservedPartner(forget=1.0).forget == 1.0  # never forget: allowed
    with pytest.raises(RobotError, match=r"belief\.open_world: expected one of uniform, learned, observed"):
        make_robot("belief", population=HARD, open_world="seen")


def test_the_solver_solves_again_only_after_a_surprise_at_the_state() -> None:
    world = World("forced_coordination")
    partner = ObservedPartner()
    partner.base = LastFirst()
    solver = ObservedSolver()
    relabel = Relabel(world)
    state = world.initial_state(np.random.default_rng(0))
    q, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
    assert solver.solves == 1 and solved and expanded > 0 and q
    # No new answer: the same solution, nothing solved, the same values.
    again, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
    assert (again, expanded, solved, solver.solves) == (q, 0, False, 1)
    # An expected answer (the base's) to the robot's other move is no surprise: still no solve.
    wait = world.n_actions(Agent.ROBOT) - 1
    other = next(a for a in world.feasible_indices(state, Agent.ROBOT) if a != wait)
    mid_other = world.step(state, Agent.ROBOT, other).state
    partner.update(world, mid_other, other, LastFirst().distribution(world, mid_other, other)[0][0])
    assert partner.version == 0
    solver.q_values(world, state, partner, 0, relabel)
    assert solver.solves == 1
    # A surprise at another state's answer changes the model but not this decision: no solve
    # here (it is used when the table gets there).
    far = world.step(mid_other, Agent.HUMAN, LastFirst().distribution(world, mid_other, other)[0][0]).state
    far_mid = world.step(far, Agent.ROBOT, wait).state
    expected_far = LastFirst().distribution(world, far_mid, wait)[0][0]
    partner.update(
        world, far_mid, wait, next(h for h in world.feasible_indices(far_mid, Agent.HUMAN) if h != expected_far)
    )
    assert partner.version == 1
    _, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
    assert (solver.solves, expanded, solved) == (1, 0, False)
    # A surprise at the robot's wait (the partner waits where the base acts) is solved for at once.
    mid = world.step(state, Agent.ROBOT, wait).state
    human_wait = world.n_actions(Agent.HUMAN) - 1
    assert mid != far_mid and LastFirst().distribution(world, mid, wait)[0][0] != human_wait
    partner.update(world, mid, wait, human_wait)
    assert partner.version == 2
    _, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
    assert solver.solves == 2 and solved and expanded > 0
    # Solved without failed actions: where the partner waits after the robot's wait but the base
    # acts after a failed move (never seen), a failed move would "work" in the model; the
    # model holds only feasible moves, at every state of it.
    assert solver.result is not None and solver.graph
    assert all([a for a, _ in options] == world.feasible_indices(s, Agent.ROBOT) for s, options in solver.graph.items())
    # The size limit: a base whose own model has 20,000 states is solved for, one more is not.
    assert ObservedSolver().max_states == 20_000
    assert solver.q_values(world, state, partner, 20_000, relabel)[0]
    assert solver.q_values(world, state, partner, 20_001, relabel) == ({}, 0, False)
    # A model that grows past the limit while it is built is refused the same way (the states
    # expanded before it was refused are charged).
    small = ObservedSolver(max_states=5)
    q, expanded, solved = small.q_values(world, state, partner, 0, relabel)
    assert (q, solved, small.solves) == ({}, True, 0) and 0 < expanded <= 5


def test_the_exact_best_response_to_a_partner_no_member_explains() -> None:
    """Against LastFirst on forced_coordination the oracle (the exact best response, solved
    against the partner itself) sets the reference; the observed robot reaches it, the
    closed-world belief robot (a member's best response) does not."""
    config = RunConfig(scenario="forced_coordination", duration=1100.0, seed=0)
    reference = run(OracleRobot(oracle_rate("forced_coordination", LastFirst(), cache=False)), LastFirst(), config)
    best = reference.summary["tasks_solved"]
    observed = run(make_robot("belief", population=HARD, open_world="observed"), LastFirst(), config)
    closed = run(make_robot("belief", population=HARD), LastFirst(), config)
    assert observed.summary["tasks_solved"] >= best - 1
    assert closed.summary["tasks_solved"] <= best - 3
    reasons = observed.log["reason"].astype(str)
    assert reasons.str.startswith("no member explains the partner: the exact best response").any()


def test_each_solve_is_charged_as_a_planner_call_of_one_node_per_state_expanded(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The clock pays for every solve (``planner_base + planner_per_node * states expanded``,
    the cost model's own constants), and the decisions that read a kept solution pay nothing."""
    sizes: list[int] = []
    real = ObservedSolver._solve

    def counted(self: ObservedSolver, *args: Any) -> Any:
        before = self.expanded
        result = real(self, *args)
        sizes.append(self.expanded - before)
        return result

    monkeypatch.setattr(ObservedSolver, "_solve", counted)
    robot = make_robot("belief", population=HARD, open_world="observed")
    log = run(robot, LastFirst(), RunConfig(scenario="forced_coordination", duration=300.0, seed=0)).log
    exact = log[log["reason"].astype(str).str.startswith("no member explains the partner: the exact")]
    assert sizes and len(exact) > len(sizes)
    cost = robot.cost
    assert exact["decision_time"].sum() == pytest.approx(
        sum(cost.planner_base + cost.planner_per_node * n for n in sizes)
    )
    assert (exact["decision_time"] == 0.0).sum() == len(exact) - len(sizes)


def test_a_failed_robot_move_is_counted_as_the_partner_saw_it_failed() -> None:
    """What the partner answered after a failed robot move is kept under the move -1 (what the
    partner sees: nothing done), not under the move the robot tried."""
    from hg_marl.policy import Turn

    world = World("forced_coordination")
    robot = make_robot("belief", population=HARD, open_world="observed")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    tried = next(a for a in range(world.n_actions(Agent.ROBOT)) if a not in world.feasible_indices(state, Agent.ROBOT))
    step = world.step(state, Agent.ROBOT, tried)
    assert not step.ok
    answer = world.feasible_indices(step.state, Agent.HUMAN)[0]
    after = world.step(step.state, Agent.HUMAN, answer).state
    robot._prev = (state, tried)
    robot._observe(Turn(world, after, Agent.ROBOT, {}, last_actions=(tried, answer)))
    partner = robot.posterior.learned
    assert isinstance(partner, ObservedPartner)
    assert set(partner.counts) == {(step.state, -1)} and partner.counts[(step.state, -1)] == {answer: 1.0}


def test_the_kept_solutions_are_dropped_once_they_reach_256() -> None:
    """``MAX_TABLES`` = 256: a solve with 255 kept adds the 256th; with 256 kept, they are
    dropped first and the new one is the only one left."""
    world, partner, relabel, state = _last_first_at_the_start()
    for kept, after in ((255, 256), (256, 1)):
        solver = ObservedSolver()
        dummy = State(where=(-1,) * 3, robot_at=0, offer_by=-1, offer_obj=-1)
        solver.tables = {dummy._replace(robot_at=k): (0, None) for k in range(kept)}
        solver.q_values(world, state, partner, 0, relabel)
        assert len(solver.tables) == after and state in solver.tables


def test_a_table_dealt_again_under_the_same_model_is_not_solved_again() -> None:
    """Two tables of ``paper2015`` (seeds 0 and 1), each solved from itself; the first dealt
    again reads its kept solution (no solve); after a surprise the model changed, and the
    second dealt again is solved again."""
    world = World("paper2015")
    partner = ObservedPartner()
    partner.base = LastFirst()
    relabel = Relabel(world)
    first, second = (world.initial_state(np.random.default_rng(seed)) for seed in (0, 1))
    solver = ObservedSolver()
    solver.q_values(world, first, partner, 0, relabel)
    assert solver.result is not None and second not in solver.result.values
    solver.q_values(world, second, partner, 0, relabel)
    assert solver.solves == 2
    q_first, expanded, solved = solver.q_values(world, first, partner, 0, relabel)
    assert (solver.solves, expanded, solved) == (2, 0, False) and q_first
    wait = world.n_actions(Agent.ROBOT) - 1
    mid = world.step(first, Agent.ROBOT, wait).state
    expected = LastFirst().distribution(world, mid, wait)[0][0]
    partner.update(world, mid, wait, next(h for h in world.feasible_indices(mid, Agent.HUMAN) if h != expected))
    assert partner.version == 1
    _, _, solved = solver.q_values(world, second, partner, 0, relabel)
    assert solver.solves == 3 and solved


def test_a_table_over_the_limit_is_not_tried_again_under_the_same_model(monkeypatch: pytest.MonkeyPatch) -> None:
    """An over-the-limit model is remembered by table and version: the next decision there asks
    no solve, and a surprise (a new model) tries again."""
    calls: list[int] = []
    real = ObservedSolver._solve

    def counted(self: ObservedSolver, *args: Any) -> Any:
        calls.append(1)
        return real(self, *args)

    monkeypatch.setattr(ObservedSolver, "_solve", counted)
    world, partner, relabel, state = _last_first_at_the_start()
    small = ObservedSolver(max_states=5)
    q, expanded, solved = small.q_values(world, state, partner, 0, relabel)
    assert (q, solved) == ({}, True) and 0 < expanded <= 5
    assert small.q_values(world, state, partner, 0, relabel) == ({}, 0, False)
    assert len(calls) == 1
    wait = world.n_actions(Agent.ROBOT) - 1
    mid = world.step(state, Agent.ROBOT, wait).state
    partner.update(world, mid, wait, world.n_actions(Agent.HUMAN) - 1)  # the base picks there: a surprise
    assert partner.version == 1
    assert small.q_values(world, state, partner, 0, relabel)[0] == {}
    assert len(calls) == 2


@pytest.mark.parametrize("scenario", ["forced_coordination", "asymmetric_advantages"])
def test_solves_over_kept_expansions_equal_the_oracle_solved_afresh(scenario: str) -> None:
    """After a history of answers (random moves, random answers: surprises everywhere), every
    solve over the kept expansions gives each of its states the value the oracle gives it,
    solved afresh from the same root against a snapshot of the partner (an independent path:
    the array builder and its own answer table)."""
    world = World(scenario)
    partner = ObservedPartner()
    partner.base = LastFirst()
    solver = ObservedSolver()
    rng = np.random.default_rng(3)
    relabel = Relabel(world)
    state = world.initial_state(rng)
    checked = 0
    for _ in range(120):
        _, _, solved = solver.q_values(world, state, partner, 0, relabel)
        if solved:
            assert solver.result is not None
            ref = oracle_rate(
                world, partner.snapshot(), failed_actions=False, max_seconds=None, roots=(state,), cache=False
            )
            for s, v in solver.result.values.items():
                assert v == pytest.approx(ref.value_at(world, s), rel=1e-9, abs=1e-9)
            checked += 1
        a = int(rng.choice(world.feasible_indices(state, Agent.ROBOT)))
        mid = world.step(state, Agent.ROBOT, a).state
        h = int(rng.choice(world.feasible_indices(mid, Agent.HUMAN)))
        partner.update(world, mid, a, h)
        state = world.step(mid, Agent.HUMAN, h).state
    assert checked >= 2 and solver.solves == checked


def test_a_solve_expands_only_the_states_new_to_it_and_those_that_read_a_counted_answer() -> None:
    """A surprise at the root's wait: the second solve expands the kept states that read that
    key (worked out here from the rules: those whose wait leads to the same mid-cycle state)
    and the states the first solve did not hold, nothing else."""
    world, partner, relabel, state = _last_first_at_the_start()
    solver = ObservedSolver()
    _, first_expanded, _ = solver.q_values(world, state, partner, 0, relabel)
    assert solver.result is not None
    first = set(solver.result.values)
    assert first_expanded == len(first)  # nothing kept yet: every state expanded
    wait = world.n_actions(Agent.ROBOT) - 1
    mid = world.step(state, Agent.ROBOT, wait).state
    partner.update(world, mid, wait, world.n_actions(Agent.HUMAN) - 1)  # the base picks there: a surprise
    _, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
    assert solved and solver.result is not None
    second = set(solver.result.values)
    readers = {
        s
        for s in first & second
        if any(
            world.table.successor(s, Agent.ROBOT, a)[0] == mid and a == wait
            for a in world.feasible_indices(s, Agent.ROBOT)
        )
    }
    assert state in readers
    assert expanded == len(readers) + len(second - first)
    assert expanded < len(second)
    # A surprise at the answer to another move of the root: its readers and the new states
    # are expanded, not those of the earlier key again (counted before the last solve).
    other = next(a for a in world.feasible_indices(state, Agent.ROBOT) if a != wait)
    mid_other = world.step(state, Agent.ROBOT, other).state
    expected = LastFirst().distribution(world, mid_other, other)[0][0]
    surprise = next(h for h in world.feasible_indices(mid_other, Agent.HUMAN) if h != expected)
    partner.update(world, mid_other, other, surprise)
    _, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
    assert solved and solver.result is not None
    third = set(solver.result.values)
    readers = {
        s
        for s in second & third
        if other in world.feasible_indices(s, Agent.ROBOT)
        and world.table.successor(s, Agent.ROBOT, other)[0] == mid_other
    }
    assert state in readers
    assert expanded == len(readers) + len(third - second)


def test_a_new_base_member_expands_every_state_again() -> None:
    """The base answers wherever the partner was never seen: a new base changes every such
    answer, so the kept expansions are dropped and the next solve expands all its states."""
    world, partner, relabel, state = _last_first_at_the_start()
    solver = ObservedSolver()
    solver.q_values(world, state, partner, 0, relabel)
    wait = world.n_actions(Agent.ROBOT) - 1
    mid = world.step(state, Agent.ROBOT, wait).state
    partner.update(world, mid, wait, world.n_actions(Agent.HUMAN) - 1)
    partner.base = helpful_partner = LastFirst()  # another object: another member
    assert helpful_partner is not solver.base
    _, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
    assert solved and solver.result is not None and expanded == solver.result.n_states


def test_a_refused_solve_reports_the_states_it_expanded(monkeypatch: pytest.MonkeyPatch) -> None:
    """A model that grows past the limit is charged the expansions made before it was refused,
    counted here by wrapping the one-step rule (each call is one state expanded), on a first
    solve and on a second one after a surprise (the count is per solve, not per run)."""
    calls = _count_expansions(monkeypatch)
    world, partner, relabel, state = _last_first_at_the_start()
    small = ObservedSolver(max_states=5)
    q, expanded, solved = small.q_values(world, state, partner, 0, relabel)
    assert (q, solved) == ({}, True) and expanded == len(calls) > 1
    wait = world.n_actions(Agent.ROBOT) - 1
    mid = world.step(state, Agent.ROBOT, wait).state
    partner.update(world, mid, wait, world.n_actions(Agent.HUMAN) - 1)  # a surprise: tried again
    before = len(calls)
    q, expanded, solved = small.q_values(world, state, partner, 0, relabel)
    assert (q, solved) == ({}, True) and expanded == len(calls) - before > 0


def test_the_kept_expansions_are_dropped_once_they_reach_the_states_limit() -> None:
    """``max_states`` kept expansions (here 1,000 of states no table reaches) are dropped before
    the next solve, which then expands every state of its model; 999 are kept."""
    world = World("forced_coordination")
    relabel = Relabel(world)
    state = world.initial_state(np.random.default_rng(0))
    for kept, dropped in ((1000, True), (999, False)):
        partner = ObservedPartner()
        partner.base = LastFirst()
        solver = ObservedSolver(max_states=1000)
        solver.base = partner.base
        dummy = State(where=(-1,) * 3, robot_at=0, offer_by=-1, offer_obj=-1)
        filler: dict[State, list[Any]] = {dummy._replace(robot_at=k): [] for k in range(kept)}
        solver.graph = dict(filler)
        _, expanded, solved = solver.q_values(world, state, partner, 0, relabel)
        assert solved and solver.result is not None
        assert expanded == solver.result.n_states
        assert (not set(filler) & set(solver.graph)) is dropped


def test_a_model_over_a_large_limit_is_refused_while_it_is_built() -> None:
    """Against a partner answering uniformly (no base), a table of ``asymmetric_advantages``
    reaches thousands of states: with a limit of 300 the solve is refused once its model holds
    300 states (at most 300 expanded, no move)."""
    world = World("asymmetric_advantages")
    partner = ObservedPartner()
    state = world.initial_state(np.random.default_rng(0))
    solver = ObservedSolver(max_states=300)
    q, expanded, solved = solver.q_values(world, state, partner, 0, Relabel(world))
    assert (q, solved, solver.solves) == ({}, True, 0) and 0 < expanded <= 300


def test_expansions_are_kept_when_nothing_was_counted_since_the_last_solve() -> None:
    """An answer counted before a solve is used by that solve; a solve from another table with
    nothing counted since expands that table's states only and keeps the first table's."""
    world = World("paper2015")
    partner = ObservedPartner()
    partner.base = LastFirst()
    relabel = Relabel(world)
    first, second = (world.initial_state(np.random.default_rng(seed)) for seed in (0, 1))
    wait = world.n_actions(Agent.ROBOT) - 1
    mid = world.step(first, Agent.ROBOT, wait).state
    partner.update(world, mid, wait, world.n_actions(Agent.HUMAN) - 1)
    solver = ObservedSolver()
    solver.q_values(world, first, partner, 0, relabel)
    assert solver.result is not None
    kept = set(solver.result.values)
    assert second not in kept
    _, expanded, solved = solver.q_values(world, second, partner, 0, relabel)
    assert solved and solver.result is not None
    assert expanded == len(set(solver.result.values) - kept)
    assert kept <= set(solver.graph)


def test_a_refused_solve_after_a_kept_one_is_charged_its_own_expansions_only(monkeypatch: pytest.MonkeyPatch) -> None:
    """``paper2015`` with a limit of 70 states: the table of seed 0 (67 states) is solved, the
    table of seed 1 (111) is refused. The refused solve reports the states it expanded itself,
    counted by wrapping the one-step rule, not the run's total nor any other mix of the two."""
    calls = _count_expansions(monkeypatch)
    world = World("paper2015")
    partner = ObservedPartner()
    partner.base = LastFirst()
    relabel = Relabel(world)
    first, second = (world.initial_state(np.random.default_rng(seed)) for seed in (0, 1))
    solver = ObservedSolver(max_states=70)
    q, expanded, solved = solver.q_values(world, first, partner, 0, relabel)
    assert q and solved and expanded == len(calls) == 67
    q, expanded, solved = solver.q_values(world, second, partner, 0, relabel)
    assert (q, solved) == ({}, True)
    assert expanded == len(calls) - 67 > 0
