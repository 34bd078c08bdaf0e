"""The partner model learned online: an estimate worked by hand, and evidence switching from the family to it."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.partner import PartnerPosterior
from hg_marl.agents.partner_model import LearnedPartner, partner_features
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import RobotError
from hg_marl.training.runner import RunConfig, run


def offered_state(world: World) -> tuple[State, int]:
    """A mid-cycle state where the robot offers an object, and the robot's give (robot moves only, breadth first)."""
    frontier = [world.initial_state(np.random.default_rng(0))]
    seen = set(frontier)
    for _ in range(6):
        nxt = []
        for state in frontier:
            for a in world.feasible_indices(state, Agent.ROBOT):
                after = world.step(state, Agent.ROBOT, a).state
                if world.actions(Agent.ROBOT)[a].kind is Kind.GIVE and after.offer_by == int(Agent.ROBOT):
                    return after, a
                if after.offer_by < 0 and after not in seen:
                    seen.add(after)
                    nxt.append(after)
        frontier = nxt
    raise AssertionError("no offer found")


def test_estimate_worked_by_hand_on_a_scripted_history() -> None:
    world = World("paper2015")
    mid, give = offered_state(world)
    acts = world.actions(Agent.HUMAN)
    feasible = world.feasible_indices(mid, Agent.HUMAN)
    kinds = {acts[i].kind for i in feasible}
    assert Kind.TAKE in kinds and Kind.WAIT in kinds
    wait = world.n_actions(Agent.HUMAN) - 1
    take = next(i for i in feasible if acts[i].kind is Kind.TAKE)
    n_take = sum(acts[i].kind is Kind.TAKE for i in feasible)
    k = len(kinds)
    model = LearnedPartner(alpha=1.0, forget=0.5)
    # No data: every feasible kind alike, alpha / (k alpha).
    assert model.predict(world, mid, give, take) == pytest.approx(1.0 / k / n_take)
    # History: wait, wait. Counts of wait: 1, then 0.5 * 1 + 1 = 1.5 (forget = 0.5).
    model.update(world, mid, give, wait)
    model.update(world, mid, give, wait)
    assert model.predict(world, mid, give, wait) == pytest.approx((1.5 + 1.0) / (1.5 + k))
    assert model.predict(world, mid, give, take) == pytest.approx(1.0 / (1.5 + k) / n_take)
    # Another context (the robot's action failed) has learnt nothing.
    assert model.predict(world, mid, -1, wait) == pytest.approx(1.0 / k)


def test_bad_settings_are_refused() -> None:
    for kwargs in ({"alpha": 0.0}, {"forget": 0.0}, {"forget": 1.5}, {"alpha": math.nan}):
        with pytest.raises(ValueError):
            LearnedPartner(**kwargs)


def test_evidence_switches_from_the_family_to_the_learned_model() -> None:
    """A partner who never takes (freezes while offered): members who take get refuted, the learned model wins."""
    world = World("paper2015")
    mid, give = offered_state(world)
    wait = world.n_actions(Agent.HUMAN) - 1
    learned = LearnedPartner()
    post = PartnerPosterior(
        types=("cooperative", "preference:accept=0.5", "learned"),
        prior=[0.475, 0.475, 0.05],
        decay=0.9,
        learned=learned,
    )
    assert post.posterior()["learned"] == pytest.approx(0.05)  # the family is trusted at first
    history = []
    for _ in range(12):
        post.observe(world, mid, give, wait)
        history.append(post.posterior()["learned"])
    # Each refusal: the member who accepts half the offers predicts it with about 0.5, the
    # learned model with (n + 1) / (n + k) after n refusals, which tends to 1: it overtakes.
    assert post.most_probable() == "learned"
    assert history[-1] > 0.9 and history[-1] > history[2]


def test_belief_robot_with_the_learned_model_runs_and_names_it() -> None:
    robot = make_robot("belief", population="populations/paper2015.toml", open_world="learned")
    log = run(robot, make_human("fo_freeze_on_offer"), RunConfig(duration=300, seed=0)).log
    assert len(log) > 20
    with pytest.raises(Exception, match="open_world"):
        make_robot("belief", population="populations/paper2015.toml", open_world="nope")


def test_refused_kinds_leave_the_planners_model() -> None:
    """Three refusals of an offer (forget 1: take feasible 3 times, done 0 times): take is refused."""
    world = World("paper2015")
    mid, give = offered_state(world)
    wait = world.n_actions(Agent.HUMAN) - 1
    model = LearnedPartner(forget=1.0)
    for n in range(3):
        assert Kind.TAKE not in model.refused_kinds()  # fewer than 3 chances: no verdict yet
        model.update(world, mid, give, wait)
        assert model.chances[int(Kind.TAKE)] == n + 1 and model.taken[int(Kind.TAKE)] == 0
    assert Kind.TAKE in model.refused_kinds()
    assert Kind.WAIT not in model.refused_kinds()
    assert Kind.TAKE not in model.planner_model().allowed_kinds
    assert Kind.THROW in model.planner_model().allowed_kinds


def test_partner_features_are_the_take_and_give_verdicts() -> None:
    world = World("paper2015")
    mid, give = offered_state(world)
    wait = world.n_actions(Agent.HUMAN) - 1
    model = LearnedPartner(forget=1.0)
    assert partner_features(model).tolist() == [0, 0]
    for _ in range(3):
        model.update(world, mid, give, wait)
    assert partner_features(model).tolist() == [1, 0]  # refuses to take; giving was never possible


def test_hybrid_habit_reads_the_partner_models_verdicts() -> None:
    robot = make_robot("hybrid", partner_features=True)
    run(robot, make_human("lazy:p_idle=0.3"), RunConfig(duration=300, seed=0))
    model = robot.partner_model
    assert model is not None and sum(model.chances.values()) > 0  # it learnt from the partner's moves
    n = World("paper2015").n_facts
    assert robot.habit.n_facts == n + 2
    codes = [bytes(k) for k in robot.habit._codes]
    assert codes and all(len(c) == n + 2 for c in codes)
    plain = make_robot("hybrid")
    run(plain, make_human("lazy:p_idle=0.3"), RunConfig(duration=300, seed=0))
    assert plain.partner_model is None and plain.habit.n_facts == n


def test_a_kind_done_once_is_not_refused_until_it_leaves_the_memory() -> None:
    """One take, then refusals (forget 0.95). After 30 refusals take's share is
    0.95**30 / ((1 - 0.95**31) / 0.05) = 0.215 / 15.9, about 1.4%: done late, not never, so
    not refused (a share of 10% once refused it). After 400 refusals the take weighs
    0.95**400 = 1.2e-9 of about 20 chances: under 1e-9 of them, refused."""
    world = World("paper2015")
    mid, give = offered_state(world)
    wait = world.n_actions(Agent.HUMAN) - 1
    take = next(i for i in world.feasible_indices(mid, Agent.HUMAN) if world.actions(Agent.HUMAN)[i].kind is Kind.TAKE)
    model = LearnedPartner(forget=0.95)
    model.update(world, mid, give, take)
    for _ in range(30):
        model.update(world, mid, give, wait)
    share = model.taken[int(Kind.TAKE)] / model.chances[int(Kind.TAKE)]
    assert share == pytest.approx(0.95**30 / ((1 - 0.95**31) / 0.05), rel=1e-9)
    assert Kind.TAKE not in model.refused_kinds()
    assert Kind.TAKE in model.refused_kinds(below=0.1)  # the former verdict
    for _ in range(370):
        model.update(world, mid, give, wait)
    assert Kind.TAKE in model.refused_kinds()


def test_a_learned_model_that_leaves_nothing_clearable_is_not_planned_with() -> None:
    """On forced_coordination every tape starts where only the human reaches, and it crosses
    by a handover (give) or by placing it on the counter (place). A learned model without
    give and place therefore clears nothing from the first table; the cooperative model does."""
    world = World("forced_coordination")
    robot = make_robot("belief", population="populations/hard_layouts.toml", open_world="learned")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    learned = robot.posterior.learned
    learned.chances = {int(Kind.GIVE): 5.0, int(Kind.PLACE): 5.0}  # five chances each, never taken
    model = learned.planner_model()
    assert {Kind.GIVE, Kind.PLACE} <= learned.refused_kinds() and Kind.GIVE not in model.allowed_kinds
    state = world.initial_state(np.random.default_rng(0))
    assert not robot._clears(world, model, state)
    assert robot._clears(world, robot._planner.partnering.fixed, state)


def test_the_learned_robot_keeps_up_with_the_planner_against_a_forgetful_partner() -> None:
    """fo_forgetful on asymmetric_advantages (seed 0, 1100 s): the learned model once refused
    the partner's late placing and throwing, and the robot planned with a model under which
    nothing could be cleared (12 tasks where the planner solves 16). Planning with the fixed
    model there, it solves at least as many as the planner."""
    config = RunConfig(scenario="asymmetric_advantages", duration=1100.0, seed=0)
    planner = run(make_robot("planner"), make_human("fo_forgetful"), config).summary["tasks_solved"]
    robot = make_robot("belief", population="populations/hard_layouts.toml", open_world="learned")
    learned = run(robot, make_human("fo_forgetful"), config).summary["tasks_solved"]
    assert planner == 16 and learned >= planner


def test_a_kind_done_once_250_chances_ago_is_still_not_refused() -> None:
    """One pick, then 250 waits (forget 0.95): the pick weighs 0.95**250 = 2.7e-6 of about 20
    chances, a share of 1.4e-7: above 1e-9, so not refused; after 350 waits (0.95**350 / 20,
    about 8e-10) it is."""
    world = World("forced_coordination")
    state = world.initial_state(np.random.default_rng(0))
    acts = world.actions(Agent.HUMAN)
    pick = next(i for i in world.feasible_indices(state, Agent.HUMAN) if acts[i].kind is Kind.PICK)
    wait = world.n_actions(Agent.HUMAN) - 1
    model = LearnedPartner()
    model.update(world, state, -1, pick)
    for _ in range(250):
        model.update(world, state, -1, wait)
    share = model.taken[int(Kind.PICK)] / model.chances[int(Kind.PICK)]
    assert share == pytest.approx(0.95**250 / ((1 - 0.95**251) / 0.05), rel=1e-9)
    assert Kind.PICK not in model.refused_kinds() and Kind.PICK in model.planner_model().allowed_kinds
    for _ in range(100):
        model.update(world, state, -1, wait)
    assert Kind.PICK in model.refused_kinds()


def test_each_learned_model_gets_its_own_verdict() -> None:
    """On forced_coordination the tapes start where only the human reaches: without the
    human's pick nothing crosses, with every kind it does. Asked in turn, the same robot
    answers each model for itself."""
    from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman

    world = World("forced_coordination")
    robot = make_robot("belief", population="populations/hard_layouts.toml", open_world="learned")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    assert robot._clears(world, RestrictedHuman("learned", HUMAN_KINDS), state)
    assert not robot._clears(world, RestrictedHuman("learned", HUMAN_KINDS - {Kind.PICK}), state)


def test_the_fallback_is_the_fixed_model_even_after_a_learned_one(monkeypatch: pytest.MonkeyPatch) -> None:
    """Off the population, turn 1's learned model (no throw: the human never throws on
    forced_coordination anyway) clears and is planned with; turn 2's (no pick) clears
    nothing, so the robot plans with the fixed cooperative model, not turn 1's."""
    from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman
    from hg_marl.policy import Turn

    world = World("forced_coordination")
    robot = make_robot("belief", population="populations/hard_layouts.toml", open_world="learned")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    names = [*robot.member_specs, robot.posterior.learned.name]
    monkeypatch.setattr(robot.posterior, "posterior", lambda: {n: float(n == "learned") for n in names})
    state = world.initial_state(np.random.default_rng(0))
    partnering = robot._planner.partnering
    for dropped in (Kind.THROW, Kind.PICK):
        model = RestrictedHuman("learned", HUMAN_KINDS - {dropped})
        monkeypatch.setattr(robot.posterior.learned, "planner_model", lambda m=model: m)
        robot.act(Turn(world, state, Agent.ROBOT, {}))
        if dropped is Kind.THROW:
            assert partnering.base is model
    assert partnering.base is partnering.fixed and Kind.PICK in partnering.fixed.allowed_kinds


def test_the_fixed_model_is_the_one_the_planner_was_built_with() -> None:
    from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman
    from hg_marl.agents.robots.planner import PlannerRobot

    model = RestrictedHuman("no_handover", HUMAN_KINDS - {Kind.GIVE, Kind.TAKE})
    robot = PlannerRobot(human_model=model)
    robot.reset(World("forced_coordination"), Agent.ROBOT, np.random.default_rng(0))
    assert robot.partnering.fixed is model and robot.partnering.base is model


def test_where_neither_model_clears_the_table_the_learned_one_is_kept(monkeypatch: pytest.MonkeyPatch) -> None:
    """The fixed model replaces the learned one only where it can clear and the learned one
    cannot: where neither finds a plan (both checks answer no here), the fixed model has no
    better claim and the robot plans as the partner behaves."""
    from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman
    from hg_marl.policy import Turn

    world = World("forced_coordination")
    robot = make_robot("belief", population="populations/hard_layouts.toml", open_world="learned")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    names = [*robot.member_specs, robot.posterior.learned.name]
    monkeypatch.setattr(robot.posterior, "posterior", lambda: {n: float(n == "learned") for n in names})
    model = RestrictedHuman("learned", HUMAN_KINDS - {Kind.THROW})
    monkeypatch.setattr(robot.posterior.learned, "planner_model", lambda: model)
    asked: list[object] = []
    monkeypatch.setattr(robot, "_clears", lambda w, m, s: asked.append(m) is not None)  # always False
    robot.act(Turn(world, world.initial_state(np.random.default_rng(0)), Agent.ROBOT, {}))
    partnering = robot._planner.partnering
    assert len(asked) == 2  # the learned model, then the fixed one
    assert partnering.base is model and partnering.base is not partnering.fixed


@pytest.mark.parametrize(("factor", "off_population"), [(1.0, True), (4.9, True), (5.1, False), (10.0, False)])
def test_the_learned_partner_drives_only_when_bayes_factor_times_as_probable_as_the_best_member(
    monkeypatch: pytest.MonkeyPatch, factor: float, off_population: bool
) -> None:
    """The learned hypothesis at 0.6, the best member at 0.12 (five times less), the other
    members sharing 0.28: with a Bayes factor under 5 the planner drives on the learned
    model; above 5 the best member's best response is played."""
    from hg_marl.policy import Turn

    world = World("forced_coordination")
    robot = make_robot("belief", population="populations/hard_layouts.toml", open_world="learned", bayes_factor=factor)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    members = list(robot.member_specs)
    post = {m: (0.12 if i == 0 else 0.28 / (len(members) - 1)) for i, m in enumerate(members)} | {"learned": 0.6}
    assert len(members) == 4 and sum(post.values()) == pytest.approx(1.0)
    monkeypatch.setattr(robot.posterior, "posterior", lambda: post)
    robot.act(Turn(world, world.initial_state(np.random.default_rng(0)), Agent.ROBOT, {}))
    assert robot.last_decision.partner == ("learned" if off_population else robot.member_names[0])
    assert robot._off_population is off_population


def test_bayes_factor_is_a_finite_number_at_least_1() -> None:
    for bad in ("0.5", "nan", "inf", "x"):
        with pytest.raises(RobotError, match="bayes_factor"):
            make_robot(f"belief:population=populations/hard_layouts.toml,open_world=learned,bayes_factor={bad}")
