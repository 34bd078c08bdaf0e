"""The ``random`` human (``agents/humans/random_human.py``), pinned for the mutation gate.

Expected values from the rules (the feasible sets are ``World.feasible_indices``, the
environment's mask) and from a reference draw: ``act`` takes the ``k``-th option for
``k = rng.integers(len(options))``, replayed here with a twin generator.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.humans.random_human import RandomHuman
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn

PAPER = World("paper2015")
ASYM = World("asymmetric_advantages")


def test_the_random_human_is_uniform_over_the_feasible_actions_by_default() -> None:
    state = State((0, 1, 4), 0)
    options = PAPER.feasible_indices(state, Agent.HUMAN)
    assert len(options) > 1
    assert RandomHuman().distribution(PAPER, state) == [(i, 1.0 / len(options)) for i in options]


def test_without_the_mask_every_action_is_equally_likely() -> None:
    dist = RandomHuman(feasible_only=False).distribution(PAPER, State((0, 1, 4), 0))
    assert dist == [(i, 1.0 / 31) for i in range(31)]  # paper2015's human has 31 actions


def test_the_random_human_is_equivariant_under_swapping_interchangeable_objects() -> None:
    """tape2 and tape3 (same bins) swap places: the feasible set, and so the answer, swaps names."""
    assert RandomHuman.equivariant is True
    human = RandomHuman()
    names = ASYM.action_names[Agent.HUMAN]

    def swap(text: str) -> str:
        return text.replace("tape2", "#").replace("tape3", "tape2").replace("#", "tape3")

    first = {names[i]: p for i, p in human.distribution(ASYM, State((0, 1, 2, 3), 0))}
    swapped = {names[i]: p for i, p in human.distribution(ASYM, State((0, 2, 1, 3), 0))}
    assert {swap(n): p for n, p in first.items()} == swapped


def test_act_draws_uniformly_among_the_seats_own_feasible_actions() -> None:
    """Played in the robot's seat it draws among the robot's feasible actions, one integer per turn."""
    state = State((0, 1, 4), 0)
    options = PAPER.feasible_indices(state, Agent.ROBOT)
    obs = {"observation": PAPER.facts(state), "action_mask": PAPER.mask(state, Agent.ROBOT)}
    turn = Turn(PAPER, state, Agent.ROBOT, obs)
    human = RandomHuman()
    human.reset(PAPER, Agent.ROBOT, np.random.default_rng(9))
    twin = np.random.default_rng(9)
    drawn = [human.act(turn) for _ in range(50)]
    assert drawn == [options[int(twin.integers(len(options)))] for _ in range(50)]
    assert set(drawn) == set(options)
