"""scripted_v0: a project actor decides, the seat's mask shows only that decision."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from pettingzoo.test import api_test

import hg_marl
from hg_marl.agents.adapters import scripted_v0
from hg_marl.core import Agent, World
from hg_marl.policy import Turn
from hg_marl.wrappers import homogenize_v0
from tests.env.seeded_spaces import seeded


class LastFeasible:
    """Reference actor: the highest-index feasible action; counts its calls."""

    def __init__(self) -> None:
        self.calls = 0

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.calls = 0

    def act(self, turn: Turn) -> int:
        self.calls += 1
        return int(np.flatnonzero(turn.mask)[-1])


def test_scripted_seat_mask_is_one_hot_on_the_actors_choice() -> None:
    actor = LastFeasible()
    env = scripted_v0(hg_marl.env(), human=actor)
    raw = env.unwrapped
    env.reset(seed=4)
    env.step(int(np.flatnonzero(env.observe("robot")["action_mask"])[0]))
    real = raw.observe("human")["action_mask"]
    shown = env.observe("human")["action_mask"]
    assert shown.sum() == 1 and shown[np.flatnonzero(real)[-1]] == 1
    env.observe("human")
    assert actor.calls == 1  # one decision per turn, however often the seat is observed
    np.testing.assert_array_equal(env.observe("robot")["action_mask"], raw.observe("robot")["action_mask"])


def test_scripted_stack_passes_api_test() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        api_test(seeded(homogenize_v0(scripted_v0(hg_marl.env(), human="cooperative"))), num_cycles=40)


def test_scripted_needs_a_seat() -> None:
    with pytest.raises(ValueError, match="robot= or human="):
        scripted_v0(hg_marl.env())
