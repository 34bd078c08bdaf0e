"""Canonical-key answers across batches, and partners that do not read the robot's action.

Expected values come from the partner itself, asked directly (a simpler reference than
asking once per canonical key and mapping back), or are worked by hand:

- a batch whose keys are partly known and partly new answers every state as the live
  partner does, and asking a known batch again asks the live partner nothing;
- a partner without ``uses_robot_action`` is one that does not read it (the attribute's
  default), and a partner that does not read it is asked as the game asks it, with the
  robot action seen as -1 (``StationaryHuman.act``); a partner uniform over the human's
  feasible actions answers ``1 / len(feasible)`` for each, in index order.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.models import StatePacker
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.equivariant import CanonicalAnswers, actions_back, canonical_answers, object_slots
from hg_marl.core import Agent, State, World
from hg_marl.core.relabel import Relabel
from hg_marl.envs.batched import BatchState
from tests.agents.ragged import per_state
from tests.agents.test_models import mid_states


def listed(table: CanonicalAnswers, states: list[State], seen: np.ndarray) -> list[list[tuple[int, float]]]:
    """The table's answers for a batch, one list of (action, probability) per state."""
    return per_state(*table(BatchState.of(states), seen, lambda i, n: None))


@pytest.mark.parametrize("spec", ["cooperative", "cooperative:p_idle=1.0"])  # the second lists its plan at 0
def test_a_batch_with_known_and_new_keys_is_answered_as_the_live_partner_answers(spec: str) -> None:
    world = World("paper2015")
    states = mid_states(world, 600)
    seen = np.random.default_rng(5).integers(-1, world.n_actions(Agent.ROBOT), size=len(states))
    table = canonical_answers(world, stationary_human(spec, world), StatePacker(world))
    assert table is not None
    fresh = stationary_human(spec, world)
    first, second = slice(0, 300), slice(150, len(states))  # the second batch: half known, the rest new
    listed(table, states[first], seen[first])
    asked = table.live_calls
    got = listed(table, states[second], seen[second])
    assert table.live_calls > asked  # the new keys were asked
    for s, a, answers in zip(states[second], seen[second].tolist(), got, strict=True):
        assert answers == [(h, p) for h, p in fresh.distribution(world, s, a) if p > 0.0], (s, a)
    asked = table.live_calls
    again = listed(table, states[first], seen[first])
    assert table.live_calls == asked  # every key known: nobody asked
    for s, a, answers in zip(states[first], seen[first].tolist(), again, strict=True):
        assert answers == [(h, p) for h, p in fresh.distribution(world, s, a) if p > 0.0], (s, a)


class UniformPartner:
    """Uniform over the human's feasible actions (a set relabelling maps onto itself); records what it is shown."""

    equivariant = True

    def __init__(self) -> None:
        self.seen_asked: set[int] = set()

    def distribution(self, world: World, state: State, seen: int = -1) -> list[tuple[int, float]]:
        self.seen_asked.add(seen)
        options = sorted(world.feasible_indices(state, Agent.HUMAN))
        return [(h, 1.0 / len(options)) for h in options]


class BlindPartner(UniformPartner):
    uses_robot_action = False


def uniform(world: World, state: State) -> list[tuple[int, float]]:
    options = sorted(world.feasible_indices(state, Agent.HUMAN))
    return [(h, 1.0 / len(options)) for h in options]


def test_a_partner_without_the_attribute_is_asked_as_one_that_does_not_read_the_robot_action() -> None:
    world = World("paper2015")
    states = mid_states(world, 120)
    seen = np.random.default_rng(6).integers(-1, world.n_actions(Agent.ROBOT), size=len(states))
    partner: Any = UniformPartner()
    table = canonical_answers(world, partner, StatePacker(world))
    assert table is not None and not table.uses_robot_action
    for s, answers in zip(states, listed(table, states, seen), strict=True):
        assert answers == uniform(world, s), s
    assert partner.seen_asked == {-1}


def test_a_partner_that_does_not_read_the_robot_action_is_shown_none() -> None:
    world = World("paper2015")
    states = mid_states(world, 120)
    seen = np.random.default_rng(7).integers(0, world.n_actions(Agent.ROBOT), size=len(states))
    partner: Any = BlindPartner()
    table = canonical_answers(world, partner, StatePacker(world))
    assert table is not None
    for s, answers in zip(states, listed(table, states, seen), strict=True):
        assert answers == uniform(world, s), s
    assert partner.seen_asked == {-1}  # as StationaryHuman.act shows it: -1 unless it reads the robot's action


@pytest.mark.parametrize("agent", [Agent.ROBOT, Agent.HUMAN])
def test_object_slots_map_every_action_back_as_the_relabelling_does(agent: Agent) -> None:
    # The reference is the relabelling's own scalar rule (Relabel.action_back), applied to
    # whole permutations: the robot's moves to an object's place name that object too.
    world = World("roboergosum")
    relabel = Relabel(world)
    slot, remap = object_slots(world, agent)
    n = world.table.n_objects
    rng = np.random.default_rng(0)
    actions = np.arange(world.n_actions(agent))
    for _ in range(10):
        orig = tuple(rng.permutation(n).tolist())
        got = actions_back(slot, remap, actions, np.array([orig]), np.zeros(len(actions), dtype=np.int64))
        assert got.tolist() == [relabel.action_back(int(agent), a, orig) for a in actions.tolist()]
