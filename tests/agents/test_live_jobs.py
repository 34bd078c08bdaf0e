"""Forked workers: the same answers and matrices whatever ``jobs`` is, and no worker left behind.

The expected values are stated apart from the parallel code: the one-tape crossing's
matrix worked by hand (``test_headroom.py``'s docstring), and the one-process answer
table, which the pinned builder tests compare with the Python enumeration.
"""

from __future__ import annotations

import multiprocessing
import os
from pathlib import Path

import numpy as np
import pytest

import hg_marl.agents.models.live as live
from hg_marl.agents.headroom import headroom
from hg_marl.agents.models import AnswerTable, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.budget import OverBudget
from hg_marl.agents.models.forked import Forked, check_jobs
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.core import Agent, Kind, State, World
from tests.cli_helpers import error_lines, run_main

CROSSING = str(Path(__file__).parent / "data" / "crossing.toml")
G = "preference:handover=1.0,shared=-1.0"
C = "preference:handover=-1.0,shared=1.0"


def test_workers_inherit_the_function_and_answer_in_order() -> None:
    offset = {"by": 1000}  # read through a lambda: neither can be pickled, a forked worker inherits both
    with Forked(lambda i: (i + offset["by"], os.getpid()), jobs=2) as workers:
        assert workers.parallel
        first = workers.map(list(range(40)))
        children = {p.pid for p in multiprocessing.active_children()}
        again = workers.map(list(range(5)))
        assert {p.pid for p in multiprocessing.active_children()} == children  # the same workers serve the next map
    assert [v for v, _ in first] == list(range(1000, 1040))
    pids = {pid for _, pid in first + again}
    assert os.getpid() not in pids and pids <= children and len(children) == 2
    assert multiprocessing.active_children() == []


def test_check_is_read_before_and_after_each_result() -> None:
    seen: list[int] = []
    with Forked(lambda i: i * i, jobs=2) as workers:
        assert workers.map([3, 4, 5], seen.append) == [9, 16, 25]
    assert seen == [0, 1, 2, 3]


def test_a_refusal_in_the_parent_stops_every_worker() -> None:
    def check(done: int) -> None:
        if done == 2:
            raise OverBudget("over its budget in phase 'test' (2 of 50 items)")

    workers = Forked(lambda i: i, jobs=2)
    with pytest.raises(OverBudget, match="2 of 50"):
        workers.map(list(range(50)), check)
    assert multiprocessing.active_children() == []


def test_an_error_in_a_worker_reaches_the_caller_and_stops_the_workers() -> None:
    def boom(i: int) -> int:
        if i == 3:
            raise ValueError("item 3 is bad")
        return i

    with pytest.raises(ValueError, match="item 3 is bad"), Forked(boom, jobs=2) as workers:
        workers.map(list(range(10)))
    assert multiprocessing.active_children() == []


def test_one_job_maps_in_this_process() -> None:
    with Forked(lambda i: os.getpid(), jobs=1) as workers:
        assert not workers.parallel
        assert workers.map([1, 2]) == [os.getpid()] * 2


@pytest.mark.parametrize("bad", [-1, 257, 1.5, True, "2"])
def test_a_bad_job_count_is_refused_by_name(bad: object) -> None:
    with pytest.raises(ValueError, match=r"^--jobs must be a whole number from 0 \(one per CPU\) to 256"):
        check_jobs(bad, "--jobs")  # type: ignore[arg-type]


def test_zero_jobs_is_one_per_cpu() -> None:
    assert check_jobs(0) == min(os.cpu_count() or 1, 256)


def test_the_planner_partner_answers_alike_in_workers(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)  # every batch of questions goes to the workers
    world = World("paper2015")
    tables = []
    for jobs in (1, 2):
        table = AnswerTable(world, stationary_human("cooperative", world), StatePacker(world), jobs=jobs)
        try:
            model = build_model(world, table, layout_distribution(world))
        finally:
            table.close()
        tables.append((table, model))
    (one, m1), (two, m2) = tables
    assert two.live.workers.parallel and one.live_calls == two.live_calls > 0
    np.testing.assert_array_equal(one.keys, two.keys)
    for name in ("actions", "probs", "next", "d_human"):
        np.testing.assert_array_equal(one.entries[name], two.entries[name])
    assert m1.n == m2.n and np.array_equal(m1.pair_action, m2.pair_action)
    assert multiprocessing.active_children() == []


def test_the_hand_worked_matrix_with_two_jobs() -> None:
    result = headroom(CROSSING, [("G", G), ("C", C)], jobs=2)
    np.testing.assert_allclose(result.optimum, [3600 / 17.5, 3600 / 8])
    rates = dict(zip(result.assumed, result.rates.tolist(), strict=True))
    np.testing.assert_allclose(rates["G"], [3600 / 17.5, 3600 / 18])
    np.testing.assert_allclose(rates["C"], [0.0, 3600 / 8])
    np.testing.assert_allclose(rates["cooperative"], [0.0, 3600 / 8])
    assert result.headroom == pytest.approx(0.5)
    assert multiprocessing.active_children() == []


def test_more_jobs_give_the_same_matrix_on_a_population() -> None:
    members = [(f"m{i}", spec) for i, spec in enumerate(["lazy", "no_handover", G, C, "random"])]
    one = headroom("paper2015", members, jobs=1)
    two = headroom("paper2015", members, jobs=2)
    assert one.assumed == two.assumed and one.n_states == two.n_states
    np.testing.assert_array_equal(one.rates, two.rates)


def test_cli_jobs_gives_the_same_csv(tmp_path: Path) -> None:
    outs = []
    for jobs in ("1", "2"):
        out = tmp_path / jobs
        code, _, err = run_main(
            ["headroom", "--scenario", CROSSING, "--humans", f"{G},{C}", "--jobs", jobs, "--out", str(out)]
        )
        assert code == 0, err
        outs.append((out / "headroom.csv").read_text())
    assert outs[0] == outs[1]


def test_cli_jobs_defaults_to_two_workers_where_the_machine_has_two_cpus(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """As ``evaluate --workers`` and ``reproduce --workers``: two where there are two CPUs, else one."""
    import hg_marl.training.headroom as command_module

    asked: list[int] = []

    def record(*args: object, jobs: int, **kwargs: object) -> None:
        asked.append(jobs)
        raise SystemExit(0)

    monkeypatch.setattr(command_module, "write_headroom", record)
    run_main(["headroom", "--scenario", CROSSING, "--humans", G, "--out", str(tmp_path / "o")])
    assert asked == [2 if (os.cpu_count() or 1) >= 2 else 1]


def test_cli_bad_jobs_is_one_line(tmp_path: Path) -> None:
    code, _, err = run_main(["headroom", "--scenario", CROSSING, "--jobs", "-1", "--out", str(tmp_path / "o")])
    lines = error_lines(err)
    assert code == 2 and len(lines) == 1 and "--jobs" in lines[0], err
    assert not (tmp_path / "o").exists()


class Echo:
    """A partner stub answering as a function of what it sees: the robot's place for sure,
    and half and half between 1 and 2 while someone offers (worked by hand below)."""

    def distribution(self, world: object, state: State, seen: int) -> list[tuple[int, float]]:
        if state.offer_by >= 0:
            return [(1, 0.5), (2, 0.5), (3, 0.0)]
        return [(state.robot_at + 10 * seen, 1.0)]


def _questions(n: int) -> list[live.Row]:
    return [((0, 1), i, -1 if i % 3 else 0, 0, i % 2) for i in range(n)]


def test_answers_by_hand_and_the_budget_read_per_chunk(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(live, "MIN_PARALLEL", 1)
    answers = live.LiveAnswers(World("paper2015"), Echo(), jobs=2)
    readings: list[tuple[int, int]] = []
    try:
        sizes, actions, probs = answers(_questions(100), lambda done, total: readings.append((done, total)))
    finally:
        answers.close()
    # rows 0, 3, 6, ... are offered (two answers, the 0.0 one dropped); the others answer robot_at + 10 * seen
    want_sizes = [2 if i % 3 == 0 else 1 for i in range(100)]
    want_actions = [a for i in range(100) for a in ([1, 2] if i % 3 == 0 else [i + 10 * (i % 2)])]
    want_probs = [p for i in range(100) for p in ([0.5, 0.5] if i % 3 == 0 else [1.0])]
    assert sizes.tolist() == want_sizes and actions.tolist() == want_actions and probs.tolist() == want_probs
    # 100 questions for 2 workers: 4 chunks of 25 (two per worker; 32 would leave one with a short second)
    assert readings == [(0, 100), (25, 100), (50, 100), (75, 100), (100, 100)]


def test_one_process_reads_the_budget_before_each_answer() -> None:
    answers = live.LiveAnswers(World("paper2015"), Echo(), jobs=1)
    readings: list[tuple[int, int]] = []
    sizes, _, _ = answers(_questions(5), lambda done, total: readings.append((done, total)))
    assert sizes.tolist() == [2, 1, 1, 2, 1] and readings == [(i, 5) for i in range(5)]


@pytest.mark.parametrize(("n", "forked"), [(127, False), (128, True)])
def test_workers_start_from_128_questions(n: int, forked: bool) -> None:
    answers = live.LiveAnswers(World("paper2015"), Echo(), jobs=2)
    try:
        answers(_questions(n), lambda done, total: None)
        assert answers.workers.started is forked
    finally:
        answers.close()
    assert not answers.workers.started and multiprocessing.active_children() == []


def test_the_job_bounds_are_inclusive(monkeypatch: pytest.MonkeyPatch) -> None:
    assert check_jobs(256) == 256 and check_jobs(1) == 1
    monkeypatch.setattr(os, "cpu_count", lambda: None)  # unknown: one worker
    assert check_jobs(0) == 1


def test_the_progress_bar_counts_policies_then_partners(capsys: pytest.CaptureFixture[str]) -> None:
    headroom(CROSSING, [("G", G), ("C", C)], progress=True)
    err = capsys.readouterr().err
    # three rows (cooperative, G, C), then two columns: five steps
    assert "headroom: policies, rates: 100%" in err and "5/5" in err and "6/5" not in err


def test_without_fork_the_items_are_mapped_here(monkeypatch: pytest.MonkeyPatch) -> None:
    def no_fork(method: str) -> None:
        raise ValueError(f"cannot find context for {method!r}")  # what multiprocessing says where fork is missing

    monkeypatch.setattr(multiprocessing, "get_context", no_fork)
    workers = Forked(lambda i: (i, os.getpid()), jobs=2)
    assert not workers.parallel
    assert workers.map([7, 8]) == [(7, os.getpid()), (8, os.getpid())] and not workers.started


def test_a_table_asks_in_this_process_unless_told_otherwise() -> None:
    assert live.LiveAnswers(World("paper2015"), Echo()).workers.jobs == 1
    world = World("paper2015")
    assert AnswerTable(world, stationary_human("cooperative", world), StatePacker(world)).live.workers.jobs == 1


def test_one_process_by_default_and_one_item_is_mapped_here() -> None:
    assert Forked(lambda i: i).jobs == 1 and not Forked(lambda i: i).parallel
    with Forked(lambda i: os.getpid(), jobs=2) as workers:
        assert workers.map([5]) == [os.getpid()] and not workers.started  # forking for one item costs more
        assert os.getpid() not in workers.map([5, 6]) and workers.started


def test_the_budget_is_read_per_policy_then_per_partner(monkeypatch: pytest.MonkeyPatch) -> None:
    import hg_marl.agents.headroom as headroom_module
    from hg_marl.agents.models.budget import Budget

    readings: list[tuple[str, int, int | None, str]] = []

    class Recording(Budget):
        def check(self, phase: str, done: int, total: int | None = None, unit: str = "states", **kw: object) -> None:
            if phase in ("policies", "rates"):
                readings.append((phase, done, total, unit))
            super().check(phase, done, total, unit, **kw)  # type: ignore[arg-type]

    monkeypatch.setattr(headroom_module, "Budget", Recording)
    headroom(CROSSING, [("G", G), ("C", C)], jobs=2)
    # three rows (cooperative, G, C), then two columns: a reading before the first result and after each
    assert readings == [
        *(("policies", i, 3, "policies") for i in range(4)),
        *(("rates", i, 2, "partners") for i in range(3)),
    ]


def test_a_question_keeps_each_column_in_its_place() -> None:
    """A batch's arrays become (where, robot_at, offer_by, offer_obj, robot action seen) rows,
    in that order (worked by hand: the robot, seat 0, offering object 2)."""
    rows = live.questions(
        np.array([[6, 4, 7], [1, 2, 3]]), np.array([3, 0]), np.array([0, -1]), np.array([2, -1]), np.array([5, -1])
    )
    assert rows == [((6, 4, 7), 3, 0, 2, 5), ((1, 2, 3), 0, -1, -1, -1)]


def test_live_answers_at_an_offer_are_the_partners_own() -> None:
    """At states where the robot offers object 1 or 2 (the column swap shows only where the
    offered object is not the offerer's seat number), the live answers are the partner's
    ``distribution`` asked directly."""
    world = World("paper2015")
    human = stationary_human("cooperative", world)
    asker = live.LiveAnswers(world, human)
    found: list[State] = []
    rng = np.random.default_rng(0)
    acts = world.actions(Agent.ROBOT)
    for _ in range(400):  # the robot's random moves until it can give object 1 or 2
        state = world.initial_state(rng)
        for _step in range(12):
            feasible = world.feasible_indices(state, Agent.ROBOT)
            gives = [i for i in feasible if acts[i].kind is Kind.GIVE and acts[i].obj in (1, 2)]
            if gives:
                offered = world.step(state, Agent.ROBOT, gives[0]).state
                found.append(offered)
                break
            state = world.step(state, Agent.ROBOT, int(rng.choice(feasible))).state
        if len(found) >= 6:
            break
    assert len(found) >= 6 and {s.offer_obj for s in found} & {1, 2}
    rows = live.questions(  # the batch's arrays, as the answer table asks
        np.array([s.where for s in found]),
        np.array([s.robot_at for s in found]),
        np.array([s.offer_by for s in found]),
        np.array([s.offer_obj for s in found]),
        np.full(len(found), -1),
    )
    sizes, actions, probs = asker(rows, lambda done, total: None)
    at = 0
    for s, size in zip(found, sizes.tolist(), strict=True):
        direct = [(h, p) for h, p in human.distribution(world, s, -1) if p > 0.0]
        assert list(zip(actions[at : at + size].tolist(), probs[at : at + size].tolist(), strict=True)) == direct
        at += size
