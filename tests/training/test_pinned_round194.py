"""Values that round 194's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np
import pytest

import hg_marl
from hg_marl.agents.partner import PartnerMonitor
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.base import LearningRobot
from hg_marl.core import Agent, State, World
from hg_marl.envs.parallel import AgentMismatchError, parallel_env
from hg_marl.policy import Turn
from hg_marl.training.play.stats import episode_stats
from hg_marl.wrappers import flatten_v0
from tests.training.test_pinned_play_stats_gate import NO_OFFER, WAIT, _episode, _step


def test_the_habit_robot_with_shared_objects_proposes_from_the_canonical_facts_it_learnt_on() -> None:
    # With share_objects the habit learns at the canonical facts. MIRROR (tapes 0 and 1 on each
    # other's places) has STATE's facts as its canonical ones, which differ from its own. Acting in
    # MIRROR then ending with reward 1 gives Q = alpha = 0.6 at STATE's facts for the executed action
    # (canonical labelling) and 0 for the 17 others. Asked again in MIRROR, the canonical Q mapped
    # back puts 1 / (1 + 17 exp(-50 * 0.6)) on that same action: it is drawn every time. Proposing
    # from MIRROR's own facts (never learnt: tabular Q = 0) would draw uniformly among the 18.
    world = World("paper2015")
    state = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    mirror = State(where=(2, 0, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    assert not np.array_equal(world.facts(state), world.facts(mirror))
    robot = make_robot("habit", share_objects=True, q_config={"features": "tabular"})
    assert isinstance(robot, LearningRobot)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))

    def turn(reward: float) -> Turn:
        observation = {"observation": world.facts(mirror), "action_mask": world.mask(mirror, Agent.ROBOT)}
        return Turn(world, mirror, Agent.ROBOT, observation, reward=reward)

    first = robot.act(turn(0.0))
    robot.end(turn(1.0), terminated=True)
    assert [robot.act(turn(0.0)) for _ in range(6)] == [first] * 6


def test_a_parallel_step_naming_no_agent_lists_every_live_agent_as_missing() -> None:
    # After reset both agents are live; an empty actions dict misses both (sorted), names none extra.
    env = parallel_env()
    env.reset(seed=0)
    with pytest.raises(AgentMismatchError) as info:
        env.step({})
    assert str(info.value) == (
        "parallel step needs one action for each live agent ['human', 'robot']; "
        "missing ['human', 'robot'], unexpected []"
    )


def test_a_failed_plan_without_blocks_counts_a_miss_and_keeps_the_refusals() -> None:
    # PartnerMonitor.planner_failed: "without blocks a failure counts as an unmet expectation" (blocks
    # are forgotten only when there are some). block_after=2, stall_after=3: one refusal of pick(tape 0)
    # (human action 0; wait is last) is 1 miss and 1 refusal, nothing blocked; the failure makes 2 misses
    # and keeps the refusal; a second refusal makes its count 2 (blocked) and 3 misses in a row (stalled).
    world = World("paper2015")
    pick, wait = 0, world.n_actions(Agent.HUMAN) - 1
    action = world.actions(Agent.HUMAN)[pick]
    monitor = PartnerMonitor(block_after=2, stall_after=3)
    monitor.observe(world, pick, wait, solved=False)
    assert monitor.misses == 1 and monitor.refusals == {action: 1} and not monitor.blocked
    monitor.planner_failed()
    assert monitor.misses == 2 and monitor.refusals == {action: 1} and not monitor.stalled
    monitor.observe(world, pick, wait, solved=False)
    assert monitor.blocked == frozenset({action}) and monitor.misses == 3 and monitor.stalled


def test_a_game_whose_trace_names_no_robot_reports_its_robot_as_unknown() -> None:
    # The header's meta names the robot; without it the robot is unknown, "?" (as `who` is), not a guess.
    assert episode_stats(_episode([_step(WAIT, NO_OFFER)])).robot == "?"
    assert episode_stats(_episode([_step(WAIT, NO_OFFER)], meta={"robot": "habit"})).robot == "habit"


def test_the_flat_wrappers_info_masks_leave_with_the_agents_at_the_end_of_an_episode() -> None:
    # max_cycles=1: both agents wait once and are truncated; stepping each out with None (the AEC
    # convention) removes it from the env's agents and infos. With mask="info" the wrapper's infos are
    # the env's with the mask added, so they hold the agents the env holds: at the end, none.
    env = flatten_v0(hg_marl.env(max_cycles=1), mask="info")
    env.reset(seed=0)
    assert set(env.infos) == {"robot", "human"}
    for agent in env.agent_iter():
        _, _, terminated, truncated, _ = env.last()
        env.step(None if terminated or truncated else int(env.action_space(agent).n) - 1)  # wait is last
        assert set(env.infos) == set(env.agents)
    assert env.agents == [] and env.infos == {}
