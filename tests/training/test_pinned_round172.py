"""Values that round 172's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

import hg_marl
from hg_marl.agents.adapters import scripted_v0
from hg_marl.agents.memory_policy import MemoryNet
from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.models import cooperative
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, State, World
from hg_marl.training.baselines.ppo_recurrent import greedy_rate
from tests.training.test_ppo_recurrent import Cue


def test_an_intent_for_a_human_kept_off_an_object_is_not_relabelled_onto_another_object() -> None:
    # paper2015: tape1 (object 0) lies on human_mat_2 (spot 5), which only the human reaches
    # (the robot reaches spots 0-3 only); tapes 2 and 3 lie on mat_centre and mat_right. The human
    # model is blocked from every action on object 0, so nobody can ever clear tape1: worked by
    # hand, no plan exists, and the intent is a failure (the robot's wait, at infinite cost).
    # Relabelled to canonical order, tape1 would be another object, one the human may touch.
    world = World("paper2015")
    model = cooperative().with_blocked(frozenset(a for a in world.actions(Agent.HUMAN) if a.obj == 0))
    state = State(where=(5, 1, 2), robot_at=0, offer_by=-1, offer_obj=-1)
    assert Relabel(world).canonical(state)[0] != state  # the state is not in canonical order
    wait = world.n_actions(Agent.ROBOT) - 1
    intent = Planner(world, human_model=model).intent(state)
    assert (intent.success, intent.robot_action, intent.human_action) == (False, wait, -1)
    assert math.isinf(intent.duration) and math.isinf(intent.cost)
    # and, where a plan exists, the same answer the full search (plan) gives from the state as it is
    for where in ((2, 0, 5), (0, 4, 2)):
        state = State(where=where, robot_at=0, offer_by=-1, offer_obj=-1)
        intent = Planner(world, human_model=model).intent(state)
        planned = Planner(world, human_model=model).plan(state)
        assert planned.success and planned.plan is not None
        assert (intent.robot_action, intent.human_action) == (planned.robot_action, planned.human_action)
        assert (intent.duration, intent.cost) == (planned.plan.duration, planned.cost)


class _TwoSpeeds(Cue):
    """Two tables: table 0's steps last 1 s and earn a task from its third step on; table 1's last 2 s, earn none."""

    def step(self, actions: np.ndarray) -> tuple[Any, Any, Any, Any, dict[str, Any]]:
        reward = np.array([float(self.t[0] >= 2), 0.0])
        self.t += 1
        self.clock += np.array([1.0, 2.0])
        done = np.zeros(self.num_envs, dtype=bool)
        return self._obs(), reward, done, done, {"clock": self.clock.copy()}


def test_the_greedy_rate_plays_every_table_for_the_seconds_asked() -> None:
    # Worked by hand, 4 s per table: table 1 (2 s steps) has played 4 s after 2 steps, table 0
    # (1 s steps) after 4, so 4 steps are played: table 0 earns at its steps 3 and 4, 2 tasks, over
    # 4 * 1 + 4 * 2 = 12 simulated seconds: 2 / 12 * 3600 = 600 tasks per hour. Stopping when the
    # first table has played enough (2 steps) would count no task at all.
    net = MemoryNet(3, 2, 8, True)
    assert greedy_rate(net, _TwoSpeeds(2), 4.0, seed=0) == 600.0


def test_a_terminated_scripted_seat_sees_the_env_observation() -> None:
    # Episodic paper2015 with both seats scripted (the planner, the cooperative human): once the
    # task is solved both seats are terminated, and a scripted seat is then shown what the env
    # shows, not a one-hot mask of a decision: the robot's raw mask there allows two actions.
    env = scripted_v0(hg_marl.env(max_cycles=200), robot="planner", human="cooperative")
    env.reset(seed=0)
    while not any(env.terminations.values()) and not any(env.truncations.values()):
        observation = env.observe(env.agent_selection)
        env.step(int(np.flatnonzero(observation["action_mask"])[0]))
    assert env.terminations == {"robot": True, "human": True}
    assert int(np.sum(env.env.observe("robot")["action_mask"])) == 2
    for seat in ("robot", "human"):
        shown, raw = env.observe(seat), env.env.observe(seat)
        assert np.array_equal(shown["action_mask"], raw["action_mask"])
        assert np.array_equal(shown["observation"], raw["observation"])
