"""When the belief robot counts a wait as unexplained, pinned for the mutation gate.

Expected values by hand from the rule (agents/robots/belief.py): the run of both-waited
cycles only grows when the robot's previous turn was a ``wait`` at this very state; then
each cycle multiplies it by ``(1 - eps) * p_wait + eps / n``. ``p_wait`` is read from
the member's own answer distribution (the model's input), ``eps = 0.05``.
A previous turn at another state, or not a wait, starts the run afresh (not unexplained).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from partners import Fixed

from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, World
from hg_marl.policy import Turn
from tests.population_files import train_members as _members


def _robot(tmp_path: Path, world: World, spec: str = "cooperative") -> BeliefRobot:
    """A closed-world belief robot with one member, its partner reset, its wait run fresh."""
    robot = BeliefRobot(population=_members(tmp_path, coop=spec), splits="train", unknown=0.0)
    for human in robot.posterior.humans:
        human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    robot._wait = world.n_actions(Agent.ROBOT) - 1
    robot._wait_run = 1.0
    return robot


def test_a_wait_answered_by_a_wait_at_the_same_unfinished_table_is_unexplained(tmp_path: Path) -> None:
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    mid = world.step(state, Agent.ROBOT, robot._wait).state
    n = len(world.feasible_indices(mid, Agent.HUMAN))
    assert n >= 2 and not world.is_clean(state)
    human = robot.posterior.humans[0]
    p_wait = dict(human.distribution(world, mid, -1)).get(world.n_actions(Agent.HUMAN) - 1, 0.0)
    p = 0.95 * p_wait + 0.05 / n  # the rule's formula, eps = 0.05 (the robot's default)
    turn = Turn(world, state, Agent.ROBOT, {})
    robot._prev = (state, robot._wait)
    assert robot._unexplained_waits(turn, [1.0]) == (p < 0.05)
    assert robot._wait_run == pytest.approx(p)
    assert robot._unexplained_waits(turn, [1.0]) == (p * p < 0.05)  # a second such cycle multiplies again
    assert robot._wait_run == pytest.approx(p * p)
    assert p < 1.0  # so the run differs from a fresh one


def test_a_previous_turn_elsewhere_or_not_waiting_starts_afresh(tmp_path: Path) -> None:
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    other = world.initial_state(np.random.default_rng(1))
    assert other != state
    turn = Turn(world, state, Agent.ROBOT, {})
    for prev in ((other, robot._wait), (state, 0)):
        robot._prev = prev
        robot._wait_run = 0.5
        assert not robot._unexplained_waits(turn, [1.0])
        assert robot._wait_run == 1.0


def test_a_turn_without_a_human_action_is_no_evidence(tmp_path: Path) -> None:
    """``last_actions[1] == -1`` (the Turn's documented "no action yet") updates nothing, whatever came before."""
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    robot._prev = (state, robot._wait)
    before = list(robot.posterior.posterior())
    calls: list[int] = []
    robot.posterior.observe = lambda *args: calls.append(1)  # type: ignore[method-assign]
    robot._observe(Turn(world, state, Agent.ROBOT, {}, last_actions=(robot._wait, -1)))
    assert calls == [] and list(robot.posterior.posterior()) == before


def test_a_member_who_never_waits_there_makes_one_shared_wait_unexplained(tmp_path: Path) -> None:
    """The member's answer at the state has no wait (p_wait = 0), so one shared wait has
    probability eps / n < 0.05 under the belief: unexplained at once."""
    world = World("paper2015")
    robot = _robot(tmp_path, world, "preference:p_idle=0.0")
    state = world.initial_state(np.random.default_rng(0))
    mid = world.step(state, Agent.ROBOT, robot._wait).state
    human_wait = world.n_actions(Agent.HUMAN) - 1
    assert dict(robot.posterior.humans[0].distribution(world, mid, -1)).get(human_wait, 0.0) == 0.0
    n = len(world.feasible_indices(mid, Agent.HUMAN))
    robot._prev = (state, robot._wait)
    assert robot._unexplained_waits(Turn(world, state, Agent.ROBOT, {}), [1.0])
    assert robot._wait_run == pytest.approx(0.05 / n)


def test_a_failed_robot_action_is_counted_as_failed_by_the_learned_model(tmp_path: Path) -> None:
    """The partner saw the robot fail: the learned model counts the answer under the
    ``failed`` context (robot action -1), not under some robot action's kind."""
    from hg_marl.agents.partner_model import FAILED

    world = World("paper2015")
    robot = BeliefRobot(population=_members(tmp_path, c="cooperative"), splits="train", open_world="learned")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    failing = next(a for a in range(world.n_actions(Agent.ROBOT)) if not world.step(state, Agent.ROBOT, a).ok)
    human_wait = world.n_actions(Agent.HUMAN) - 1
    after = world.step(world.step(state, Agent.ROBOT, failing).state, Agent.HUMAN, human_wait).state
    robot._prev = (state, failing)
    robot._observe(Turn(world, after, Agent.ROBOT, {}, last_actions=(failing, human_wait)))
    learned = robot.posterior.learned
    assert learned is not None
    assert [ctx[3] for ctx in learned.counts] == [FAILED]


def test_the_information_of_a_reply_reads_what_the_partner_saw_the_robot_do(tmp_path: Path) -> None:
    """A member who mirrors the robot (``fo_mirror``) answers a failed robot action (-1) with a
    wait: the information is the docstring's formula on the members' answers to -1,
    which differ from their answers to any robot action index."""
    world = World("paper2015")
    robot = BeliefRobot(population=_members(tmp_path, m="fo_mirror", p="preference"), splits="train", unknown=0.0)
    for human in robot.posterior.humans:
        human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    state = world.initial_state(np.random.default_rng(0))
    failing = next(a for a in range(world.n_actions(Agent.ROBOT)) if not world.step(state, Agent.ROBOT, a).ok)
    mid = world.table.successor(state, Agent.ROBOT, failing)[0]
    replies = world.feasible_indices(mid, Agent.HUMAN)
    mirror = robot.posterior.humans[0]
    assert mirror.distribution(world, mid, -1) != mirror.distribution(world, mid, 1)
    n = len(replies)
    ps = [
        np.array([0.95 * dict(h.distribution(world, mid, -1)).get(r, 0.0) + 0.05 / n for r in replies])
        for h in robot.posterior.humans
    ]
    mix = 0.5 * ps[0] + 0.5 * ps[1]
    expected = float(-(mix * np.log(mix)).sum()) - sum(0.5 * float(-(p * np.log(p)).sum()) for p in ps)
    assert robot.information(world, state, failing, [0.5, 0.5]) == pytest.approx(expected, rel=1e-12)


def test_a_probe_is_the_most_telling_action_within_the_budget(tmp_path: Path) -> None:
    """Actions 1 and 2 cost 1 and 2 s more than the best (0) and tell 0.5 and 0.2 nats
    (0 for the best): within a budget of 5 s the probe is action 1, the most telling one."""
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    robot.probe = 5.0
    info = {0: 0.0, 1: 0.5, 2: 0.2}
    robot.information = lambda w, s, a, weights: info[a]  # type: ignore[method-assign]
    state = world.initial_state(np.random.default_rng(0))
    assert robot._probe(world, state, [1.0], {0: 10.0, 1: 11.0, 2: 12.0}, 1.0) == (1, 0.5)


def test_a_run_exactly_at_the_threshold_is_not_yet_unexplained(tmp_path: Path) -> None:
    """The run is unexplained when it is *less* likely than 0.05. A member who always waits
    gives one shared wait q = 0.95 + 0.05 / n; with the weight w for which the run w * q is
    0.05 exactly, the wait is still explained, and with the next float below it is not."""
    world = World("paper2015")
    robot = _robot(tmp_path, world)
    state = world.initial_state(np.random.default_rng(0))
    mid = world.step(state, Agent.ROBOT, robot._wait).state
    n = len(world.feasible_indices(mid, Agent.HUMAN))
    robot.posterior.humans = [Fixed(world.n_actions(Agent.HUMAN) - 1)]
    q = (1.0 - 0.05) * 1.0 + 0.05 / n
    w = 0.05 / q
    for _ in range(8):  # the float that makes the product the threshold itself (a few ulps away)
        if w * q == 0.05:
            break
        w = float(np.nextafter(w, 1.0 if w * q < 0.05 else 0.0))
    assert w * q == 0.05
    turn = Turn(world, state, Agent.ROBOT, {})
    for weight, unexplained in ((w, False), (float(np.nextafter(w, 0.0)), True)):
        robot._prev, robot._wait_run = (state, robot._wait), 1.0
        assert robot._unexplained_waits(turn, [weight]) is unexplained


@pytest.mark.parametrize("hedge", ["map", "".join(["m", "ap"])])  # a literal and a string made at run time
def test_map_consults_one_member_whatever_object_spells_it(tmp_path: Path, hedge: str) -> None:
    """``hedge="map"`` plays the most probable member alone: after the first decision with three
    members under an equal prior, one member's model is solved (``"qmdp"`` would solve all
    three). The name is compared by value, so a string read from a spec counts as well."""
    from hg_marl.agents.humans import make_human
    from hg_marl.training.runner import RunConfig, run

    population = _members(tmp_path, a="cooperative", b="lazy", c="no_handover")
    robot = BeliefRobot(population=population, splits="train", hedge=hedge, cache=str(tmp_path / "c"))
    run(robot, make_human("cooperative"), RunConfig(duration=60.0, seed=0, max_decisions=1))
    assert robot.members_built() == [0]
