"""The build's pipeline: the next batch's live questions queued behind this one's, small batches
sent to running workers, and the headroom's shortcuts that must not change a float.

Expected values are stated apart from the code under test: by hand (the ``Echo`` stub's
answers, chunk spans, feasible rows), from the same table or model filled in one process
without any prefetch, or from the plain ``numpy`` / ``scipy`` computation the shortcut skips.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np
import pytest

import hg_marl.agents.models.builder as builder
import hg_marl.agents.models.live as live
from hg_marl.agents.models import AnswerTable, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.builder import Dynamics
from hg_marl.agents.models.chains import transitions
from hg_marl.agents.models.keyed import Searches, SegmentTable, ranges
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.partners import batch_answers, feasible_rows
from hg_marl.agents.models.solve import without_self_loops
from hg_marl.core import State, World
from hg_marl.envs.batched import BatchState
from tests.agents.test_models import mid_states

PAPER = World("paper2015")
PARENT = os.getpid()


class Echo:
    """Answers the robot's place plus ten times the action seen (known by hand for every key)."""

    def distribution(self, world: object, state: State, seen: int) -> list[tuple[int, float]]:
        return [(state.robot_at + 10 * max(seen, 0), 1.0)]

    def reset(self, *args: object) -> None:
        pass


class Where:
    """Answers 1 in a forked worker and 0 in the test's own process."""

    def distribution(self, world: object, state: State, seen: int) -> list[tuple[int, float]]:
        return [(int(os.getpid() != PARENT), 1.0)]


def _keys(n: int, seen: int = -1) -> np.ndarray:
    b = BatchState.of(mid_states(PAPER, n))
    return np.unique(StatePacker(PAPER).pack(b, np.full(len(b), seen, dtype=np.int64)))[:n]


def _echoed(packer: StatePacker, keys: np.ndarray) -> list[int]:
    states, seen = packer.unpack(keys)
    return (states.robot_at + 10 * np.maximum(seen, 0)).tolist()


@pytest.mark.parametrize(
    ("n", "spans"),
    [
        (100, [(0, 25), (25, 50), (50, 75), (75, 100)]),  # two per worker: 25, not 32
        (72, [(0, 18), (18, 36), (36, 54), (54, 72)]),
        (3, [(0, 1), (1, 2), (2, 3)]),
        (200, [(i, min(i + 32, 200)) for i in range(0, 200, 32)]),  # large: chunks of 32, the last 8
    ],
)
def test_questions_are_split_into_chunks_of_at_most_32_and_two_per_worker(n: int, spans: list[tuple[int, int]]) -> None:
    assert live.chunks(n, 2) == spans


def test_three_workers_get_two_chunks_each() -> None:
    assert live.chunks(120, 3) == [(i, i + 20) for i in range(0, 120, 20)]


def test_chunks_are_as_large_as_two_per_worker_allow() -> None:
    # 10 questions, 2 workers: four messages of 3, 3, 3 and 1 (not five of 2)
    assert live.chunks(10, 2) == [(0, 3), (3, 6), (6, 9), (9, 10)]


def test_once_the_workers_run_a_small_batch_goes_to_them() -> None:
    answers = live.LiveAnswers(PAPER, Where(), jobs=2)
    row: live.Row = ((0, 1, 2), 0, -1, -1, -1)
    try:
        _, first, _ = answers([row] * 5, lambda done, total: None)  # under 128 questions: not worth a fork
        assert not answers.workers.started and first.tolist() == [0] * 5
        answers([row] * 128, lambda done, total: None)
        _, small, _ = answers([row] * 5, lambda done, total: None)
    finally:
        answers.close()
    assert small.tolist() == [1] * 5  # answered in the workers that were running
    one = live.LiveAnswers(PAPER, Where(), jobs=2)
    try:
        one([row] * 128, lambda done, total: None)
        _, alone, _ = one([row], lambda done, total: None)  # one question: no message for it
    finally:
        one.close()
    assert alone.tolist() == [0]


def test_two_prefetches_in_flight_ask_each_key_once_and_store_every_answer(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    keys = _keys(200, seen=1)[:60]
    first, second = keys[:40], keys[20:]
    asked: list[int] = []
    submit = live.LiveAnswers.submit

    def counted(self: live.LiveAnswers, rows: Any) -> live.Asked:
        asked.append(len(rows))
        return submit(self, rows)

    monkeypatch.setattr(live.LiveAnswers, "submit", counted)
    packer = StatePacker(PAPER)
    table = AnswerTable(PAPER, Echo(), packer, jobs=2)
    try:
        table.prefetch(first)
        table.prefetch(second)  # the 20 keys the first asked are left out
        monkeypatch.setattr(live.LiveAnswers, "__call__", lambda *a: pytest.fail("asked again"))
        table.ensure(first)
        assert table._pending and np.array_equal(table.keys, first)  # the second's answers still in the workers
        table.ensure(second)
    finally:
        table.close()
    assert len(keys) == 60 and asked == [40, 20] and table.live_calls == 60
    assert table._pending == [] and table._inflight == []
    start, size = table.lookup(keys)
    assert size.tolist() == [1] * 60 and table.entries["actions"][start].tolist() == _echoed(packer, keys)


def test_the_builder_queues_the_next_batchs_searches_before_collecting_this_ones(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    monkeypatch.setattr(builder, "FIRST_CHUNK", 8)  # batches small beside the states known: the next
    monkeypatch.setattr(builder, "CHUNK", 16)  # batch's boundary is known before this one is answered
    world = World("paper2015")
    events: list[str] = []
    prefetch, ensure = AnswerTable.prefetch, AnswerTable.ensure

    def spy_prefetch(self: AnswerTable, keys: np.ndarray, batch: Any = None) -> None:
        events.append("prefetch")
        prefetch(self, keys, batch)

    def spy_ensure(self: AnswerTable, keys: np.ndarray, batch: Any = None) -> None:
        events.append("ensure")
        ensure(self, keys, batch)

    fronts: list[tuple[int, int]] = []
    front_of = builder._Front.of.__func__

    def spy_front(cls: Any, rules: Any, packer: Any, index: Any, lo: int, hi: int, *rest: Any) -> Any:
        fronts.append((lo, hi))
        return front_of(cls, rules, packer, index, lo, hi, *rest)

    models = []
    for jobs in (1, 2):
        table = AnswerTable(world, stationary_human("cooperative", world), StatePacker(world), jobs=jobs)
        if jobs == 2:
            monkeypatch.setattr(AnswerTable, "prefetch", spy_prefetch)
            monkeypatch.setattr(AnswerTable, "ensure", spy_ensure)
            monkeypatch.setattr(builder._Front, "of", classmethod(spy_front))
        try:
            models.append((build_model(world, table, layout_distribution(world)), table))
        finally:
            table.close()
    (m1, t1), (m2, t2) = models
    # per batch: its own keys (nothing left to ask where they were asked ahead), the next batch's, then
    # this batch's answers collected
    assert "".join("p" if e == "prefetch" else "e" for e in events).count("ppe") > 10
    # each batch's front computed once (ahead or in its own step), the batches one after the other
    assert [lo for lo, _ in fronts] == [0] + [hi for _, hi in fronts[:-1]] and fronts[-1][1] == m2.n
    assert t1.live_calls == t2.live_calls > 0
    assert m1.n == m2.n and np.array_equal(m1.keys, m2.keys) and np.array_equal(m1.pair_action, m2.pair_action)
    for d1, d2 in zip(m1.dynamics, m2.dynamics, strict=True):
        for name in ("t_start", "t_next", "t_prob", "t_tau"):
            assert np.array_equal(getattr(d1, name), getattr(d2, name)), name


def test_a_front_asked_past_the_known_states_ends_where_they_end() -> None:
    world = World("paper2015")
    packer = StatePacker(world)
    index = builder._Index()
    index.add(np.unique(packer.pack(BatchState.of([s for s, _ in layout_distribution(world)]))))
    n = index.n
    front = builder._Front.of(builder.BatchedRules(world), packer, index, n - 3, n + 5, [], True)
    assert front.hi == n and set(front.ps.tolist()) == {0, 1, 2}  # three states read, each with its pairs


@pytest.mark.parametrize(("shared", "chosen"), [("1.0000000005", 8), ("1.000000002", 27)])
def test_the_array_preference_keeps_the_first_action_within_the_tie(shared: str, chosen: int) -> None:
    # paper2015: tape3 in the human's hand, the robot at human_side. give(tape3) (index 8) scores
    # handover = 1.0, place(tape3, mat_shared) (index 27) scores ``shared``: within 1e-9 of the
    # first, the first in index order stays; beyond it, the place wins (the live rule's tie)
    world = World("paper2015")
    human = stationary_human(f"preference:handover=1.0,shared={shared},haste=0", world)
    answers = batch_answers(world, human)
    assert answers is not None
    sizes, actions, probs = answers(BatchState.of([State((0, 1, 8), 3)]))
    assert sizes.tolist() == [1] and actions.tolist() == [chosen] and probs.tolist() == [1.0]


def test_feasible_rows_by_hand() -> None:
    mask = np.array([[True, False, True], [True, True, False], [False, True, True]])
    rows = feasible_rows(mask)
    assert [r.tolist() for r in rows] == [[0, 1], [1, 2], [0, 2]]


def test_a_chains_transition_pairs_are_its_rows() -> None:
    chain = Dynamics(np.array([0, 2, 2, 5]), np.zeros(5, np.int64), np.ones(5), np.ones(5), *([np.zeros(0)] * 3))
    assert chain.t_pair.tolist() == [0, 0, 2, 2, 2]
    assert chain.t_pair is chain.t_pair  # computed once


@pytest.mark.parametrize("loop", [0.0, 0.25])
def test_the_closed_form_matches_the_plain_scaling_with_and_without_loops(loop: float) -> None:
    # state 0: pair 0 -> state 1 (and back to 0 with ``loop``), pair 1 -> state 1; state 1: pair 2 completes
    t_start = np.array([0, 2, 3, 3]) if loop else np.array([0, 1, 2, 2])
    t_next = np.array([0, 1, 1]) if loop else np.array([1, 1])
    t_prob = np.array([loop, 1.0 - loop, 1.0]) if loop else np.array([1.0, 1.0])
    pair_state = np.array([0, 0, 1])
    cost = np.array([3.0, 4.0, 0.0])
    matrix, scaled, looping = without_self_loops(pair_state, t_start, t_next, t_prob, cost, 2)
    leave = 1.0 - loop
    assert matrix.toarray().tolist() == [[0.0, leave / leave], [0.0, 1.0], [0.0, 0.0]]
    assert scaled.tolist() == [3.0 / leave, 4.0, 0.0] and looping.tolist() == [False, False, False]


def test_costs_summed_per_pair_equal_the_csr_product() -> None:
    rng = np.random.default_rng(5)
    counts = rng.integers(0, 4, 300)
    t_start = np.concatenate([[0], np.cumsum(counts)])
    m = int(t_start[-1])
    chain = Dynamics(t_start, rng.integers(0, 50, m), rng.random(m), rng.random(m) * 7, *([np.zeros(0)] * 3))
    product = transitions(chain, 50, chain.t_prob * chain.t_tau) @ np.ones(50)
    summed = np.bincount(chain.t_pair, weights=chain.t_prob * chain.t_tau, minlength=300)
    assert np.array_equal(product, summed)


def _table(keys: list[int], sizes: list[int]) -> SegmentTable:
    table = SegmentTable({"v": np.int64})
    table.add(np.array(keys, dtype=np.int64), np.array(sizes), {"v": np.arange(sum(sizes), dtype=np.int64)})
    return table


def test_tables_with_the_same_keys_search_once_and_share_the_merged_keys() -> None:
    a, b, c = _table([3, 7, 9], [1, 2, 1]), _table([3, 7, 9], [2, 1, 1]), _table([3, 7, 8], [1, 1, 1])
    assert a.keys is not b.keys
    searches = Searches()
    queries = np.array([7, 8, 9], dtype=np.int64)
    assert a.lacks(queries, searches).tolist() == [False, True, False]
    calls: list[str] = []
    compute = searches.get

    def counted(kind: str, table: SegmentTable, asked: np.ndarray, make: Any) -> Any:
        def searched() -> Any:
            calls.append(kind)
            return make()

        return compute(kind, table, asked, searched)

    searches.get = counted
    assert b.lacks(queries, searches).tolist() == [False, True, False] and calls == []  # a's answer, not searched
    assert b.keys is a.keys  # equal keys: b now shares a's array
    # other keys: its own search (the positions, which a lookup of the same queries then reads)
    assert c.lacks(queries, searches).tolist() == [False, False, True] and calls == ["positions"]
    both = np.array([7, 8], dtype=np.int64)  # c holds both: a lookup after the check reads the check's search
    assert not c.lacks(both, searches).any() and c.lookup(both, searches=searches)[0].tolist() == [1, 2]
    assert calls == ["positions", "positions"]
    new = np.array([8], dtype=np.int64)
    for table, v in ((a, 10), (b, 20)):
        table.add(new, np.array([1]), {"v": np.array([v])}, searches)
    assert a.keys is b.keys and a.keys.tolist() == [3, 7, 8, 9] and not a.keys.flags.writeable
    # each keeps its own entries: a's 8 is its fifth entry (10), b's its fifth (20)
    for table, want in ((a, [(0, 1), (1, 2), (4, 1), (3, 1)]), (b, [(0, 2), (2, 1), (4, 1), (3, 1)])):
        first, size = table.lookup(np.array([3, 7, 8, 9]), searches=searches)
        assert list(zip(first.tolist(), size.tolist(), strict=True)) == want
    assert int(a.entries["v"][4]) == 10 and int(b.entries["v"][4]) == 20


def test_the_headrooms_array_partners_share_one_keys_array() -> None:
    world = World("paper2015")
    packer = StatePacker(world)
    specs = ["preference", "preference:handover=1.0,shared=-1.0", "random"]
    tables = [AnswerTable(world, stationary_human(spec, world), packer) for spec in specs]
    build_model(world, tables, layout_distribution(world), keep=False)
    alone = AnswerTable(world, stationary_human("random", world), packer)
    alone.ensure(tables[2].keys.copy())
    assert tables[0].keys is tables[1].keys is tables[2].keys and len(tables[0].keys) > 1000
    start, size = tables[2].lookup(tables[2].keys)
    s0, n0 = alone.lookup(tables[2].keys)
    assert np.array_equal(size, n0)
    for name in ("actions", "probs", "next"):
        assert np.array_equal(tables[2].entries[name][ranges(start, size)], alone.entries[name][ranges(s0, n0)])
