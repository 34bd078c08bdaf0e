"""The headroom model, pinned for the gate: its solve, its Python enumeration, what it keeps.

Expected values by hand: the solve reads the budget every 64th sweep and the process's
memory every 4,096th (so a run of 4,096 sweeps reads it at 64, 128, ..., 4,096 and the
memory once, at 4,096); the states budget's default is the one the documentation gives.
On a hand-made three-state model (below) the values, the sweeps and the rate are worked
by hand; on the one-tape crossing the matrix is ``tests/agents/test_headroom.py``'s, and
each pair's transitions are the live cycle's (``hg_marl.core.cycle``), read as a reference.
"""

from __future__ import annotations

import inspect
import re
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import pytest

from hg_marl.agents.headroom import JointModel, headroom
from hg_marl.agents.humans import make_human
from hg_marl.agents.models import Model, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.budget import Budget
from hg_marl.agents.models.builder import Dynamics
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.core import Agent, World
from hg_marl.core.cycle import half, seen
from tests.agents.test_headroom import CROSSING, C, G
from tests.agents.test_oracle import TINY

ROOT = Path(__file__).resolve().parents[2]


class SpyBudget(Budget):
    """A budget without limits that records the solve's checks."""

    def __init__(self) -> None:
        super().__init__(None, None, None)
        self.solve_checks: list[tuple[int, bool]] = []

    def check(self, phase: str, done: int, total: int | None = None, unit: str = "states", **kw: Any) -> None:
        if phase == "solve":
            self.solve_checks.append((done, bool(kw.get("memory", False))))
        super().check(phase, done, total, unit, **kw)


def test_the_solve_reads_the_budget_every_64_sweeps_and_memory_every_4096() -> None:
    world = World(TINY)
    human = make_human("cooperative")
    human.reset(world, Agent.HUMAN, __import__("numpy").random.default_rng(0))
    budget = SpyBudget()
    model = JointModel(world, [human], failed_actions=False, budget=budget)
    model.optimal_policy(0, tolerance=-1.0, max_iterations=4096)  # a negative tolerance never stops early
    assert budget.solve_checks == [(k, k == 4096) for k in range(64, 4097, 64)]


def test_the_states_budget_default_is_the_documented_one() -> None:
    doc = (ROOT / "docs" / "exact-references.md").read_text()
    match = re.search(r"`--max-states`, default ([\d,]+)", doc)
    assert match is not None
    documented = int(match.group(1).replace(",", ""))
    assert documented == 1_500_000
    assert inspect.signature(headroom).parameters["max_states"].default == documented
    assert inspect.signature(JointModel).parameters["max_states"].default == documented


# ---- the joint model's own solve on a hand-made model ---------------------------------------
#
# Three states, one partner, every transition certain (probability 1):
#   state 0: pair 0 (action 0) -> state 1 in 1 s;  pair 1 (action 1) -> state 2 in 0.25 s
#   state 1: pair 2 (action 2) completes the task (no transition; the re-draw follows)
#   state 2: pair 3 (action 3) -> state 1 in 0.25 s
#   re-draw: state 0 with probability 1 after a 1 s completing cycle.
# Expected seconds to the next success, by hand: V(1) = 0, V(2) = 0.25,
# V(0) = min(1 + 0, 0.25 + 0.25) = 0.5 by pair 1. Value iteration from 0 (a completing pair
# is worth 0 seconds): sweep 1 gives (0.25, 0, 0.25), sweep 2 gives (0.5, 0, 0.25), sweep 3
# changes nothing and the solve stops. From one success to the next the optimal policy
# takes the completing cycle's 1 s, then V(0) = 0.5 s: 3600 / 1.5 = 2400 tasks per hour.


def hand_made_model() -> JointModel:
    world = World(TINY)
    dynamics = Dynamics(
        t_start=np.array([0, 1, 2, 2, 3], dtype=np.int64),  # pair 2 (completing) has no transition
        t_next=np.array([1, 2, 1], dtype=np.int64),
        t_prob=np.array([1.0, 1.0, 1.0]),
        t_tau=np.array([1.0, 0.25, 0.25]),
        regen_next=np.array([0], dtype=np.int64),
        regen_prob=np.array([1.0]),
        regen_tau=np.array([1.0]),
    )
    model = Model(
        packer=StatePacker(world),
        keys=np.arange(3, dtype=np.int64),  # labels only: the solve reads ids
        pair_start=np.array([0, 2, 3, 4], dtype=np.int64),
        pair_action=np.array([0, 1, 2, 3], dtype=np.int64),
        pair_terminal=np.array([False, False, True, False]),
        dynamics=[dynamics],
        n_layouts=1,
    )
    return JointModel.from_model(world, model, StopAtTheFirstSolveCheck())


class StopAtTheFirstSolveCheck(Budget):
    """A budget that fails the test if a solve reaches its first check (the 64th sweep)."""

    def __init__(self) -> None:
        super().__init__(None, None, None)

    def check(self, phase: str, done: int, total: int | None = None, unit: str = "states", **kw: Any) -> None:
        assert phase != "solve", f"the solve was still sweeping at sweep {done}"
        super().check(phase, done, total, unit, **kw)


def test_the_solve_stops_once_a_sweep_changes_nothing() -> None:
    model = hand_made_model()
    choice = model.optimal_policy(0)  # three sweeps, far below the budget's 64th-sweep check
    assert choice.tolist() == [1, 2, 3]  # the quicker route through state 2, the completing pair, the only pair
    assert model.rate(choice, 0) == pytest.approx(3600 / 1.5)


def test_a_solve_cut_short_is_greedy_on_the_values_of_its_sweeps() -> None:
    """With ``max_iterations`` sweeps the policy is greedy on those sweeps' values from 0."""
    model = hand_made_model()
    # after one sweep (0.25, 0, 0.25): pair 0 is 1 + V(1) = 1, pair 1 is 0.25 + V(2) = 0.5
    assert model.optimal_policy(0, max_iterations=1).tolist() == [1, 2, 3]
    # (a completing pair worth -1 s would make pair 0 look like 1 - 1 = 0 s after one sweep)
    # after two sweeps the values are exact, (0.5, 0, 0.25): pair 1 again
    assert model.optimal_policy(0, max_iterations=2).tolist() == [1, 2, 3]


# ---- the Python enumeration (the reference the array builder is tested against) ------------


def test_the_python_joint_model_gives_the_hand_worked_crossing_matrix() -> None:
    """The rates of ``tests/agents/test_headroom.py``'s docstring, read through the Python
    enumeration's own ``rate`` (each policy's transitions gathered pair by pair)."""
    world = World(CROSSING)
    model = JointModel(world, [stationary_human(spec, world) for spec in (G, C)])
    pi_g, pi_c = model.optimal_policy(0), model.optimal_policy(1)
    assert model.rate(pi_g, 0) == pytest.approx(3600 / 17.5)
    assert model.rate(pi_g, 1) == pytest.approx(3600 / 18)
    assert model.rate(pi_c, 0) == 0.0
    assert model.rate(pi_c, 1) == pytest.approx(3600 / 8)


def test_a_pairs_transitions_are_the_live_cycle_after_that_robot_action() -> None:
    """Each pair's transitions are the live cycle's: the robot's half, what the human sees
    of it (:func:`~hg_marl.core.cycle.seen`: nothing, -1, after a failed action; a human that
    does not read the robot's action is always told -1), the human's answers and halves, and
    a cycle as long as the longer action. ``noisy`` reads the robot's action (its answer
    weighs the cycle's length), ``G`` does not; the failed robot action is one of the options."""
    world = World(CROSSING)
    humans = [stationary_human(spec, world) for spec in ("noisy", G)]
    model = JointModel(world, humans, failed_actions=True)
    failed = 0
    for pair in range(model.n_pairs):
        state, action = model.states[int(model.pair_state[pair])], int(model.actions[pair])
        robot = half(world, state, Agent.ROBOT, action)
        failed += not robot.ok
        assert bool(model.terminal[pair]) == (robot.reward > 0)
        for i, human in enumerate(humans):
            told = seen(action, robot.ok) if human.uses_robot_action else -1
            expected = []
            if not robot.reward:
                for h, p in human.distribution(world, robot.state, told):
                    if p > 0.0:
                        answer = half(world, robot.state, Agent.HUMAN, h)
                        expected.append((answer.state, p, max(robot.duration, answer.duration)))
            _, nxt, prob, tau = model.arrays(i)
            rows = np.flatnonzero(model.arrays(i)[0] == pair)
            got = [(model.states[int(nxt[k])], float(prob[k]), float(tau[k])) for k in rows]
            assert got == expected, (pair, i)
    assert failed > 0  # the failed actions are checked too
    wait = world.table.wait[Agent.ROBOT]
    for i, human in enumerate(humans):  # the re-draw: the completing wait succeeded, then the first answer
        told = seen(wait, True) if human.uses_robot_action else -1
        expected = []
        for state, q in layout_distribution(world):
            for h, p in human.distribution(world, state, told):
                if p > 0.0:
                    answer = half(world, state, Agent.HUMAN, h)
                    expected.append((answer.state, q * p, max(world.durations.wait, answer.duration)))
        chain = model.chain(i)
        got = [
            (model.states[int(k)], p, tau)
            for k, p, tau in zip(chain.regen_next, chain.regen_prob.tolist(), chain.regen_tau.tolist(), strict=True)
        ]
        assert got == expected, i


# ---- what the headroom keeps --------------------------------------------------------------


def test_the_headroom_model_keeps_no_partner_transitions(monkeypatch: pytest.MonkeyPatch) -> None:
    """The matrix's joint model leaves each partner's transitions in its answer table (read
    when asked): a model of many partners would not fit in memory otherwise."""
    import hg_marl.agents.headroom as module

    built: list[Model] = []

    def spy(*args: Any, **kwargs: Any) -> Model:
        built.append(build_model(*args, **kwargs))
        return built[-1]

    monkeypatch.setattr(module, "build_model", spy)
    result = headroom(CROSSING, [("G", G), ("C", C)])
    np.testing.assert_allclose(result.optimum, [3600 / 17.5, 3600 / 8])  # the same matrix
    (model,) = built
    assert model.dynamics == [] and model.lazy is not None


class ExploreSpy(SpyBudget):
    """Also records the Python enumeration's explore readings: (states explored, memory read)."""

    def __init__(self) -> None:
        super().__init__()
        self.explore_checks: list[tuple[int, bool]] = []

    def check(self, phase: str, done: int, total: int | None = None, unit: str = "states", **kw: Any) -> None:
        if phase == "explore":
            self.explore_checks.append((done, bool(kw.get("memory", False))))
        super().check(phase, done, total, unit, **kw)


class BarSpy:
    """A stand-in progress bar that records its count after each update."""

    counts: ClassVar[list[int]] = []

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self.n = 0
        BarSpy.counts = []

    def update(self, k: int) -> None:
        self.n += k
        BarSpy.counts.append(self.n)

    def close(self) -> None:
        pass


def test_the_python_enumeration_reads_the_budget_per_state_memory_every_2048_and_shows_every_64th(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Stated, not read from the code: one budget reading before each state is explored,
    # the resident memory at states 0, 2048, 4096, ...; the bar moves at every 64th state
    # and once more at the end with the whole count.
    import hg_marl.agents.headroom as module

    monkeypatch.setattr(module, "tqdm", BarSpy)
    world = World("asymmetric_advantages")
    budget = ExploreSpy()
    model = JointModel(world, [stationary_human("random", world)], budget=budget)
    n = model.n
    assert n > 4096  # enough states for three memory readings
    assert budget.explore_checks == [(k, k % 2048 == 0) for k in range(n)]
    assert BarSpy.counts == [*range(0, n, 64), n]
