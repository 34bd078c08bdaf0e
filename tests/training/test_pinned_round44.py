"""Round 44 of the fresh planted bugs: the values its missed bugs changed, pinned.

The expected values are stated independently of the code under test: the uniform robot
draws every action its mask marks feasible and only those (a property of "uniform over the
feasible actions", checked on a hand-made mask too); paper2015's reset layouts are
enumerated by hand from its scenario file (one tape on one of the two human mats, the other
two on distinct robot-side mats: 3 x 2 x 3 x 2 = 36 tables); the controller's rule with no
planner is its docstring's (the habit acts, ``habit_only``); the human seat's reward is the
task reward less ``effort_weight`` times the seconds of its successful action, the seconds
read from the rules (``World.step``), not from the batched table.
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np
import pytest

from hg_marl.agents.meta.base import Criterion, Expert, HabitView, PlanProposal
from hg_marl.agents.meta.controller import MetaController
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.agents.vector_envs import human_vector_env
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn
from tests.core.test_pinned_world_gate import _by_hand


def _turn(world: World, state: State, mask: np.ndarray) -> Turn:
    return Turn(world, state, Agent.ROBOT, {"observation": world.facts(state), "action_mask": mask})


def test_the_random_robot_draws_every_feasible_action_and_only_those() -> None:
    """At paper2015's start the robot's feasible actions are the mask's ones (wait, the last
    action, among them): 2,000 seeded draws meet each of them (a missed one has odds
    below 1e-100 at four actions) and nothing else; with wait alone feasible it waits."""
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    mask = world.mask(state, Agent.ROBOT)
    feasible = set(np.flatnonzero(mask).tolist())
    wait = world.table.wait[Agent.ROBOT]
    assert wait in feasible and len(feasible) >= 2
    robot = RandomRobot()
    robot.reset(world, Agent.ROBOT, np.random.default_rng(1))
    drawn = [robot.act(_turn(world, state, mask)) for _ in range(2000)]
    assert set(drawn) == feasible
    only_wait = np.zeros_like(mask)
    only_wait[wait] = 1
    assert {robot.act(_turn(world, state, only_wait)) for _ in range(20)} == {wait}


def _paper2015_layouts() -> set[tuple[int, ...]]:
    """By hand from paper2015.toml (the world gate's own enumeration: spots 0-2 are the
    robot-side mats, two tapes on distinct spots, 4-5 the human mats, one tape; any tape
    may be the human-side one): 3 x 2 x 3 x 2 = 36 tables."""
    out = _by_hand()
    assert len(out) == 36
    return out


def test_a_reset_deals_every_layout_of_the_scenario_to_every_object() -> None:
    """3,000 seeded resets of paper2015 draw each of its 36 tables (a missed one has odds
    about 36 * (35/36)^3000, below 1e-35) and no other, each tape on the human side in
    about a third of them."""
    world = World("paper2015")
    rng = np.random.default_rng(7)
    states = [world.initial_state(rng) for _ in range(3000)]
    assert {s.where for s in states} == _paper2015_layouts()
    assert {s.robot_at for s in states} == {0}
    for tape in range(3):
        share = np.mean([s.where[tape] >= 4 for s in states])
        assert share == pytest.approx(1 / 3, abs=0.05)


class _AlwaysPlanner(Criterion):
    """A criterion that trusts the habit only after three visits and otherwise wants the plan."""

    name: ClassVar[str] = "always_planner"
    min_visits = 3

    def choose(self, habit: HabitView, plan: PlanProposal) -> Expert:
        return Expert.PLANNER


def test_with_no_planner_an_untrained_habit_acts_habit_only() -> None:
    """The controller's docstring: ``plan`` is None when no planner is available, and then
    the habit acts (``habit_only``, nothing planned), however few its visits."""
    n = 5
    probs = np.full(n, 1 / n)
    habit = HabitView(b"s", probs, 2, np.zeros(n), np.ones(n), 0.0, 0.0, visits=0)
    controller = MetaController(_AlwaysPlanner())
    controller.reset(np.random.default_rng(0))
    decision = controller.decide(habit, None)
    assert (decision.expert, decision.action, decision.plan, decision.reason) == (Expert.HABIT, 2, None, "habit_only")
    # with a planner, the same untrained habit defers to it (the min_visits rule)
    plan = PlanProposal.make(4, n, 0.1)
    decision = controller.decide(habit, plan)
    assert (decision.expert, decision.action, decision.reason) == (Expert.PLANNER, 4, "habit_untrained")


class _Waiter:
    """A live robot that only waits (so the human acts on the table as reset)."""

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.wait = world.table.wait[agent]

    def act(self, turn: Turn) -> int:
        return int(self.wait)


@pytest.mark.parametrize("weight", [0.0, 0.5])
def test_the_human_seats_reward_is_less_its_effort_weight_times_its_seconds_of_work(weight: float) -> None:
    """The human picks a tape it reaches on the table as reset: no task is solved, so its
    reward is ``-effort_weight * seconds``, the seconds of that successful pick as the rules
    give them (``World.step``)."""
    env = human_vector_env(num_envs=1, robot=_Waiter(), effort_weight=weight, cache=False)
    env.reset(seed=3)
    world = env.world
    st = env.state
    state = State(tuple(int(x) for x in st.where[0]), int(st.robot_at[0]), int(st.offer_by[0]), int(st.offer_obj[0]))
    picks = [i for i in np.flatnonzero(env.action_masks()[0]) if world.action_names[Agent.HUMAN][i].startswith("pick(")]
    assert picks, world.action_names[Agent.HUMAN]
    outcome = world.step(state, Agent.HUMAN, int(picks[0]))
    assert outcome.ok and outcome.reward == 0.0 and outcome.duration > 0
    _, reward, _, _, _ = env.step(np.array([picks[0]]))
    assert float(reward[0]) == pytest.approx(-weight * outcome.duration)
