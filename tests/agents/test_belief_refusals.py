"""The belief robot and a partner who refuses offers: members planned as never taking, a verdict that lapses.

The table (``data/offer_or_throw.toml``) has two tapes the robot reaches from the handover
place and a bin the robot reaches only from the other place: handing a tape over costs the
robot a second, carrying it to the bin a walk there and back. The believed members take an
offer with probability 0.9 and 0.4, so each refusal stays explained by the 0.4 member.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.preference import never_takes
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.belief import REFUSAL_LIKELIHOOD, REFUSALS_WITHIN, BeliefRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import RobotError
from hg_marl.training.runner import RunConfig, RunResult, run

TABLE = str(Path(__file__).parent / "data" / "offer_or_throw.toml")
DURATION = 1100.0
NEVER = "preference:accept=0.0"


@pytest.fixture(scope="module")
def population(tmp_path_factory: pytest.TempPathFactory) -> str:
    path = tmp_path_factory.mktemp("refusals") / "population.toml"
    path.write_text(
        f'name = "t"\nscenario = "{TABLE}"\n'
        '\n[[members]]\nname = "taker"\nsplit = "train"\nspec = "preference:accept=0.9"\n'
        '\n[[members]]\nname = "hesitant"\nsplit = "train"\nspec = "preference:accept=0.4"\n'
    )
    return str(path)


def _play(population: str, partner: str, **params: object) -> tuple[BeliefRobot, RunResult]:
    robot = make_robot("belief", population=population, cache="", **params)
    assert isinstance(robot, BeliefRobot)
    return robot, run(robot, make_human(partner), RunConfig(scenario=TABLE, duration=DURATION, seed=0))


def test_never_takes_is_the_member_with_accept_zero_and_leaves_other_humans_alone() -> None:
    assert never_takes("preference:accept=0.73,colour=blue,handover=1.34") == (
        "preference:accept=0.0,colour=blue,handover=1.34"
    )
    assert never_takes("preference") == "preference:accept=0.0"
    assert never_takes("lazy:p_idle=0.5") == "lazy:p_idle=0.5"
    assert make_human(never_takes("preference:accept=0.5,p_idle=0.2")).accept == 0.0


def test_the_refusal_threshold_worked_by_hand() -> None:
    """A 0.9 taker must refuse three offers in a row (0.1^2 = 0.01 > 1/500 > 0.1^3), a 0.4 taker thirteen."""
    assert 0.1**2 > REFUSAL_LIKELIHOOD > 0.1**3
    assert 0.6**12 > REFUSAL_LIKELIHOOD > 0.6**13


def test_a_partner_who_never_takes_gets_its_best_response_not_offers(population: str) -> None:
    """Without the verdict the robot keeps offering to a partner the 0.4 member explains
    (hundreds of refused offers); with it, the members are solved as never taking and the
    robot carries the tapes itself: at least 90% of that partner's exact best response."""
    best = oracle_rate(TABLE, NEVER).rate_per_hour * DURATION / 3600
    robot, with_verdict = _play(population, NEVER)
    _, without = _play(population, NEVER, refusals=False)
    offers = with_verdict.log["action_name"].str.startswith("give")
    assert with_verdict.summary["tasks_solved"] >= 0.9 * best
    assert without.summary["tasks_solved"] < 0.5 * best
    assert without.log["action_name"].str.startswith("give").sum() > 300
    # Thirteen refusals before the verdict, then one offer each time it lapses (every
    # REFUSALS_WITHIN + 1 answers at most): the refused offer repeated is bounded.
    answers = len(with_verdict.log)
    assert offers.sum() <= 13 + math.ceil(answers / (REFUSALS_WITHIN + 1)) + 1
    reasons = with_verdict.log["reason"]
    assert reasons.str.startswith("the partner refuses offers").sum() > answers / 2
    # The never-taking members were solved (and only as the spec says).
    assert robot._never_takes.specs == ("preference:accept=0.0", "preference:accept=0.0")
    assert robot._never_takes.built()


@pytest.mark.parametrize("partner", ["preference:accept=0.9", "preference:accept=0.4"])
def test_a_partner_the_members_explain_plays_exactly_as_without_the_verdict(population: str, partner: str) -> None:
    _, with_verdict = _play(population, partner)
    _, without = _play(population, partner, refusals=False)
    assert with_verdict.log["action"].tolist() == without.log["action"].tolist()
    assert not with_verdict.log["reason"].str.startswith("the partner refuses").any()


def test_the_verdict_lapses_and_a_partner_who_starts_taking_is_offered_again(population: str) -> None:
    """Never takes for 400 s, then takes everything: after the switch the robot offers again
    and most of its tapes go over by hand, as against a taker from the start."""
    switching = make_human("switching", humans=[NEVER, "preference:accept=1.0"], at=[400.0])
    robot = make_robot("belief", population=population, cache="")
    log = run(robot, switching, RunConfig(scenario=TABLE, duration=DURATION, seed=0)).log
    before, after = log[log["time"] < 400], log[log["time"] > 500]
    assert before["reason"].str.startswith("the partner refuses").any()
    gives_after = after["action_name"].str.startswith("give").sum()
    throws_after = after["action_name"].str.startswith("throw").sum()
    assert gives_after > 3 * throws_after
    assert not after["reason"].str.startswith("the partner refuses").any()


def _offering(robot: BeliefRobot) -> tuple[BeliefRobot, World, State, int, State]:
    """``robot`` reset on the table, the state after its first pick, its give there, and the state offering it."""
    world = World(TABLE)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    acts = world.actions(Agent.ROBOT)
    pick = next(i for i in world.feasible_indices(state, Agent.ROBOT) if acts[i].kind is Kind.PICK)
    held = world.step(state, Agent.ROBOT, pick).state
    give = next(i for i in world.feasible_indices(held, Agent.ROBOT) if acts[i].kind is Kind.GIVE)
    return robot, world, held, give, world.step(held, Agent.ROBOT, give).state


def test_the_refusal_run_worked_by_hand(population: str) -> None:
    """Two refusals at an offered state: the run is the product of the mixture's refusal
    chances, each member's (1 - eps) (1 - accept) + eps (n - takes) / n, weighed by the
    posterior before the answer; a take ends the run."""
    robot, world, _, give, mid = _offering(BeliefRobot(population=population, cache="", unknown=0.0, epsilon=0.05))
    human = world.actions(Agent.HUMAN)
    feasible = world.feasible_indices(mid, Agent.HUMAN)
    n, wait = len(feasible), world.n_actions(Agent.HUMAN) - 1
    take = next(i for i in feasible if human[i].kind is Kind.TAKE)
    # Both members: take with their accept; otherwise their own best move, here not a take.
    expected = 1.0
    for _ in range(2):
        post = robot.posterior.posterior()
        refuse = sum(
            post[spec] * ((1 - 0.05) * (1 - accept) + 0.05 * (n - 1) / n)
            for spec, accept in (("preference:accept=0.9", 0.9), ("preference:accept=0.4", 0.4))
        )
        robot._count_refusal(world, mid, give, wait)
        robot.posterior.observe(world, mid, give, wait)
        expected *= refuse
        assert robot._refusal_run == pytest.approx(expected, rel=1e-12)
    assert robot._since_offer == 0
    robot._count_refusal(world, mid, give, take)
    assert robot._refusal_run == 1.0


def test_refusals_is_a_boolean_option(population: str) -> None:
    with pytest.raises(RobotError, match="parameter 'refusals'"):
        make_robot("belief", population=population, refusals="maybe")
    with pytest.raises(RobotError, match=r"belief\.refusals"):
        BeliefRobot(population=population, refusals="maybe")


def test_the_verdict_holds_while_the_last_offer_is_at_most_refusals_within_answers_old(population: str) -> None:
    """Refused offers until the run is less likely than 1/500: the verdict holds at the last
    offer and for 30 answers after it (each at a state with nothing offered), and lapses at
    the 31st (the docstring's "at most REFUSALS_WITHIN answers old")."""
    assert REFUSALS_WITHIN == 30
    robot, world, held, give, mid = _offering(BeliefRobot(population=population, cache=""))
    wait = world.n_actions(Agent.HUMAN) - 1
    refused = 0
    while not robot.refuses_offers():
        robot._count_refusal(world, mid, give, wait)
        robot.posterior.observe(world, mid, give, wait)
        refused += 1
        assert refused < 100
    assert robot._refusal_run < REFUSAL_LIKELIHOOD
    assert held.offer_by != int(Agent.ROBOT)  # nothing offered: an answer there only ages the last offer
    for answers in range(1, 32):
        robot._count_refusal(world, held, wait, wait)
        assert robot._since_offer == answers
        assert robot.refuses_offers() is (answers <= 30), answers


def test_a_refused_offer_seen_by_the_robot_is_scored_under_the_belief_before_it_moves(population: str) -> None:
    """The robot's own update (``_observe``, as ``act`` calls it): the refusal's chance is the
    mixture's under the posterior held *before* that refusal (the prior here, 1/2 each), and
    only then does the posterior move toward the member who takes less."""
    robot, world, held, give, mid = _offering(BeliefRobot(population=population, cache="", unknown=0.0, epsilon=0.05))
    wait = world.n_actions(Agent.HUMAN) - 1
    n = len(world.feasible_indices(mid, Agent.HUMAN))
    # by hand: each member refuses with (1 - eps)(1 - accept) + eps (n - 1) / n, weighed 1/2 each
    expected = sum(0.5 * (0.95 * (1 - accept) + 0.05 * (n - 1) / n) for accept in (0.9, 0.4))
    after = world.step(mid, Agent.HUMAN, wait).state
    robot._prev = (held, give)
    turn = SimpleNamespace(world=world, state=after, last_actions=(give, wait), reward=0.0)
    robot._observe(turn)  # type: ignore[arg-type]
    assert robot._refusal_run == pytest.approx(expected, rel=1e-12)
    post = robot.posterior.posterior()
    assert post["preference:accept=0.4"] > 0.5 > post["preference:accept=0.9"]  # the belief moved after
