"""Values a third mutation sample of the newest modules found unpinned (seed 2027, 16 mutants each).

``python mutation/run.py --modules ... --sample 16 --seed 2027`` on the fourteen newest
gated modules: 193 of 224 caught. Each test below answers a survivor that changes what a
user sees, with the expected value stated from the documented rule:

- the oracle's rate against a partner with whom no task can complete is 0 tasks per hour
  (``lazy:p_idle=1.0`` never acts, and on ``forced_coordination`` every tape starts where
  only the human reaches), as built and as read back from the disk cache;
- the array progress guard counts a robot that walks between two places as changing the
  state (``unchanged`` stays 0) while nothing else moves (``quiet`` grows);
- the learned partner refuses a negative ``forget``, reads an unspecified robot action as
  unknown (the failed-action context), and counts a partner's action 0 like any other;
- an answer table's ``live_calls`` is the number of distributions the live human was asked,
  over several batches (an equivariant human asked once per canonical key).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.models import AnswerTable, StatePacker
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.partner_model import LearnedPartner, observe_move
from hg_marl.agents.progress import ArrayProgressGuard
from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchState
from hg_marl.envs.batched import BatchedRules
from hg_marl.policy import Turn

# --- agents/oracle.py ---


def test_a_partner_who_never_acts_where_only_it_reaches_gives_zero_tasks_per_hour(tmp_path: Path) -> None:
    built = oracle_rate("forced_coordination", "lazy:p_idle=1.0", cache=tmp_path)
    read = oracle_rate("forced_coordination", "lazy:p_idle=1.0", cache=tmp_path)  # from the disk cache
    assert read is not built
    for result in (built, read):
        assert result.seconds_per_task == float("inf")
        assert result.rate_per_hour == 0.0


# --- agents/progress.py ---


def test_the_array_guard_counts_a_walking_robot_as_changing_the_state() -> None:
    world = World("paper2015")
    where, _, by, obj = world.initial_state(np.random.default_rng(0))
    places = range(len(world.scenario.robot_locations))
    assert len(places) >= 2
    guard = ArrayProgressGuard(world)
    guard.reset_rows(np.arange(1))
    for turn in range(6):  # the robot alternates between its first two places; no object moves
        state = State(where, turn % 2, by, obj)
        guard.apply(BatchState.of([state]), np.zeros(1, dtype=np.int64))
        assert int(guard.unchanged[0]) == 0, turn
        assert int(guard.quiet[0]) == turn, turn


# --- agents/partner_model.py ---


def test_a_negative_forget_is_refused() -> None:
    with pytest.raises(ValueError, match="forget"):
        LearnedPartner(forget=-0.5)


def test_the_distribution_without_a_robot_action_is_the_failed_contexts() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    model = LearnedPartner()
    wait = world.n_actions(Agent.HUMAN) - 1
    for _ in range(4):  # evidence in the context of robot action 1 only
        model.update(world, state, 1, wait)
    assert model.distribution(world, state) == model.distribution(world, state, -1)
    assert model.distribution(world, state) != model.distribution(world, state, 1)


def test_the_partners_action_zero_is_counted() -> None:
    world = World("paper2015")
    wait_r = world.n_actions(Agent.ROBOT) - 1
    for seed in range(50):  # a first table where the human may take its action 0 (a pick)
        state = world.initial_state(np.random.default_rng(seed))
        after_robot = world.step(state, Agent.ROBOT, wait_r).state
        if 0 in world.feasible_indices(after_robot, Agent.HUMAN):
            break
    else:
        pytest.fail("no first table lets the human take its action 0")
    after_human = world.step(after_robot, Agent.HUMAN, 0).state
    turn = Turn(world, after_human, Agent.ROBOT, {}, last_actions=(wait_r, 0))
    model = LearnedPartner()
    observe_move(model, world, (state, wait_r), turn)
    (counts,) = model.counts.values()
    assert counts == {int(world.actions(Agent.HUMAN)[0].kind): 1.0}


# --- agents/models/answers.py ---


def test_live_calls_count_the_live_humans_distributions_over_several_batches() -> None:
    world = World("paper2015")
    human = stationary_human("cooperative", world)
    asked = []
    own = human.distribution

    def counting(*args: object, **kwargs: object) -> object:
        asked.append(args)
        return own(*args, **kwargs)

    human.distribution = counting
    packer = StatePacker(world)
    table = AnswerTable(world, human, packer)
    assert table.canonical is not None  # the cooperative human is asked once per canonical key
    rules = BatchedRules(world)
    rng = np.random.default_rng(1)
    batch = rules.initial(rng, 32)
    for step in range(6):  # several batches of mid-cycle keys, each with some the table lacks
        masks = rules.masks(batch, Agent.ROBOT)
        actions = (rng.random(masks.shape) * masks).argmax(1)
        ok, _, _ = rules.step(batch, Agent.ROBOT, actions)
        table.ensure(np.unique(packer.pack(batch, np.where(ok, actions, -1))))
        assert table.live_calls == len(asked) > 0, step
        masks = rules.masks(batch, Agent.HUMAN)
        rules.step(batch, Agent.HUMAN, (rng.random(masks.shape) * masks).argmax(1))
