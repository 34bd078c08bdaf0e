"""The observed partner's two rules for partners who rest: a pause is not an answer, and its
best response is played only where the partner was seen (``agents/observed_partner.py``,
``agents/robots/belief.py``)."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.family_out import Bursts
from hg_marl.agents.observed_partner import ObservedPartner, ObservedSolver
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, State, World
from hg_marl.training.runner import RunConfig, run
from hg_marl.training.study import load_study
from tests.agents.test_observed_partner import HARD, LastFirst, first_state


def _first_key() -> tuple[World, State, int, int, int, int]:
    """The first table's key for the robot's wait: its world, mid-cycle state, the robot's wait,
    the number of the human's feasible answers, the human's wait and one answer that is not."""
    world = World("forced_coordination")
    mid, wait_r, feasible = first_state(world)
    wait_h = world.n_actions(Agent.HUMAN) - 1
    return world, mid, wait_r, len(feasible), wait_h, next(h for h in feasible if h != wait_h)


def test_a_wait_where_the_partner_did_something_else_is_a_pause_and_not_counted() -> None:
    world, mid, wait_r, n, wait_h, act = _first_key()
    model = ObservedPartner(weight=0.5, forget=0.8)  # no base: uniform over the n feasible answers
    model.update(world, mid, wait_r, act)
    version, observations, repeats = model.version, model.observations, model.repeats
    # Three waits there: pauses. The counts stay {act: 1}: p(act) = (1 + 0.5 / n) / 1.5.
    for _ in range(3):
        model.update(world, mid, wait_r, wait_h)
    assert model.counts[(mid, wait_r)] == {act: 1.0}
    assert model.predict(world, mid, wait_r, act) == pytest.approx((1 + 0.5 / n) / 1.5)
    assert model.predict(world, mid, wait_r, wait_h) == pytest.approx((0.5 / n) / 1.5)
    # Nothing changed: no surprise (no solve again), no expansion dropped, no repeat counted.
    assert (model.version, model.observations, model.repeats) == (version, observations, repeats)
    # The action again is counted as before: 0.8 + 1.
    model.update(world, mid, wait_r, act)
    assert model.counts[(mid, wait_r)] == pytest.approx({act: 1.8})


def test_a_wait_where_the_partner_only_ever_waited_is_its_answer() -> None:
    """A partner who waits whenever the robot waits (a mirror) is learnt: its waits are answers."""
    world, mid, wait_r, n, wait_h, act = _first_key()
    model = ObservedPartner(weight=0.5, forget=0.8)  # no base: uniform over the n feasible answers
    model.update(world, mid, wait_r, wait_h)
    model.update(world, mid, wait_r, wait_h)
    assert model.counts[(mid, wait_r)] == pytest.approx({wait_h: 1.8})  # 1 * 0.8 + 1
    # An action after the waits is counted (and the waits kept, forgotten once more).
    model.update(world, mid, wait_r, act)
    assert model.counts[(mid, wait_r)] == pytest.approx({wait_h: 1.44, act: 1.0})
    assert model.predict(world, mid, wait_r, act) == pytest.approx((1 + 0.5 / n) / 2.94)
    # From now on a wait there is a pause.
    model.update(world, mid, wait_r, wait_h)
    assert model.counts[(mid, wait_r)] == pytest.approx({wait_h: 1.44, act: 1.0})


def test_seen_at_is_true_only_at_a_state_one_of_whose_moves_the_partner_answered() -> None:
    world = World("forced_coordination")
    state = world.initial_state(np.random.default_rng(0))
    partner = ObservedPartner()
    assert not partner.seen_at(world, state)  # nothing seen yet
    wait_r, wait_h = world.n_actions(Agent.ROBOT) - 1, world.n_actions(Agent.HUMAN) - 1
    mid = world.step(state, Agent.ROBOT, wait_r).state
    partner.update(world, mid, wait_r, wait_h)  # the partner answered the robot's wait here
    assert partner.seen_at(world, state)
    other = world.initial_state(np.random.default_rng(1))
    assert other != state
    assert not partner.seen_at(world, other)  # another table: never seen there
    # The key is (mid-cycle state, move): an answer counted at the state the wait leads to,
    # under another move of the robot, is not an answer to that move made from `state`.
    move = next(a for a in world.feasible_indices(state, Agent.ROBOT) if a != wait_r)
    assert world.table.successor(state, Agent.ROBOT, move)[0] != mid
    fresh = ObservedPartner()
    fresh.update(world, mid, move, wait_h)
    assert not fresh.seen_at(world, state)


def test_the_exact_best_response_is_played_only_where_the_partner_was_seen(monkeypatch: pytest.MonkeyPatch) -> None:
    """Where the partner never answered any of the robot's moves, the observed model is only its
    base member, a member that explains the partner worse than the model does: the planner
    drives there, and the observed model is solved only at states it has seen."""
    seen: list[bool] = []
    real = ObservedSolver.q_values

    def recorded(self: ObservedSolver, world: World, state: Any, partner: ObservedPartner, *args: Any) -> Any:
        feasible = world.feasible_indices(state, Agent.ROBOT)
        seen.append(any((world.table.successor(state, Agent.ROBOT, a)[0], a) in partner.counts for a in feasible))
        return real(self, world, state, partner, *args)

    monkeypatch.setattr(ObservedSolver, "q_values", recorded)
    robot = make_robot("belief", population=HARD, open_world="observed")
    log = run(robot, LastFirst(), RunConfig(scenario="forced_coordination", duration=600.0, seed=0)).log
    reasons = log["reason"].astype(str)
    assert seen and all(seen)
    assert reasons.str.startswith("no member explains the partner: the exact best response").any()
    assert reasons.str.startswith("no member explains the partner, the planner drives").any()


def test_a_partner_back_from_a_rest_is_planned_for_as_it_worked() -> None:
    """``fo_bursts`` works 90 s and rests 60 s. Working, it puts what it holds on the counter
    unless the robot stands at the handover place, so the best plan never fetches a handover:
    the plain planner takes none. Counting the rests' waits as answers, the observed model
    learnt that the partner stops answering, and the robot went to fetch handovers (4 in this
    run before pauses were told apart); now it takes none, and solves what the planner solves."""
    config = RunConfig(scenario="forced_coordination", duration=1100.0, seed=0)
    planner = run(make_robot("planner"), Bursts(), config)
    observed = run(make_robot("belief", population=HARD, open_world="observed"), Bursts(), config)
    takes = [int(r.log["action_name"].astype(str).str.startswith("take").sum()) for r in (planner, observed)]
    assert takes == [0, 0]
    assert observed.summary["tasks_solved"] >= planner.summary["tasks_solved"]


def test_the_rests_study_runs_the_planner_and_the_observed_robot_over_25_spells() -> None:
    """``studies/family_out_rests.toml`` (docs/adaptation.md, section 11): every pair of work
    in 70, 80, ..., 110 s and rest in 40, 50, ..., 80 s, on both hard layouts, 3 seeds."""
    study = load_study("studies/family_out_rests.toml")
    assert study.scenarios == ("forced_coordination", "asymmetric_advantages")
    assert study.seeds == (0, 1, 2)
    assert [r.label for r in study.robots] == [
        "planner",
        "belief:open_world=observed,population=populations/hard_layouts.toml",
    ]
    spells = {(a.params["work"], a.params["rest"]) for a in study.humans if a.name == "fo_bursts"}
    assert spells == {(w, r) for w in range(70, 111, 10) for r in range(40, 81, 10)}
    assert len(study.humans) == 25
