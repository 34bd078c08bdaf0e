"""The partner model: blocking facts and stalls (no livelock), and the posterior over types."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from partners import PARTNERS, Fixed

from hg_marl.agents.humans import make_human
from hg_marl.agents.partner import PartnerMonitor, PartnerPosterior
from hg_marl.agents.robots import make_robot
from hg_marl.core import WAIT, Agent, Kind, World
from hg_marl.core.errors import RobotError
from hg_marl.training.runner import RunConfig, run


@pytest.fixture(scope="module")
def world() -> World:
    return World("paper2015")


def _human_index(world: World, kind: Kind) -> int:
    return next(i for i, a in enumerate(world.actions(Agent.HUMAN)) if a.kind is kind)


def test_monitor_blocks_a_refused_action_then_forgets_it_on_success(world: World) -> None:
    give, wait = _human_index(world, Kind.GIVE), world.index(Agent.HUMAN, WAIT)
    monitor = PartnerMonitor(block_after=2, stall_after=3)
    monitor.observe(world, give, wait, solved=False)
    assert not monitor.blocked and monitor.misses == 1
    monitor.observe(world, wait, give, solved=False)  # doing more than hoped is no refusal
    assert monitor.misses == 1
    monitor.observe(world, give, wait, solved=False)
    assert monitor.blocked == {world.actions(Agent.HUMAN)[give]} and not monitor.stalled
    monitor.observe(world, give, wait, solved=False)
    assert monitor.stalled
    monitor.fell_back()
    assert not monitor.stalled
    monitor.observe(world, -1, wait, solved=True)
    assert not monitor.blocked and monitor.misses == 0


def test_monitor_forgets_blocks_when_no_plan_remains(world: World) -> None:
    give, wait = _human_index(world, Kind.GIVE), world.index(Agent.HUMAN, WAIT)
    monitor = PartnerMonitor(block_after=1, stall_after=2)
    monitor.observe(world, give, wait, solved=False)
    assert monitor.blocked
    monitor.planner_failed()
    assert not monitor.blocked
    monitor.planner_failed()  # no blocks left: a failure is an unmet expectation
    assert monitor.misses == 2 and monitor.stalled


def test_posterior_by_hand(world: World) -> None:
    state = world.initial_state(np.random.default_rng(0))
    feasible = world.feasible_indices(state, Agent.HUMAN)
    a, b = feasible[0], feasible[-1]
    post = PartnerPosterior(types=("cooperative", "lazy"), prior=(0.5, 0.5), decay=1.0, epsilon=0.1)
    post.humans = [Fixed(a), Fixed(b)]
    post.observe(world, state, -1, a)
    post.observe(world, state, -1, a)
    n = len(feasible)
    like_a, like_b = 0.9 + 0.1 / n, 0.1 / n
    expected = like_a**2 / (like_a**2 + like_b**2)
    assert post.posterior()["cooperative"] == pytest.approx(expected)
    assert post.most_probable() == "cooperative"
    post.decay = 0.5  # old evidence fades: two observations of b now outweigh it
    post.observe(world, state, -1, b)
    post.observe(world, state, -1, b)
    ea = 0.5 * (0.5 * 2 * math.log(like_a) + math.log(like_b)) + math.log(like_b)
    eb = 0.5 * (0.5 * 2 * math.log(like_b) + math.log(like_a)) + math.log(like_a)
    assert post.posterior()["lazy"] == pytest.approx(math.exp(eb) / (math.exp(ea) + math.exp(eb)))


@pytest.mark.parametrize("human", ["cooperative", "lazy", "no_handover", "noisy"])
def test_posterior_converges_to_the_scripted_type(human: str) -> None:
    """Over the second half of a 300 s run the robot believes the true type at >= 80% of its decisions."""
    robot = make_robot("planner", partner_aware=True)
    log = run(robot, make_human(human), RunConfig(duration=300.0, seed=1)).log
    assert (log.loc[log["time"] > 150.0, "partner"] == human).mean() >= 0.8
    assert robot.partnering.posterior.most_probable() == human  # type: ignore[attr-defined]


FAST = [
    ("planner", {}),
    ("hybrid", {"criterion": "entropy_and_cost"}),
    ("hybrid", {"criterion": "vpi", "partner_aware": True}),
]
SLOW = [
    ("planner", {"partner_aware": True}),
    *[("hybrid", {"criterion": c}) for c in ("random", "entropy", "vpi", "learning_state")],
    ("hybrid", {"criterion": "entropy_and_cost", "partner_aware": True}),
]


def _tasks_in_second_half(name: str, params: dict[str, Any], partner: str, duration: float = 600.0) -> int:
    log = run(make_robot(name, **params), PARTNERS[partner](), RunConfig(duration=duration, seed=0)).log
    return int(log.loc[log["time"] > duration / 2, "reward"].sum())


def _id(x: Any) -> str:
    return x if isinstance(x, str) else ",".join(f"{k}={v}" for k, v in x.items()) or "-"


@pytest.mark.parametrize("partner", sorted(PARTNERS))
@pytest.mark.parametrize("name, params", FAST, ids=_id)
def test_no_livelock_with_adversarial_partners(name: str, params: dict[str, Any], partner: str) -> None:
    """Every partner here leaves the table solvable: the robot keeps solving tasks."""
    assert _tasks_in_second_half(name, params, partner) > 0


@pytest.mark.slow
@pytest.mark.parametrize("partner", sorted(PARTNERS))
@pytest.mark.parametrize("name, params", SLOW, ids=_id)
def test_no_livelock_with_adversarial_partners_all_robots(name: str, params: dict[str, Any], partner: str) -> None:
    assert _tasks_in_second_half(name, params, partner) > 0


@pytest.mark.parametrize("name", ["planner", "hybrid"])
def test_partner_aware_must_be_a_bool(name: str) -> None:
    with pytest.raises(RobotError, match=r"partner_aware'?: expected true or false, got 'yes'"):
        make_robot(name, partner_aware="yes")
