"""The values round 85's missed planted bugs changed, pinned after the round.

Round 85 planted 16 bugs in sixteen gated modules, written blind; 12 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- the HTN domain's ``handover_r2h`` method is "the robot picks ``o``, gives it at the
  handover location; the human takes *and throws* it": it needs a human model with both
  kinds, so a human who takes but never throws is never planned to be handed an object;
- a plan's expected cost against a stochastic human is the same whether the planner is
  asked at the cycle's boundary (the robot to move) or just after the robot's planned
  action (the human to move, that action under way): the cost of a plan begun at the
  human's turn includes every later cycle, not only the first;
- a single-agent view's ``info["idle"]`` is the learning seat's own idle seconds (the
  partner's work is in ``partner_effort``): a robot that only waits has been idle for
  the whole clock;
- the homogenising wrapper's shared ``action_mask`` space is ``Box(0, 1, (A,), int8)``
  whatever the observation dtype (the spec sheet's ``dtype`` is the facts' and the id's).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from gymnasium import spaces

import hg_marl
from hg_marl.agents.planner import Planner, PlannerConfig
from hg_marl.agents.planner.domain import Domain
from hg_marl.agents.planner.expectimax import expectimax
from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman, cooperative
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, Kind, World
from hg_marl.policy import Turn
from hg_marl.wrappers import homogenize_v0

WORLD = World("paper2015")


# -- the domain: a handover to the human needs a human who takes and throws ----------------


def test_a_human_who_never_throws_is_never_handed_an_object() -> None:
    # worked from the method's definition: the human ends a robot-to-human handover by
    # throwing the object into a bin it reaches, so without THROW the method never applies;
    # the control (the cooperative human, who takes and throws) has it for every object
    # whose bin the human reaches, from the robot's hand and from the robot's offer
    world = World("roboergosum")  # its bin 1 is in the human's reach (paper2015 has none)
    no_throw = Domain(world, RestrictedHuman("no_throw", HUMAN_KINDS - {Kind.THROW}))
    both = Domain(world, cooperative())
    reached = [o for o in range(world.n_objects) if both.bin_human[o]]
    assert reached
    at = world.initial_state(np.random.default_rng(0)).robot_at
    for o in reached:
        for status in (both.robot_hand, both.robot_offer):
            assert "handover_r2h" in {name for name, _ in both.works(o, status, at)}
            assert "handover_r2h" not in {name for name, _ in no_throw.works(o, status, at)}


# -- expectimax: a plan begun at the human's turn costs all its cycles ----------------------


@pytest.mark.parametrize("seed", [0, 1])
def test_a_plans_expected_cost_is_the_same_before_and_after_the_robots_planned_action(seed: int) -> None:
    # a property of the expected cost: the robot's first cycle is charged once its action
    # is under way, so asking just after the planned robot action (the human to move, that
    # action's duration given) gives the cost asked at the cycle's boundary (the same
    # value, to the sweep's tolerance), and so does the cost of the evaluated breakdown
    config = PlannerConfig()
    space = Planner(WORLD, human_model=cooperative(p_idle=0.3)).space
    state = WORLD.initial_state(np.random.default_rng(seed))
    args = (config.node_budget, config.value_tolerance, config.max_sweeps)
    before = expectimax(space, state, Agent.ROBOT, (0.0, -1), *args)
    assert before.cycles is not None
    robot_action = before.cycles[0][0]
    d_robot = WORLD.durations.of(WORLD.actions(Agent.ROBOT)[robot_action].kind)
    mid = WORLD.step(state, Agent.ROBOT, robot_action).state
    after = expectimax(space, mid, Agent.HUMAN, (d_robot, robot_action), *args)
    assert after.cycles is not None
    assert after.cost == pytest.approx(before.cost, rel=1e-6)
    assert after.cost == pytest.approx(config.weights.total(after.terms), rel=1e-6)
    assert after.cost > 10 * WORLD.durations.wait  # many cycles are left, not one


# -- the views: info's idle is the learning seat's -----------------------------------------


class _Busy:
    """A human that plays its first feasible action other than wait (wait when none is)."""

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.world, self.agent = world, agent

    def act(self, turn: Turn) -> int:
        actions = self.world.actions(self.agent)
        feasible = [int(i) for i in np.flatnonzero(np.asarray(turn.mask))]
        working = [i for i in feasible if actions[i].kind is not Kind.WAIT]
        return working[0] if working else feasible[-1]


def test_a_robot_that_only_waits_is_idle_for_the_whole_clock() -> None:
    # worked from the clock's rule: an agent that waits is idle for the whole cycle, so a
    # robot that waits at every step has been idle for every second of the clock, while
    # its partner, who works, has not (the control: partner_effort > 0)
    view = RobotView("paper2015", human=_Busy(), max_cycles=20)
    view.reset(seed=0)
    wait = next(i for i, a in enumerate(WORLD.actions(Agent.ROBOT)) if a.kind is Kind.WAIT)
    info: dict[str, Any] = {}
    for _ in range(6):
        _, _, done, truncated, info = view.step(wait)
        assert info["idle"] == pytest.approx(info["clock"])
        if done or truncated:
            break
    assert info["clock"] > 0 and info["partner_effort"] > 0


# -- the homogenising wrapper: the mask space stays int8 ------------------------------------


@pytest.mark.parametrize("dtype", [np.float32, np.int8])
def test_the_shared_action_mask_space_is_int8_whatever_the_dtype(dtype: Any) -> None:
    # the spec sheet: Dict(observation=Box(0, 1, (F + N,), dtype), action_mask=Box(0, 1, (A,), int8))
    env = homogenize_v0(hg_marl.env(), dtype=dtype)
    env.reset(seed=0)
    for agent in env.possible_agents:
        space = env.observation_space(agent)
        assert isinstance(space, spaces.Dict)
        assert space["observation"].dtype == np.dtype(dtype)
        assert space["action_mask"].dtype == np.int8
        obs = env.observe(agent)
        assert obs is not None and obs["action_mask"].dtype == space["action_mask"].dtype
