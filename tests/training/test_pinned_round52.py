"""Round 52's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.habit import QLearner, QLearnerConfig
from hg_marl.agents.member_models import ORACLE_OPTIONS, MemberModels
from hg_marl.agents.models import StatePacker
from hg_marl.agents.models.equivariant import canonical_answers
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchState
from hg_marl.policy import Turn

SCENARIO = "paper2015"
WORLD = World(SCENARIO)


class PairedPartner:
    """Uniform over the human's feasible actions whatever it is shown (so every relabelling maps its answer
    onto itself); it answers robot actions ``2k`` and ``2k + 1`` alike, says so, and records what it is shown."""

    equivariant = True
    uses_robot_action = True

    def __init__(self) -> None:
        self.seen_asked: list[int] = []

    def seen_representatives(self, world: World) -> list[int]:
        return [a - a % 2 for a in range(world.n_actions(Agent.ROBOT))]

    def distribution(self, world: World, state: State, seen: int = -1) -> list[tuple[int, float]]:
        self.seen_asked.append(seen)
        options = sorted(world.feasible_indices(state, Agent.HUMAN))
        return [(h, 1.0 / len(options)) for h in options]


def test_a_partner_is_asked_once_per_class_of_robot_actions_it_answers_alike() -> None:
    # agents/models/equivariant.py: the answer at a mid-cycle state is the partner's answer
    # "seen the class's representative", and the live partner is asked "once per such
    # canonical key". One table asked with every robot action seen (and -1): the partner
    # above says 2k and 2k + 1 are answered alike (representative 2k), so it must be asked
    # with the even actions and -1 only, once each: ceil(n / 2) + 1 questions, counted here
    # by hand from the action count, and every row's answer is still the uniform one.
    n_robot = WORLD.n_actions(Agent.ROBOT)
    state = WORLD.initial_state(np.random.default_rng(0))
    partner: Any = PairedPartner()
    table = canonical_answers(WORLD, partner, StatePacker(WORLD))
    assert table is not None and table.uses_robot_action
    seen = np.arange(-1, n_robot, dtype=np.int64)
    size, actions, probs = table(BatchState.of([state] * len(seen)), seen, lambda i, n: None)
    options = sorted(WORLD.feasible_indices(state, Agent.HUMAN))
    assert size.tolist() == [len(options)] * len(seen)
    assert actions.tolist() == options * len(seen)
    assert np.allclose(probs, 1.0 / len(options))
    expected_asked = [-1, *range(0, n_robot, 2)]
    assert len(expected_asked) == (n_robot + 1) // 2 + 1
    assert sorted(partner.seen_asked) == expected_asked
    assert table.live_calls == len(expected_asked)


def test_a_members_one_step_model_offers_the_oracles_failed_action() -> None:
    # agents/member_models.py: members are solved with ORACLE_OPTIONS (failed_actions True:
    # the oracle models the robot's options as every feasible action, in index order, then
    # the first infeasible one standing for them all), and the member's one-step model is
    # that model's: its options on a table must be the same, listed here from the mask.
    assert ORACLE_OPTIONS["failed_actions"] is True
    members = MemberModels(("random",))
    members.reset(WORLD)
    model = members.model(0)
    for seed in range(3):
        state = WORLD.initial_state(np.random.default_rng(seed))
        mask = np.asarray(WORLD.mask(state, Agent.ROBOT), dtype=bool)
        feasible = np.flatnonzero(mask).tolist()
        infeasible = np.flatnonzero(~mask).tolist()
        assert infeasible  # a fresh table: the robot cannot, say, place an object it does not hold
        assert model.robot_options(state) == [*feasible, infeasible[0]]


def test_the_random_robot_draws_with_the_generator_it_was_reset_with() -> None:
    # agents/robots/uniform.py: "Draw one feasible action uniformly with the robot's
    # generator" (the one reset() hands over). The reference draws with an equal generator:
    # one integers(len(feasible)) per turn, the action being that feasible index. Twelve
    # turns matching by chance from another generator: (1/4) ** 12 or less.
    robot = RandomRobot()
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(11))
    reference = np.random.default_rng(11)
    for seed in range(12):
        state = WORLD.initial_state(np.random.default_rng(seed))
        mask = WORLD.mask(state, Agent.ROBOT)
        feasible = np.flatnonzero(mask)
        assert len(feasible) >= 4
        expected = int(feasible[reference.integers(len(feasible))])
        obs = {"observation": WORLD.facts(state), "action_mask": mask}
        assert robot.act(Turn(WORLD, state, Agent.ROBOT, obs)) == expected


def test_a_habit_with_beta_zero_is_accepted_and_its_policy_is_uniform() -> None:
    # agents/habit.py: the policy is softmax(beta * Q), beta the inverse temperature
    # ("higher = greedier"), checked beta >= 0: beta = 0 is the uniform policy, 1/n each
    # whatever the values (worked by hand: exp(0) / n), and only a negative beta is refused.
    config = QLearnerConfig(beta=0.0)
    habit = QLearner(n_facts=3, n_actions=4, config=config)
    facts = np.array([1, 0, 1], dtype=np.int8)
    habit.update(facts, 2, 1.0, facts, done=True)  # Q(s, 2) > 0 now: a greedy policy would prefer it
    assert habit.q_values(facts)[2] > 0
    assert habit.policy(facts).tolist() == [0.25] * 4
    with pytest.raises(ValueError, match="beta"):
        QLearnerConfig(beta=-1.0)
