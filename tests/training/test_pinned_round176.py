"""Values that round 176's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.partner import PartnerMonitor
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.base import LearningRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.batch import BatchState
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.training.play.stats import PlayStats, summarise
from tests.agents.test_pinned_robot_base_gate import WORLD, _turn
from tests.env.test_pinned_aec_env_gate import _index


def test_the_habit_robot_learns_its_last_step_before_it_draws_an_action() -> None:
    # Tabular habit (alpha 0.6, gamma 0.9, beta 50, Q = 0 at the start). The robot acts in S (all 18
    # Q-values 0: a uniform draw, `first`), then is asked again in the same S with reward 1. The TD
    # step on (S, first) comes first: Q(S, first) = 0.6 * (1 + 0.9 * 0 - 0) = 0.6, the others stay 0,
    # and the Boltzmann policy then puts 1 / (1 + 17 exp(-30)) on `first`: it is chosen again, on
    # every seed. (Drawing before the step would draw uniformly again: `first` 1 time in 18.)
    state = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    for seed in range(8):
        robot = make_robot("habit", share_objects=False, q_config={"features": "tabular"})
        assert isinstance(robot, LearningRobot)
        robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(seed))
        first = robot.act(_turn(state, 0.0))
        assert robot.act(_turn(state, 1.0)) == first


def test_the_monitor_keeps_every_blocked_action_until_a_task_is_solved() -> None:
    # block_after = 1: the human refuses an expected give, then an expected pick (doing wait each
    # time). Each refusal blocks its action, and blocks are forgotten only when a task is solved
    # or a plan fails: both stay blocked, {give, pick}, not just the last one.
    world = World("paper2015")
    actions = world.actions(Agent.HUMAN)
    give = next(i for i, a in enumerate(actions) if a.kind is Kind.GIVE)
    pick = next(i for i, a in enumerate(actions) if a.kind is Kind.PICK)
    wait = next(i for i, a in enumerate(actions) if a.kind is Kind.WAIT)
    monitor = PartnerMonitor(block_after=1, stall_after=10)
    monitor.observe(world, give, wait, solved=False)
    monitor.observe(world, pick, wait, solved=False)
    assert monitor.blocked == frozenset({actions[give], actions[pick]})


def test_a_summary_without_moves_has_no_idle_share() -> None:
    # No move at all (no game, or one game of 0 moves): the idle share is a share of nothing, None,
    # like moves_per_task and the acceptance; 0.0 would claim a player who never idled.
    assert summarise([])["idle_share"] is None
    empty = PlayStats("p", "planner", 0, 0, None)
    assert summarise([empty])["idle_share"] is None


def test_an_episodic_env_ends_on_the_clean_table_it_completed() -> None:
    # paper2015, every tape in the bin (spot 6): the robot waits on the clean table (reward 1) and
    # the human waits; the episode terminates. Only a continuing env re-draws the table, so the
    # episodic one ends on the state it completed, (6, 6, 6) with the robot at 0, waits changing
    # nothing, and its final observation is that clean table's facts.
    env = raw_env()
    clean = State((6, 6, 6), 0)
    env.reset(seed=0, options={"state": clean})
    env.step(_index(env, "robot", "wait"))
    env.step(_index(env, "human", "wait"))
    assert env.terminations == {"robot": True, "human": True}
    assert env.world_state == clean
    np.testing.assert_array_equal(env.observe("robot")["observation"], env.world.facts(clean))


def test_put_copies_each_tables_offered_object_and_offerer() -> None:
    # Two tables without offers; put overwrites table 1 with a table where the human (1) offers
    # object 2, and table 0 with one where the robot (0) offers object 1: each table then is
    # exactly the state put there, offer_by and offer_obj each from its own field.
    plain = State((0, 2, 4), 1)
    human_offer = State((0, 2, 4), 1, offer_by=1, offer_obj=2)
    robot_offer = State((0, 2, 4), 1, offer_by=0, offer_obj=1)
    batch = BatchState.of([plain, plain])
    batch.put(np.array([1, 0]), BatchState.of([human_offer, robot_offer]))
    assert batch.state(1) == human_offer
    assert batch.state(0) == robot_offer
