"""Exact values of each MetaController criterion after a known sequence of decisions.

Every expected number is worked by hand in the comments (filtered vectors written out,
entropies from ``H = -sum p log2 p`` over ``log2 |A|``, normal-table values for VPI), so
a wrong filter rate, a swapped filter term, a wrong best/second-best action in VPI or a
wrong reward-rate step changes a number here. Four actions keep the arithmetic short.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.meta import Criterion, Expert, HabitView, MetaController, PlanProposal
from hg_marl.agents.meta.vpi import vpi

N = 4


def h_norm(p: list[float]) -> float:
    """Reference normalised entropy (bits over log2 N), written independently of the code."""
    return -sum(x * math.log2(x) for x in p if x > 0) / math.log2(len(p))


# The planner's distribution around one action, 4 actions, eps = 0.01: 1 - 3 * 0.01 = 0.97.
# H = 0.97 * log2(1/0.97) + 3 * 0.01 * log2(100) = 0.042625 + 0.199316 = 0.241940 bits;
# normalised: / log2(4) = 0.120970.
H_PLANNER = 0.120970


def view(probs: list[float], key: bytes = b"A", cost: float = 1e-3, amplitude: float = 0.0, **kw: Any) -> HabitView:
    p = np.array(probs, dtype=float)
    q = np.asarray(kw.get("q", np.zeros(N)), dtype=float)
    sd = np.asarray(kw.get("sd", np.ones(N)), dtype=float)
    visits = int(kw.get("visits", 10**6))  # default: a well-visited state (the visit gate is tested apart)
    return HabitView(
        key=key, probs=p, action=int(p.argmax()), q=q, sd=sd, weight_amplitude=amplitude, cost=cost, visits=visits
    )


def proposal(action: int, cost: float = 0.2) -> PlanProposal:
    return PlanProposal.make(action, N, cost, nodes=10)


def controller(name: str, **params: float) -> MetaController:
    mc = MetaController(name, **params)
    mc.reset(np.random.default_rng(0))
    return mc


def never() -> PlanProposal:
    raise AssertionError("the planner must not be consulted for this decision")


def test_reference_entropy_of_planner_distribution() -> None:
    assert h_norm([0.97, 0.01, 0.01, 0.01]) == pytest.approx(H_PLANNER, abs=1e-6)


def test_entropy_filter_values_after_a_sequence() -> None:
    """rate 0.75: p <- 0.25 p + 0.75 p_new per state; the lower filtered entropy wins."""
    mc = controller("entropy", rate=0.75)

    # 1. state A, first visit: filters start at the first vectors.
    #    habit [1,0,0,0]: H = 0; planner (action 0): 0.120970 -> habit.
    d = mc.decide(view([1, 0, 0, 0]), proposal(0))
    assert d.stats["h_habit"] == pytest.approx(0.0)
    assert d.stats["h_planner"] == pytest.approx(H_PLANNER, abs=1e-6)
    assert d.expert is Expert.HABIT

    # 2. state A: habit [0,1,0,0] -> 0.25*[1,0,0,0] + 0.75*[0,1,0,0] = [0.25, 0.75, 0, 0]
    #    H = 0.25*2 + 0.75*log2(4/3) = 0.5 + 0.311278 = 0.811278 bits -> 0.405639.
    #    planner action 1 -> 0.25*[.97,.01,.01,.01] + 0.75*[.01,.97,.01,.01] = [0.25, 0.73, 0.01, 0.01]
    #    H = 0.5 + 0.73*log2(1/0.73) + 0.02*log2(100) = 0.5 + 0.331443 + 0.132877 = 0.964320 -> 0.482160.
    d = mc.decide(view([0, 1, 0, 0]), proposal(1))
    assert d.stats["h_habit"] == pytest.approx(0.405639, abs=1e-6)
    assert d.stats["h_planner"] == pytest.approx(0.482160, abs=1e-6)
    assert d.expert is Expert.HABIT and d.action == 1

    # 3. another state B has its own (fresh) filters: habit [0.5,0.5,0,0] -> H = 1 bit -> 0.5.
    d = mc.decide(view([0.5, 0.5, 0, 0], key=b"B"), proposal(2))
    assert d.stats["h_habit"] == pytest.approx(0.5)
    assert d.stats["h_planner"] == pytest.approx(H_PLANNER, abs=1e-6)
    assert d.expert is Expert.PLANNER and d.action == 2

    # 4. state A: habit [0,0,.5,.5] -> 0.25*[.25,.75,0,0] + 0.75*[0,0,.5,.5] = [0.0625, 0.1875, 0.375, 0.375]
    #    H = 0.0625*4 + 0.1875*log2(1/0.1875) + 0.75*log2(1/0.375)
    #      = 0.25 + 0.452820 + 1.061278 = 1.764098 bits -> 0.882049.
    #    planner action 1 -> 0.25*[.25,.73,.01,.01] + 0.75*[.01,.97,.01,.01] = [0.07, 0.91, 0.01, 0.01]
    #    H = 0.07*log2(1/0.07) + 0.91*log2(1/0.91) + 0.132877 = 0.268555 + 0.123816 + 0.132877 = 0.525248 -> 0.262624.
    d = mc.decide(view([0, 0, 0.5, 0.5]), proposal(1))
    assert d.stats["h_habit"] == pytest.approx(0.882049, abs=1e-6)
    assert d.stats["h_planner"] == pytest.approx(0.262624, abs=1e-6)
    assert d.expert is Expert.PLANNER and d.action == 1
    # cross-check the hand arithmetic with the reference entropy
    assert h_norm([0.0625, 0.1875, 0.375, 0.375]) == pytest.approx(0.882049, abs=1e-6)
    assert h_norm([0.07, 0.91, 0.01, 0.01]) == pytest.approx(0.262624, abs=1e-6)


def test_entropy_and_cost_values_after_a_sequence() -> None:
    """kappa 1, rate 0.75; values -(H_i + exp(-H_MF bits) * t_i), larger wins."""
    mc = controller("entropy_and_cost", kappa=1.0, rate=0.75)
    consulted: list[float] = []

    def planner(cost: float, action: int) -> PlanProposal:
        consulted.append(cost)
        return proposal(action, cost)

    # 1. state A: habit [.5,.5,0,0] (H 1 bit -> 0.5), cost 1 ms. No planning yet: planner cost 0,
    #    its distribution the canonical one (0.120970). scale = max(0.001, 0) -> t_habit 1, t_planner 0.
    #    weight exp(-1) = 0.367879: v_habit = -(0.5 + 0.367879) = -0.867879, v_planner = -0.120970.
    d = mc.decide(view([0.5, 0.5, 0, 0]), lambda: planner(0.2, 2))
    assert d.expert is Expert.PLANNER and consulted == [0.2]
    assert (d.stats["t_habit"], d.stats["t_planner"]) == (1.0, 0.0)
    assert d.stats["value_habit"] == pytest.approx(-0.867879, abs=1e-6)
    assert d.stats["value_planner"] == pytest.approx(-H_PLANNER, abs=1e-6)
    # the planner's cost over all states: 0.25*0 + 0.75*0.2 = 0.15

    # 2. state B (new): habit [1,0,0,0] (H 0, weight 1); the planner's cost here is its all-states
    #    cost 0.15: t_habit = 0.001/0.15, t_planner = 1. v_habit = -0.006667 > v_planner = -1.120970.
    d = mc.decide(view([1, 0, 0, 0], key=b"B"), never)
    assert d.expert is Expert.HABIT
    assert d.stats["t_habit"] == pytest.approx(0.001 / 0.15)
    assert d.stats["t_planner"] == pytest.approx(1.0)
    assert d.stats["value_planner"] == pytest.approx(-(H_PLANNER + 1.0), abs=1e-6)

    # 3. state A: habit [0,0,1,0] -> 0.25*[.5,.5,0,0] + 0.75*[0,0,1,0] = [0.125, 0.125, 0.75, 0]
    #    H = 0.25*3 + 0.75*log2(4/3) = 0.75 + 0.311278 = 1.061278 bits -> 0.530639;
    #    weight exp(-1.061278) = 0.367879 * 0.940562 = 0.346013.
    #    habit cost filter 0.001; planner cost in A 0.2 (its filter there): t_habit 0.005, t_planner 1.
    #    planner's filtered distribution in A: [.01,.01,.97,.01] -> 0.120970.
    #    v_habit = -(0.530639 + 0.346013*0.005) = -0.532369; v_planner = -(0.120970 + 0.346013) = -0.466983.
    d = mc.decide(view([0, 0, 1, 0]), lambda: planner(0.4, 2))
    assert d.expert is Expert.PLANNER and consulted == [0.2, 0.4]
    assert d.stats["h_habit"] == pytest.approx(0.530639, abs=1e-6)
    assert d.stats["t_habit"] == pytest.approx(0.005)
    assert d.stats["value_habit"] == pytest.approx(-0.532369, abs=1e-6)
    assert d.stats["value_planner"] == pytest.approx(-0.466983, abs=2e-6)
    # all-states planner cost: 0.25*0.15 + 0.75*0.4 = 0.3375

    # 4. state C (new): habit [1,0,0,0]: t_habit = 0.001/0.3375 (the all-states filter, not the last cost).
    d = mc.decide(view([1, 0, 0, 0], key=b"C"), never)
    assert d.expert is Expert.HABIT
    assert d.stats["t_habit"] == pytest.approx(0.001 / 0.3375)


# Standard normal table: Phi(-1) = 0.158655, phi(1) = 0.241971, Phi(-2) = 0.022750,
# phi(2) = 0.053991, phi(0) = 1/sqrt(2 pi) = 0.398942. g(d, s) = d Phi(d/s) + s phi(d/s).
G_MINUS1_1 = -0.158655 + 0.241971  # g(-1, 1) = 0.083316
G_MINUS2_1 = -2 * 0.022750 + 0.053991  # g(-2, 1) = 0.008491


def test_vpi_values_by_hand() -> None:
    # q ties at the top: a1 = 0 (first), a2 = 1. VPI(a1) = g(q2 - q1, sd1) = g(0, 0.5) = 0.5 * 0.398942;
    # VPI(1) = g(1 - 1, 2) = 2 * 0.398942; VPI(2) = g(0 - 1, 1); VPI(3) = max(0 - 1, 0) = 0 (sd 0).
    v = vpi(np.array([1.0, 1.0, 0.0, 0.0]), np.array([0.5, 2.0, 1.0, 0.0]))
    assert v == pytest.approx([0.199471, 0.797885, G_MINUS1_1, 0.0], abs=1e-5)
    # best action not first: q = [0, 2, 1], a1 = 1, a2 = 2, all sd 1.
    # VPI(1) = g(1 - 2, 1); VPI(0) = g(0 - 2, 1); VPI(2) = g(1 - 2, 1).
    v = vpi(np.array([0.0, 2.0, 1.0]), np.ones(3))
    assert v == pytest.approx([G_MINUS2_1, G_MINUS1_1, G_MINUS1_1], abs=1e-5)
    # the best action's own uncertainty is what counts for it: sd of a1 = 0 -> max(q2 - q1, 0) = 0
    v = vpi(np.array([0.0, 2.0, 1.0]), np.array([1.0, 0.0, 1.0]))
    assert v[1] == 0.0 and v[0] == pytest.approx(G_MINUS2_1, abs=1e-5)


def test_vpi_reward_rate_and_threshold_after_a_sequence() -> None:
    mc = controller("vpi", tau=0.5, rate_step=0.25)
    # R <- R + 0.25 (r - R): 1 -> 0.25; 1 -> 0.4375; 0 -> 0.328125. Threshold tau R = 0.1640625.
    for r in (1.0, 1.0, 0.0):
        mc.observe(r)
    q = [1.0, 1.0, 0.0, 0.0]
    # sd 0.4 on the two tied actions: max VPI = 0.4 * 0.398942 = 0.159577 < 0.1640625 -> habit, no plan.
    d = mc.decide(view([0.25] * 4, q=q, sd=[0.4, 0.4, 0.0, 0.0]), never)
    assert d.expert is Expert.HABIT
    assert d.stats["reward_rate"] == pytest.approx(0.328125)
    assert d.stats["threshold"] == pytest.approx(0.1640625)
    assert d.stats["vpi"] == pytest.approx(0.159577, abs=1e-6)
    # sd 0.42: 0.42 * 0.398942 = 0.167556 > 0.1640625 -> plan, and the plan is executed.
    d = mc.decide(view([0.25] * 4, q=q, sd=[0.42, 0.42, 0.0, 0.0]), proposal(3))
    assert d.expert is Expert.PLANNER and d.action == 3
    assert d.stats["vpi"] == pytest.approx(0.167556, abs=1e-6)


def test_vpi_zero_gain_never_plans_even_at_zero_threshold() -> None:
    mc = controller("vpi")
    # no uncertainty: every VPI is 0, the threshold is 0 (no reward yet): 0 > 0 is false.
    d = mc.decide(view([0.25] * 4, q=[1.0, 0.5, 0.0, 0.0], sd=[0.0] * 4), never)
    assert d.expert is Expert.HABIT and d.stats["vpi"] == 0.0 and d.stats["threshold"] == 0.0


def test_learning_state_acts_where_the_proposed_actions_td_error_has_settled() -> None:
    """Habit iff RMS TD error of its proposed action in this state < threshold (0.5)."""
    mc = controller("learning_state", threshold=0.5)
    # proposed action 1 (argmax); its sd 0.4 < 0.5: habit, whatever the other actions' sd.
    d = mc.decide(view([0.1, 0.7, 0.1, 0.1], sd=[0.9, 0.4, 0.9, 0.9]), never)
    assert d.expert is Expert.HABIT and d.action == 1 and d.stats["td_rms"] == pytest.approx(0.4)
    # exactly at the threshold is not settled: 0.5 < 0.5 is false.
    d = mc.decide(view([0.1, 0.7, 0.1, 0.1], sd=[0.0, 0.5, 0.0, 0.0]), proposal(3))
    assert d.expert is Expert.PLANNER and d.action == 3 and d.stats["td_rms"] == pytest.approx(0.5)
    # the weight amplitude plays no part any more (it drifted like 1/t: see the module's docstring).
    d = mc.decide(view([0.1, 0.7, 0.1, 0.1], sd=[0.0, 0.1, 0.0, 0.0], amplitude=1e9), never)
    assert d.expert is Expert.HABIT


def test_learned_criteria_defer_to_the_planner_in_states_the_habit_has_not_learnt() -> None:
    # min_visits 3: with 2 TD updates from this state the planner acts (reason habit_untrained)
    # even though the habit is sharp and settled there; with 3 the criterion decides.
    for name in ("entropy", "entropy_and_cost", "vpi", "learning_state"):
        mc = controller(name, min_visits=3)
        sharp = dict(sd=[0.0] * 4, q=[1.0, 0.0, 0.0, 0.0])
        d = mc.decide(view([1, 0, 0, 0], visits=2, **sharp), proposal(2))
        assert (d.expert, d.action, d.reason) == (Expert.PLANNER, 2, "habit_untrained"), name
        # with 3 the criterion decides: a sharp, settled, certain habit wins under entropy, vpi
        # and learning_state (the last two do not even ask the planner: reason habit_only);
        # entropy_and_cost's first decision knows no planner cost yet (0), so the planner wins.
        d = mc.decide(view([1, 0, 0, 0], visits=3, **sharp), lambda: proposal(2))
        expected = Expert.PLANNER if name == "entropy_and_cost" else Expert.HABIT
        assert d.expert is expected and d.reason != "habit_untrained", name


def test_cost_model_constants_and_validation() -> None:
    from hg_marl.agents.meta import CostModel

    model = CostModel()  # documented defaults: habit 1 ms; planner 50 ms + 0.5 ms per node
    assert model.habit_cost(wall_time=7.0) == 0.001
    assert model.planner_cost(0) == pytest.approx(0.05)
    assert model.planner_cost(200, wall_time=7.0) == pytest.approx(0.15)
    wall = CostModel(mode="wall")
    assert wall.habit_cost(wall_time=0.3) == 0.3 and wall.planner_cost(200, wall_time=0.4) == 0.4
    assert CostModel(habit=0.0, planner_base=0.0, planner_per_node=0.0).planner_cost(10) == 0.0
    for name in ("habit", "planner_base", "planner_per_node"):
        with pytest.raises(ValueError, match=f"CostModel.{name}"):
            CostModel(**{name: -1e-9})  # type: ignore[arg-type]


def test_controller_record_and_reasons() -> None:
    mc = controller("planner")
    d = mc.decide(view([0.25] * 4), proposal(2))
    assert d.reason == "criterion"
    assert (d.record["expert"], d.record["action"], d.record["reason"]) == ("planner", 2, "criterion")
    failed = PlanProposal.make(2, N, 0.1, success=False)
    d = mc.decide(view([0.7, 0.1, 0.1, 0.1]), failed)
    assert (d.expert, d.action, d.reason, d.plan) == (Expert.HABIT, 0, "planner_failed", failed)
    d = mc.decide(view([0.7, 0.1, 0.1, 0.1]), None)
    assert (d.expert, d.action, d.reason, d.plan) == (Expert.HABIT, 0, "habit_only", None)


class _AlwaysHabit(Criterion):
    """Consults the planner every decision, then always picks the habit."""

    name = "always_habit"

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        return Expert.HABIT


def test_criterion_choosing_the_habit_over_a_successful_plan_executes_the_habits_action() -> None:
    # the habit's greedy action is 0, the plan's is 2: the criterion's pick decides which runs
    mc = MetaController(_AlwaysHabit())
    mc.reset(np.random.default_rng(0))
    d = mc.decide(view([0.7, 0.1, 0.1, 0.1]), proposal(2))
    assert (d.expert, d.action, d.reason) == (Expert.HABIT, 0, "criterion")
    assert d.plan is not None and d.plan.action == 2
