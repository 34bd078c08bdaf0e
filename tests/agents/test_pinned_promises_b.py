"""Pins promises of the model builder, its answer table, chains, the oracle, the progress guard
and the live answers in forked workers that no other test checked: each expected value is worked
by hand from the rule a docstring states (a robot's options are its feasible actions in index
order, then its first infeasible one; the re-draw lasts the longer of the robot's wait and the
partner's first answer; a policy's seconds per task include the re-draw's; ``W`` doubles up to
320), computed from a simpler reference in the scalar world (``World.step``,
``feasible_indices``, ``Relabel.canonical``, a human's own ``distribution``), or is a property
(a cached result reads back as the computed one; a reset starts its counters afresh; a worker
is forked with the collector frozen).
"""

from __future__ import annotations

import gc
import math
import multiprocessing
import os
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest
from scipy import sparse

import hg_marl.agents.models.forked as forked
import hg_marl.agents.models.live as live
from hg_marl.agents.humans import make_human
from hg_marl.agents.models import AnswerTable, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.builder import Dynamics, Model
from hg_marl.agents.models.chains import backward, forward, policy_rate, transitions
from hg_marl.agents.models.forked import Forked
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.partners import batch_answers
from hg_marl.agents.oracle import OracleResult, OracleRobot, oracle_rate
from hg_marl.agents.progress import ArrayProgressGuard, ProgressGuard, guard_option
from hg_marl.core import Agent, Durations, State, World
from hg_marl.core.relabel import Relabel
from hg_marl.envs.batched import BatchState
from hg_marl.policy import Turn
from tests.agents.test_pinned_model_answers_gate import RecordingBudget
from tests.agents.test_progress import batch_of

PAPER = World("paper2015")
ROBOT_WAIT = PAPER.n_actions(Agent.ROBOT) - 1
HUMAN_WAIT = PAPER.n_actions(Agent.HUMAN) - 1
K = 12
"""The progress guard's ``K`` as ``agents/progress.py`` states it."""


def _layout_keys(world: World, packer: StatePacker, count: int | None = None) -> np.ndarray:
    """The distinct sorted mid-cycle keys (nothing seen) of the first ``count`` layouts."""
    states = [s for s, _ in layout_distribution(world)][:count]
    return np.unique(packer.pack(BatchState.of(states), np.full(len(states), -1)))


class Recording(RecordingBudget):
    """The gate's recording budget, its readings as (phase, done, total, unit, states)."""

    def seen(self) -> list[tuple[str, int, int | None, str, int | None]]:
        return [(*r[:4], n) for r, n in zip(self.readings, self.states, strict=True)]


# --- agents/models/answers.py -------------------------------------------------------------


class _Stub:
    """A stationary human that records its resets and always waits."""

    name = "stub"

    def __init__(self) -> None:
        self.resets: list[tuple[World, Agent]] = []

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.resets.append((world, agent))

    def distribution(self, world: World, state: State, seen: int = -1) -> list[tuple[int, float]]:
        return [(world.n_actions(Agent.HUMAN) - 1, 1.0)]


def test_a_human_given_as_an_instance_is_that_instance_reset_in_the_human_seat() -> None:
    stub = _Stub()
    assert stationary_human(stub, PAPER) is stub  # "an instance is used as it is"
    assert stub.resets == [(PAPER, Agent.HUMAN)]  # "... and reset"


def test_known_keys_asked_again_read_no_budget_on_arrays() -> None:
    # a random human has an array form: one reading per ensure that has keys to answer, none otherwise
    packer = StatePacker(PAPER)
    budget = Recording()
    table = AnswerTable(PAPER, stationary_human("random", PAPER), packer, budget=budget)
    assert table.batch is not None
    keys = _layout_keys(PAPER, packer)
    table.ensure(keys)
    table.ensure(keys)  # every key known: nothing to answer, nothing to read
    table.ensure(keys[:3])
    assert budget.seen() == [("answers", 0, len(keys), "partner answers on arrays", None)]


def test_answers_given_on_arrays_serve_a_table_without_a_human() -> None:
    # the random human's rule: uniform over the human's feasible actions (by hand from the world)
    packer = StatePacker(PAPER)
    uniform = batch_answers(PAPER, stationary_human("random", PAPER))
    table = AnswerTable(PAPER, None, packer, batch=uniform)
    keys = _layout_keys(PAPER, packer)
    table.ensure(keys)
    assert table.live_calls == 0
    start, size = table.lookup(keys)
    states, _ = packer.unpack(keys)
    for i in range(len(keys)):
        feasible = PAPER.feasible_indices(states.state(i), Agent.HUMAN)
        at = slice(int(start[i]), int(start[i] + size[i]))
        assert table.entries["actions"][at].tolist() == feasible
        assert table.entries["probs"][at].tolist() == [1.0 / len(feasible)] * len(feasible)


@pytest.mark.parametrize("relabelled", [None, False])
def test_entries_carry_their_next_states_canonical_key_unless_told_not_to(relabelled: bool | None) -> None:
    # None (a fresh table): the next state's key in Relabel.canonical's labelling; False: the key as is
    packer = StatePacker(PAPER)
    table = AnswerTable(PAPER, stationary_human("lazy", PAPER), packer, arrays=False)
    table.relabelled = relabelled
    table.ensure(_layout_keys(PAPER, packer))
    nxt = table.entries["next"]
    relabel = Relabel(PAPER)
    b, _ = packer.unpack(nxt)
    canonical = packer.pack(BatchState.of([relabel.canonical(b.state(i))[0] for i in range(len(b))]))
    assert (canonical != nxt).any()  # some next states are not in canonical order: the cases differ
    want = canonical if relabelled is None else nxt
    assert table.entries["canonical"].tolist() == want.tolist()


# --- agents/models/builder.py -------------------------------------------------------------


@pytest.fixture(scope="module")
def lazy_model() -> Model:
    """paper2015 against the lazy human, full model, failed actions included."""
    table = AnswerTable(PAPER, stationary_human("lazy", PAPER), StatePacker(PAPER))
    return build_model(PAPER, table, layout_distribution(PAPER))


@pytest.mark.parametrize("failed_actions", [True, False])
def test_a_states_options_are_its_feasible_actions_in_index_order_then_its_first_failed_one(
    lazy_model: Model, failed_actions: bool
) -> None:
    model = lazy_model
    if not failed_actions:
        table = AnswerTable(PAPER, stationary_human("lazy", PAPER), StatePacker(PAPER))
        model = build_model(PAPER, table, layout_distribution(PAPER), failed_actions=False)
    n = PAPER.n_actions(Agent.ROBOT)
    for s, state in enumerate(model.states()):
        feasible = PAPER.feasible_indices(state, Agent.ROBOT)
        infeasible = [a for a in range(n) if a not in feasible]
        want = sorted(feasible) + (infeasible[:1] if failed_actions else [])
        got = model.pair_action[model.pair_start[s] : model.pair_start[s + 1]].tolist()
        assert got == want, state


def test_only_the_wait_on_a_clean_table_is_terminal_and_every_other_pair_sums_to_one(lazy_model: Model) -> None:
    model = lazy_model
    state_of = model.pair_state()
    states = model.states()
    clean = np.array([PAPER.is_clean(states[s]) for s in state_of])
    want = clean & (model.pair_action == ROBOT_WAIT)
    assert want.any() and model.pair_terminal.tolist() == want.tolist()
    rows = np.asarray(model.transitions().sum(axis=1)).ravel()
    assert model.transitions().shape == (model.n_pairs, model.n)
    # a terminal pair's transitions are the re-draw's, kept apart: its row is empty
    np.testing.assert_allclose(rows, np.where(want, 0.0, 1.0), rtol=0.0, atol=1e-12)
    assert model.t_pair().tolist() == np.repeat(np.arange(model.n_pairs), np.diff(model.t_start)).tolist()


class _SeesTheWait:
    """Answers as the lazy human only when it saw the robot's wait; otherwise it waits."""

    name = "sees_the_wait"
    uses_robot_action = True

    def __init__(self, world: World) -> None:
        self.inner = stationary_human("lazy", world)

    def distribution(self, world: World, state: State, seen: int = -1) -> list[tuple[int, float]]:
        if seen == world.n_actions(Agent.ROBOT) - 1:
            return list(self.inner.distribution(world, state, -1))
        return [(world.n_actions(Agent.HUMAN) - 1, 1.0)]


@pytest.mark.parametrize("wait_seconds", [1.0, 5.0])
@pytest.mark.parametrize("human", ["lazy", "sees_the_wait"])
def test_the_redraw_is_each_table_times_the_first_answer_to_the_robots_wait(human: str, wait_seconds: float) -> None:
    # By hand from the rule: layout s (probability q), the partner's answer h (p) to the robot's
    # wait gives the next state world.step(s, h), probability q * p, seconds max(wait, d_h).
    # wait = 1 s: a pick (2 s) outlasts it; wait = 5 s: it outlasts the pick.
    world = World("paper2015", Durations(wait=wait_seconds))
    partner = stationary_human("lazy", world) if human == "lazy" else _SeesTheWait(world)
    packer = StatePacker(world)
    model = build_model(world, AnswerTable(world, partner, packer), layout_distribution(world))
    wait = world.n_actions(Agent.ROBOT) - 1
    want = []
    for s, q in layout_distribution(world):
        for h, p in partner.distribution(world, s, wait):
            out = world.step(s, Agent.HUMAN, h)
            want.append((packer.pack_one(out.state), q * p, max(wait_seconds, out.duration)))
    regen = (model.keys[model.regen_next].tolist(), model.regen_prob.tolist(), model.regen_tau.tolist())
    got = list(zip(*regen, strict=True))
    assert len(got) == len(want)
    for (gk, gp, gt), (wk, wp, wt) in zip(sorted(got), sorted(want), strict=True):
        assert (gk, gt) == (wk, wt) and gp == pytest.approx(wp, rel=1e-12)
    assert {t for _, _, t in want} == ({1.0, 2.0} if wait_seconds == 1.0 else {5.0})


def test_a_model_read_for_another_partner_reads_that_partners_arrays() -> None:
    packer = StatePacker(PAPER)
    tables = [AnswerTable(PAPER, stationary_human(h, PAPER), packer) for h in ("lazy", "no_handover")]
    model = build_model(PAPER, tables, layout_distribution(PAPER))
    other = model.of(1)
    assert model.partner == 0 and other.partner == 1 and other.keys is model.keys  # arrays shared
    assert len(model.dynamics[0].t_next) != len(model.dynamics[1].t_next)  # the partners differ
    for name in ("t_start", "t_next", "t_prob", "t_tau", "regen_next", "regen_prob", "regen_tau"):
        assert getattr(model, name) is getattr(model.dynamics[0], name), name
        assert getattr(other, name) is getattr(model.dynamics[1], name), name
    assert model.chain(1) is model.dynamics[1]
    assert [a is b for a, b in zip(model.regen(1), other.regen(1), strict=True)] == [True] * 3
    assert model.regen(1)[0] is model.dynamics[1].regen_next


def test_an_empty_table_takes_the_models_labelling_and_a_computed_one_serves_either() -> None:
    # an empty table is marked as the model it first serves; one filled with computed
    # canonical keys (relabelled None) may serve a reduced model
    from hg_marl.agents.models.layouts import canonical_layouts

    packer = StatePacker(PAPER)
    fresh = AnswerTable(PAPER, stationary_human("cooperative", PAPER), packer)
    build_model(PAPER, fresh, canonical_layouts(PAPER), canonical=True)
    assert fresh.relabelled is True
    filled = AnswerTable(PAPER, stationary_human("cooperative", PAPER), packer)
    filled.ensure(_layout_keys(PAPER, packer))
    assert filled.relabelled is None and len(filled.keys) > 0
    reduced = build_model(PAPER, filled, canonical_layouts(PAPER), canonical=True)
    assert reduced.n == build_model(PAPER, fresh, canonical_layouts(PAPER), canonical=True).n


def test_the_partners_answers_are_read_in_the_first_answers_phase_then_in_the_exploration() -> None:
    # lazy is asked live: a reading before every fourth answer, in the table's phase
    budget = Recording()
    table = AnswerTable(PAPER, stationary_human("lazy", PAPER), StatePacker(PAPER), budget)
    model = build_model(PAPER, table, layout_distribution(PAPER), budget=budget)
    phases = [r[0] for r in budget.readings]
    first = phases.index("explore")
    assert first > 0 and set(phases[:first]) == {"first answers"}
    assert set(phases[first:]) == {"explore", "explore: partner answers"}
    assert "explore: partner answers" in phases
    # the last reading: every state explored, the states budget counting the states known
    assert budget.seen()[-1] == ("explore", model.n, None, "states explored", model.n)


# --- agents/models/chains.py --------------------------------------------------------------


def _chain(rows: list[list[tuple[int, float, float]]], regen: list[tuple[int, float, float]]) -> Dynamics:
    """One row per pair: ``(next state, probability, seconds)`` each; the re-draw likewise."""
    t_start = np.concatenate([[0], np.cumsum([len(r) for r in rows])]).astype(np.int64)
    flat = [t for row in rows for t in row]
    return Dynamics(
        t_start=t_start,
        t_next=np.array([s for s, _, _ in flat], dtype=np.int64),
        t_prob=np.array([p for _, p, _ in flat], dtype=np.float64),
        t_tau=np.array([t for _, _, t in flat], dtype=np.float64),
        regen_next=np.array([s for s, _, _ in regen], dtype=np.int64),
        regen_prob=np.array([p for _, p, _ in regen], dtype=np.float64),
        regen_tau=np.array([t for _, _, t in regen], dtype=np.float64),
    )


def test_transitions_are_the_probabilities_by_default_and_the_weights_given() -> None:
    chain = _chain([[(0, 1.0, 2.0)], [(0, 0.5, 3.0), (2, 0.5, 4.0)], [(2, 1.0, 5.0)]], [])
    assert transitions(chain, 3).toarray().tolist() == [[1.0, 0.0, 0.0], [0.5, 0.0, 0.5], [0.0, 0.0, 1.0]]
    seconds = transitions(chain, 3, chain.t_tau).toarray()
    assert seconds.tolist() == [[2.0, 0.0, 0.0], [3.0, 0.0, 4.0], [0.0, 0.0, 5.0]]


def test_forward_includes_the_seeds_and_backward_finds_every_state_that_reaches_one() -> None:
    # edges 0 -> 1, 1 -> 2, 3 -> 0; state 4 alone
    graph = sparse.csr_matrix((np.ones(3), ([0, 1, 3], [1, 2, 0])), shape=(5, 5))
    assert forward(graph, np.array([0, 0])).tolist() == [True, True, True, False, False]
    assert forward(graph, np.array([4])).tolist() == [False, False, False, False, True]
    assert not forward(graph, np.zeros(0, dtype=np.int64)).any()  # no seed: nothing reached
    assert backward(graph, np.array([True, False, False, False, False])).tolist() == [True, False, False, True, False]
    assert backward(graph, np.array([False, False, True, False, False])).tolist() == [True, True, True, True, False]
    assert not backward(graph, np.zeros(5, dtype=bool)).any()


def _one_step_policy(done_loop: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """State 0 goes to state 1 in 1 s; state 1 completes (with a 100 s pair back to 0 if ``done_loop``)."""
    if done_loop:
        return np.array([0, 1, 2]), np.array([1, 0]), np.array([1.0, 1.0]), np.array([1.0, 100.0])
    return np.array([0, 1, 1]), np.array([1]), np.array([1.0]), np.array([1.0])


def test_a_policys_rate_counts_the_redraws_seconds_weighted_by_its_probabilities() -> None:
    # re-draw: state 0 (p 0.25, 2 s) or straight onto the completing state 1 (p 0.75, 4 s):
    # 0.25 * (2 + 1) + 0.75 * (4 + 0) = 3.75 s per task, 3,600 / 3.75 = 960 per hour
    chain = _chain([], [(0, 0.25, 2.0), (1, 0.75, 4.0)])
    done = np.array([False, True])
    assert policy_rate(chain, done, _one_step_policy(False)) == pytest.approx(960.0, rel=1e-12)


def test_a_completing_states_own_transitions_are_not_part_of_the_cycle() -> None:
    # the completing pair is followed by the re-draw: a transition listed at the done state is
    # never taken, so the rate is the same (re-draw to state 0 in 2 s: 2 + 1 = 3 s, 1,200 per hour)
    chain = _chain([], [(0, 1.0, 2.0)])
    done = np.array([False, True])
    for loop in (False, True):
        assert policy_rate(chain, done, _one_step_policy(loop)) == pytest.approx(1200.0, rel=1e-12), loop


# --- agents/oracle.py ---------------------------------------------------------------------


def test_a_human_given_as_an_instance_is_never_cached(tmp_path: Path) -> None:
    result = oracle_rate(PAPER, make_human("no_handover"), cache=tmp_path)
    assert result.rate_per_hour > 0.0 and result.human == "no_handover"
    assert [p for p in tmp_path.rglob("*") if p.is_file()] == []
    oracle_rate(PAPER, "no_handover", cache=tmp_path)  # the same human by its spec is
    assert len(list(tmp_path.glob("paper2015-*.npz"))) == 1


def test_a_cached_result_reads_back_its_flags_and_figures(tmp_path: Path) -> None:
    # three sweeps cannot meet 1e-9 s on this model: converged False beside reduced True,
    # so a read-back that mixed up the two flags shows
    options: dict[str, Any] = {"max_iterations": 3}
    fresh = oracle_rate(PAPER, "cooperative", cache=False, **options)
    assert fresh.reduced and not fresh.converged and fresh.iterations == 3
    oracle_rate(PAPER, "cooperative", cache=tmp_path, **options)
    cached = oracle_rate(PAPER, "cooperative", cache=tmp_path, **options)
    fields = ("rate_per_hour", "seconds_per_task", "n_states", "n_transitions", "n_layouts", "iterations")
    assert [getattr(cached, f) for f in fields] == [getattr(fresh, f) for f in fields]
    assert (cached.converged, cached.reduced, cached.scenario, cached.human) == (
        False,
        True,
        "paper2015",
        "cooperative",
    )
    state = next(s for s in fresh.policy if Relabel(PAPER).canonical(s)[0] == s)
    assert cached.action_at(PAPER, state) == fresh.action_at(PAPER, state)


@pytest.mark.parametrize("reduced", [False, True])
def test_off_its_model_a_result_has_no_action_and_infinite_seconds(reduced: bool) -> None:
    state = PAPER.initial_state(np.random.default_rng(0))
    empty = OracleResult(0.0, math.inf, 0, 0, 0, 0, True, {}, {}, scenario="paper2015", reduced=reduced)
    assert empty.action_at(PAPER, state) is None
    assert empty.value_at(PAPER, state) == math.inf


def test_the_oracle_robot_plays_the_robot_seat_only() -> None:
    empty = OracleResult(0.0, math.inf, 0, 0, 0, 0, True, {}, {}, scenario="paper2015")
    with pytest.raises(ValueError, match="robot seat only"):
        OracleRobot(empty).reset(PAPER, Agent.HUMAN, np.random.default_rng(0))


def test_an_on_model_decision_states_the_states_expected_seconds() -> None:
    state = PAPER.initial_state(np.random.default_rng(0))
    result = OracleResult(1.0, 3600.0, 1, 0, 1, 1, True, {state: 3}, {state: 12.5}, scenario="paper2015")
    robot = OracleRobot(result)
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    assert robot.act(Turn(PAPER, state, Agent.ROBOT, {})) == 3
    decision = robot.last_decision
    assert decision is not None
    assert (decision.expert, decision.action, decision.stats) == ("oracle", 3, (("expected_seconds", 12.5),))
    assert robot.off_model == 0


def _off_model_robot() -> tuple[OracleRobot, State]:
    """A robot with an empty policy whose planner always proposes ``wait``, and a state with moves."""
    empty = OracleResult(0.0, math.inf, 0, 0, 0, 0, True, {}, {}, scenario="paper2015")
    robot = OracleRobot(empty)
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    robot._planner = SimpleNamespace(
        world=PAPER, intent=lambda s, a: SimpleNamespace(success=True, robot_action=ROBOT_WAIT, human_action=-1)
    )
    return robot, PAPER.initial_state(np.random.default_rng(0))


def test_off_its_model_the_reason_names_the_planner_then_the_guard() -> None:
    robot, state = _off_model_robot()
    reasons = []
    for _ in range(K + 1):  # turns 2..13 at the same state: unchanged 1..12; K = 12 fires at the 13th
        robot.act(Turn(PAPER, state, Agent.ROBOT, {}))
        assert robot.last_decision is not None
        reasons.append(robot.last_decision.reason)
    assert reasons == ["off model: the planner's move"] * K + [
        "off model: nothing changed for K turns; the progress guard's move"
    ]


def test_a_reset_on_the_same_table_keeps_the_result_and_starts_the_counts_afresh() -> None:
    robot, state = _off_model_robot()
    result = robot.result
    for _ in range(K + 2):
        robot.act(Turn(PAPER, state, Agent.ROBOT, {}))
    assert robot.off_model == K + 2 and robot.progress.unchanged == K + 1 and robot.progress.moves == 2
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(1))
    assert robot.result is result  # the same table: not solved again
    assert (robot.off_model, robot.progress.unchanged, robot.progress.moves) == (0, 0, 0)
    assert robot._planner is None


# --- agents/progress.py -------------------------------------------------------------------


def _walk(n: int) -> list[State]:
    """One table seen from two robot places in turn: nothing moves, the robot's place does."""
    a = PAPER.initial_state(np.random.default_rng(0))
    b = a._replace(robot_at=(a.robot_at + 1) % PAPER.table.n_locations)
    return [a if t % 2 == 0 else b for t in range(n)]


# Spells in which nothing moves: each begins after 200 quiet turns and lasts W, then W doubles:
# 40 -> 80 -> 160 -> 320, and stays at the cap 320 (8 * 40). The first spell begins at turn
# 201 (the first turn has no previous state), so four spells end by turn
# 201 + 40 + 200 + 80 + 200 + 160 + 200 + 320 = 1,401.
SPELL_ENDS = [80, 160, 320, 320]
TURNS = 1401


def test_the_scalar_guards_w_doubles_up_to_its_cap() -> None:
    guard = ProgressGuard()
    after: list[int] = []
    for state in _walk(TURNS):
        was = guard.waiting
        guard.observe(state)
        if was and not guard.waiting:
            after.append(guard.patience)
    assert after == SPELL_ENDS and guard.spells == 4


def test_the_array_guards_w_doubles_up_to_its_cap() -> None:
    guard = ArrayProgressGuard(PAPER)
    guard.reset_rows(np.arange(1))
    after: list[int] = []
    for state in _walk(TURNS):
        was = bool(guard.waiting[0])
        guard.apply(batch_of([state]), np.zeros(1, dtype=np.int64))
        if was and not guard.waiting[0]:
            after.append(int(guard.patience[0]))
    assert after == SPELL_ENDS and guard.spells.tolist() == [4]


def test_a_reset_table_has_no_previous_state_and_the_others_keep_theirs() -> None:
    guard = ArrayProgressGuard(PAPER)
    state = PAPER.initial_state(np.random.default_rng(0))
    proposed = np.zeros(2, dtype=np.int64)
    for _ in range(3):
        guard.apply(batch_of([state, state]), proposed)
    assert guard.unchanged.tolist() == [2, 2]
    guard.reset_rows(np.array([0]))
    guard.apply(batch_of([state, state]), proposed)
    # table 0 has no previous state (a first turn: 0), table 1 its third unchanged turn in a row
    assert guard.unchanged.tolist() == [0, 3]
    assert guard.quiet.tolist() == [0, 3]


def test_equal_scores_keep_the_guards_options_in_index_order() -> None:
    state = PAPER.initial_state(np.random.default_rng(0))
    options = [i for i in PAPER.feasible_indices(state, Agent.ROBOT) if i != ROBOT_WAIT]
    assert len(options) >= 2
    flat = np.zeros(PAPER.n_actions(Agent.ROBOT))
    assert [guard_option(PAPER, state, k, prefer=flat) for k in range(len(options))] == options
    # the last two tied at the top, the rest below: those two first, in index order
    top = flat.copy()
    top[options[-2:]] = 1.0
    ranked = [guard_option(PAPER, state, k, prefer=top) for k in range(len(options))]
    assert ranked == [*options[-2:], *options[:-2]]


@pytest.mark.parametrize("after", [0, True, 1.5, "12"])
def test_k_must_be_a_whole_positive_number_in_both_forms(after: object) -> None:
    with pytest.raises(ValueError, match="K must be a positive number of turns"):
        ProgressGuard(after)
    with pytest.raises(ValueError, match="K must be a positive number of turns"):
        ArrayProgressGuard(PAPER, after)


def test_a_stall_of_unchanged_turns_is_logged_as_no_progress() -> None:
    guard = ProgressGuard(1)
    state = PAPER.initial_state(np.random.default_rng(0))
    assert [guard.observe(state) for _ in range(2)] == [False, True]
    assert not guard.waiting and guard.reason == "no_progress"


# --- agents/models/live.py ----------------------------------------------------------------


class _Listed:
    """Answers in an order that is not the actions' order, with a zero and a tiny probability."""

    def distribution(self, world: object, state: State, seen: int) -> list[tuple[int, float]]:
        return [(7, 0.5), (2, 0.0), (4, 1e-300), (1, 0.5)]


def test_live_answers_keep_the_partners_order_and_drop_only_zero_probabilities() -> None:
    asker = live.LiveAnswers(PAPER, _Listed())
    sizes, actions, probs = asker([((0, 1, 2), 0, -1, -1, -1)] * 2, lambda done, total: None)
    assert sizes.tolist() == [3, 3]
    assert actions.tolist() == [7, 4, 1] * 2
    assert probs.tolist() == [0.5, 1e-300, 0.5] * 2


def test_one_job_reads_the_budget_before_every_answer_even_for_many_questions() -> None:
    # 130 questions (over the 128 from which workers would answer) with one job: in this
    # process, a reading before each answer, not one per chunk of 32
    asker = live.LiveAnswers(PAPER, _Listed(), jobs=1)
    readings: list[tuple[int, int]] = []
    asker([((0, 1, 2), 0, -1, -1, -1)] * 130, lambda done, total: readings.append((done, total)))
    assert readings == [(i, 130) for i in range(130)]


# --- agents/models/forked.py --------------------------------------------------------------


def test_in_this_process_check_is_read_before_the_first_item_and_after_each() -> None:
    seen: list[int] = []
    workers = Forked(lambda i: i + 1, jobs=1)
    assert workers.map([3, 4, 5], seen.append) == [4, 5, 6]
    assert seen == [0, 1, 2, 3]
    seen.clear()
    assert workers.map([], seen.append) == [] and seen == [0]  # no item: the reading before the first


def test_closed_workers_are_replaced_at_the_next_map() -> None:
    workers: Forked[int, tuple[int, int]] = Forked(lambda i: (i * 2, os.getpid()), jobs=2)
    try:
        first = workers.map([1, 2, 3])
        assert workers.started and workers._key in forked._FUNCTIONS
        workers.close()
        assert not workers.started and workers._key not in forked._FUNCTIONS
        assert multiprocessing.active_children() == []
        again = workers.map([4, 5])
        assert [v for v, _ in first + again] == [2, 4, 6, 8, 10] and workers.started
        assert not {p for _, p in again} & {p for _, p in first}  # new workers
    finally:
        workers.close()
    assert multiprocessing.active_children() == []


def test_workers_inherit_a_frozen_collector_and_this_process_is_left_unfrozen() -> None:
    before = gc.get_freeze_count()  # 0 in a plain run; a warm test server may have frozen its own heap
    try:
        with Forked(lambda i: gc.get_freeze_count(), jobs=2) as workers:
            counts = workers.map([0, 1])
        # forked while frozen: every object this process tracked then is in the workers' permanent generation
        assert min(counts) > before
        assert gc.get_freeze_count() == 0  # and unfrozen here once the workers are forked
    finally:
        if before == 0:
            gc.unfreeze()
