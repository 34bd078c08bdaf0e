"""What the partners of one model share: work handed to the workers early, a batch's unpacking,
masks and derived arrays computed once, and table positions searched once.

Each is a speed-up that must not change an answer, so each test states the answers apart from
the shared path: by hand (the ``Echo`` stub), from the live humans' own ``distribution``, or
from the same call made without sharing.
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

import hg_marl.agents.models.live as live
from hg_marl.agents.models import AnswerTable, StatePacker
from hg_marl.agents.models.answers import KeyBatch, stationary_human
from hg_marl.agents.models.forked import Forked
from hg_marl.agents.models.keyed import ranges
from hg_marl.agents.models.partners import batch_answers
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchedRules, BatchState
from tests.agents.test_models import mid_states

PAPER = World("paper2015")


class Echo:
    """Answers as a function of what it sees: the robot's place plus ten times the action seen."""

    def distribution(self, world: object, state: State, seen: int) -> list[tuple[int, float]]:
        return [(state.robot_at + 10 * max(seen, 0), 1.0)]

    def reset(self, *args: object) -> None:
        pass


def _echoed(table: AnswerTable, keys: np.ndarray) -> list[int]:
    states, seen = table.packer.unpack(keys)
    return (states.robot_at + 10 * np.maximum(seen, 0)).tolist()


def _keys(n: int, seen: int = -1) -> np.ndarray:
    """Distinct sorted keys of paper2015's mid-cycle states (at most ``n``), with the robot action ``seen``."""
    b = BatchState.of(mid_states(PAPER, n))
    return np.unique(StatePacker(PAPER).pack(b, np.full(len(b), seen, dtype=np.int64)))[:n]


def _seen_keys(world: World) -> tuple[StatePacker, BatchState, np.ndarray]:
    """Mid-cycle states of ``world``, each with a robot action seen, and their distinct keys."""
    packer = StatePacker(world)
    states = BatchState.of(mid_states(world, 300))
    seen = np.arange(len(states)) % world.n_actions(Agent.ROBOT)
    return packer, states, np.unique(packer.pack(states, seen))


def test_submitted_items_come_back_in_order_with_the_readings_of_map() -> None:
    readings: list[int] = []
    with Forked(lambda i: i * 3, jobs=2) as workers:
        handed = workers.submit(list(range(10)))
        assert workers.started  # the workers have the items before anyone collects them
        assert handed.collect(readings.append) == [3 * i for i in range(10)]
    assert readings == list(range(11)) and multiprocessing.active_children() == []


def test_in_this_process_nothing_is_computed_before_collect() -> None:
    done: list[int] = []

    def record(i: int) -> int:
        done.append(i)
        return i

    workers = Forked(record, jobs=1)
    handed = workers.submit([1, 2, 3])
    assert done == []
    assert handed.collect() == [1, 2, 3] and done == [1, 2, 3]


def test_a_prefetch_is_collected_by_the_ensure_of_its_keys(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    table = AnswerTable(PAPER, Echo(), StatePacker(PAPER), jobs=2)
    keys = _keys(40, seen=2)
    try:
        table.prefetch(keys)
        assert table.live.workers.started

        def asked_again(*args: object) -> None:
            raise AssertionError("the prefetched keys were asked again")

        monkeypatch.setattr(live.LiveAnswers, "__call__", asked_again)
        table.ensure(keys)
    finally:
        table.close()
    start, size = table.lookup(keys)
    assert size.tolist() == [1] * len(keys) and table.live_calls == len(keys)
    assert table.entries["actions"][start].tolist() == _echoed(table, keys)


def test_an_ensure_of_other_keys_answers_them_and_not_the_prefetch(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    table = AnswerTable(PAPER, Echo(), StatePacker(PAPER), jobs=2)
    keys = _keys(40, seen=1)
    try:
        table.prefetch(keys[:20])
        table.ensure(keys[10:])
    finally:
        table.close()
    assert len(keys) > 20 and np.array_equal(table.keys, keys[10:]) and table.live_calls == len(keys) - 10
    start, _ = table.lookup(keys[10:])
    assert table.entries["actions"][start].tolist() == _echoed(table, keys[10:])


def test_no_prefetch_for_a_partner_on_arrays_or_without_workers() -> None:
    arrays = AnswerTable(PAPER, stationary_human("random", PAPER), StatePacker(PAPER), jobs=2)
    alone = AnswerTable(PAPER, Echo(), StatePacker(PAPER), jobs=1)
    for table in (arrays, alone):
        table.prefetch(_keys(200))
        assert not table.live.workers.started
    assert not arrays.answers_live and alone.answers_live


@pytest.mark.parametrize(("batches", "together"), [(1, False), (2, False), (2, True)])
def test_the_planner_partner_prefetched_answers_as_asked(
    monkeypatch: pytest.MonkeyPatch, batches: int, together: bool
) -> None:
    """The equivariant path: prefetches of canonical keys (two in flight, overlapping), each collected
    by its own batch's ensure (or both by one ensure of all the keys), the same answers as a table
    filled in one process without them."""
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    world = World("paper2015")
    packer, _, keys = _seen_keys(world)
    parts = [keys] if batches == 1 else [keys[: 2 * len(keys) // 3], keys[len(keys) // 3 :]]
    plain = AnswerTable(world, stationary_human("cooperative", world), packer)
    for part in parts:
        plain.ensure(part)
    early = AnswerTable(world, stationary_human("cooperative", world), packer, jobs=2)
    try:
        for part in parts:
            early.prefetch(part)
        assert early.canonical is not None and len(early.canonical._pending) == batches
        monkeypatch.setattr(live.LiveAnswers, "__call__", lambda *a: pytest.fail("asked again"))
        if together:
            early.ensure(keys)  # its keys were asked by both prefetches: both collected, nothing asked again
            assert early.canonical._pending == []
        for done, part in enumerate(parts, start=1):
            early.ensure(part)
            assert len(early.canonical._pending) == (0 if together else batches - done)  # each waited for its own
    finally:
        early.close()
    assert early.live_calls == plain.live_calls
    if together:  # one ensure stored every key: compare key by key
        start, size = early.lookup(keys)
        s0, n0 = plain.lookup(keys)
        assert np.array_equal(size, n0)
        for name in ("actions", "probs", "next", "d_human"):
            assert np.array_equal(early.entries[name][ranges(start, size)], plain.entries[name][ranges(s0, n0)])
        return
    for name in ("actions", "probs", "next", "d_human"):
        assert np.array_equal(early.entries[name], plain.entries[name]), name


def test_a_shared_batch_gives_every_preference_its_live_answers() -> None:
    world = World("roboergosum")
    states = mid_states(world, 1500)
    packer = StatePacker(world)
    keys = np.unique(packer.pack(BatchState.of(states)))
    specs = ["preference", "preference:handover=-1,shared=1,robot_side=0.8,accept=0", "random", "preference:p_idle=1"]
    shared = KeyBatch(packer, BatchedRules(world), keys)
    tables = [AnswerTable(world, stationary_human(spec, world), packer) for spec in specs]
    for table in tables:
        table.ensure(keys, shared)
    b, _ = packer.unpack(keys)
    for spec, table in zip(specs, tables, strict=True):
        human = stationary_human(spec, world)
        start, size = table.lookup(keys)
        for i in range(0, len(keys), 7):
            got = [
                (int(table.entries["actions"][e]), float(table.entries["probs"][e]))
                for e in range(start[i], start[i] + size[i])
            ]
            want = [(h, p) for h, p in human.distribution(world, b.state(i), -1) if p > 0.0]
            assert got == want, (spec, i)


def test_a_shared_batch_computes_what_it_derives_once_per_name() -> None:
    packer = StatePacker(PAPER)
    keys = _keys(30)
    shared = KeyBatch(packer, BatchedRules(PAPER), keys)
    calls: list[str] = []

    def make(name: str, value: int) -> Callable[[], int]:
        def compute() -> int:
            calls.append(name)
            return value

        return compute

    assert shared.derived("a", make("a", 1)) == 1
    assert shared.derived("a", make("a", 2)) == 1
    assert shared.derived("b", make("b", 3)) == 3
    assert calls == ["a", "b"]
    b, seen = packer.unpack(keys)
    assert np.array_equal(shared.unpacked[0].where, b.where) and np.array_equal(shared.unpacked[1], seen)
    assert np.array_equal(shared.mask, BatchedRules(PAPER).masks(b, Agent.HUMAN))
    rows = np.array([0, 4, 9])
    part = shared.rows(rows)
    assert shared.rows(np.array([0, 4, 9])) is part and shared.rows(np.array([0, 4])) is not part
    assert np.array_equal(part.keys, keys[rows])
    again = shared.rows(rows)  # kept again
    other = shared.rows(np.array([1, 5, 8]))  # as many rows, other ones: not the subset kept
    assert other is not again and np.array_equal(other.keys, keys[[1, 5, 8]])
    assert shared.rows(np.array([1, 5, 8])) is other
    assert np.array_equal(part.mask, BatchedRules(PAPER).masks(packer.unpack(keys[rows])[0], Agent.HUMAN))
    assert np.array_equal(part.unpacked[0].robot_at, b.robot_at[rows])


def test_tables_lacking_different_keys_of_a_shared_batch_each_get_their_own() -> None:
    world = World("paper2015")
    packer = StatePacker(world)
    keys = np.unique(packer.pack(BatchState.of(mid_states(world, 400))))
    fresh = AnswerTable(world, stationary_human("random", world), packer)
    ahead = AnswerTable(world, stationary_human("random", world), packer)
    ahead.ensure(keys[::3])  # already answered a third: it lacks other keys than ``fresh``
    shared = KeyBatch(packer, BatchedRules(world), keys)
    for table in (ahead, fresh):
        table.ensure(keys, shared)
    alone = AnswerTable(world, stationary_human("random", world), packer)
    alone.ensure(keys)
    s0, n0 = alone.lookup(keys)
    for table in (ahead, fresh):
        start, size = table.lookup(keys)
        assert np.array_equal(size, n0)
        for name in ("actions", "probs", "next", "d_human"):
            assert np.array_equal(table.entries[name][ranges(start, size)], alone.entries[name][ranges(s0, n0)]), name


def test_array_answers_with_and_without_a_shared_batch_agree() -> None:
    world = World("forced_coordination")
    packer = StatePacker(world)
    keys = np.unique(packer.pack(BatchState.of(mid_states(world, 800))))
    b, _ = packer.unpack(keys)
    shared = KeyBatch(packer, BatchedRules(world), keys)
    for spec in ("preference:colour=blue,colour_bonus=0.4,haste=0.2", "preference:handover=1,keep=0.3", "random"):
        answers = batch_answers(world, stationary_human(spec, world))
        assert answers is not None
        for x, y in zip(answers(b), answers(b, shared), strict=True):
            assert np.array_equal(x, y) and x.dtype == y.dtype, spec


def test_a_prefetched_batchs_canonical_keys_and_masks_are_computed_once(monkeypatch: pytest.MonkeyPatch) -> None:
    from hg_marl.agents.models.equivariant import CanonicalAnswers

    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    world = World("paper2015")
    packer, states, keys = _seen_keys(world)
    computed: list[int] = []
    original = CanonicalAnswers._keys

    def counted(self: CanonicalAnswers, b: BatchState, s: np.ndarray) -> Any:
        computed.append(len(b))
        return original(self, b, s)

    monkeypatch.setattr(CanonicalAnswers, "_keys", counted)
    table = AnswerTable(world, stationary_human("cooperative", world), packer, jobs=2)
    shared = KeyBatch(packer, BatchedRules(world), keys)
    try:
        table.prefetch(keys, shared)
        assert shared._mask is not None  # the masks the answers are stepped with: computed while they are searched
        table.ensure(keys, shared)
        assert computed == [len(keys)]  # the ensure read the prefetch's canonical keys back
        more = np.unique(np.concatenate([keys, packer.pack(states, np.zeros(len(states), dtype=np.int64))]))
        table.ensure(more)  # a batch that was not prefetched computes its own
    finally:
        table.close()
    assert len(computed) == 2
    plain = AnswerTable(world, stationary_human("cooperative", world), packer)
    plain.ensure(more)
    start, size = table.lookup(more)
    s0, n0 = plain.lookup(more)
    assert np.array_equal(size, n0)
    for name in ("actions", "probs", "next"):
        assert np.array_equal(table.entries[name][ranges(start, size)], plain.entries[name][ranges(s0, n0)]), name


def test_a_closed_table_asks_again_what_it_had_prefetched(monkeypatch: pytest.MonkeyPatch) -> None:
    """Workers stopped before their answers were collected (a refusal between the two): the keys
    are asked again, not waited for."""
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    world = World("paper2015")
    packer, _, seen_keys = _seen_keys(world)
    echo_keys = _keys(40, seen=2)
    echo = AnswerTable(world, Echo(), packer, jobs=2)
    planner = AnswerTable(world, stationary_human("cooperative", world), packer, jobs=2)
    for table, keys in ((echo, echo_keys), (planner, seen_keys)):
        try:
            table.prefetch(keys)
            table.close()
            assert multiprocessing.active_children() == []
            table.ensure(keys)
        finally:
            table.close()
        assert table.live_calls > 0 and np.array_equal(table.keys, keys)
    start, _ = echo.lookup(echo_keys)
    assert echo.entries["actions"][start].tolist() == _echoed(echo, echo_keys)
    plain = AnswerTable(world, stationary_human("cooperative", world), packer)
    plain.ensure(seen_keys)
    for name in ("actions", "probs", "next"):
        assert np.array_equal(planner.entries[name], plain.entries[name]), name
