"""Values round 61's missed planted bugs changed, pinned after the round (see mutation/planted.py's FRESH61)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from hg_marl.agents.habit import QLearnerConfig
from hg_marl.agents.models.layouts import canonical_layout_count
from hg_marl.agents.planner.planner import Planner
from hg_marl.core import Agent, State, World
from hg_marl.core.scenario import BUILTIN


def test_an_uncertainty_rate_of_one_is_accepted() -> None:
    # uncertainty_rate is the rate of a running mean of squared TD errors: any rate in (0, 1] is a
    # running mean, and rate 1 (the mean is the latest squared TD error) is its legal end point.
    assert QLearnerConfig(uncertainty_rate=1.0).uncertainty_rate == 1.0
    with pytest.raises(ValueError, match="uncertainty_rate"):
        QLearnerConfig(uncertainty_rate=1.5)


def _deals_by_brute_force(world: World) -> int:
    """Count the deals by labelling every spot of each layout group with a class or nothing.

    A deal fills exactly ``count`` of a group's spots, each with one object class, using no
    more objects of a class than are left: the class make-up and its spot assignment of
    :func:`canonical_layouts`. Times the robot's starts, as the count's docstring says.
    """
    sizes: dict[tuple[int, ...], int] = {}
    for bins in world.bins_of:
        sizes[bins] = sizes.get(bins, 0) + 1
    left0 = tuple(sizes.values())
    groups = world.scenario.layout

    def count(k: int, left: tuple[int, ...]) -> int:
        if k == len(groups):
            return 1
        group = groups[k]
        total = 0
        for labels in itertools.product(range(-1, len(left)), repeat=len(group.spots)):
            if sum(lab >= 0 for lab in labels) != group.count:
                continue
            used = [labels.count(c) for c in range(len(left))]
            if any(u > n for u, n in zip(used, left, strict=True)):
                continue
            total += count(k + 1, tuple(n - u for n, u in zip(left, used, strict=True)))
        return total

    return len(world.scenario.robot_start) * count(0, left0)


@pytest.mark.parametrize("name", BUILTIN)
def test_the_canonical_layout_count_is_the_number_of_deals(name: str) -> None:
    # Reference: a brute-force count of the deals (every labelling of each group's spots).
    world = World(name)
    assert canonical_layout_count(world) == _deals_by_brute_force(world)


@pytest.mark.parametrize("by", [Agent.HUMAN, Agent.ROBOT], ids=["human", "robot"])
def test_the_bounds_statuses_give_an_offered_object_0_its_offer_code(by: Agent) -> None:
    # Domain.status's rule (its docstring): an offered object's status is the offer code of
    # whoever offers it, whatever its index; object 0 is as much an object as the others.
    planner = Planner(World("paper2015"))
    space, domain = planner.space, planner.domain
    where = list(planner.world.initial_state(np.random.default_rng(0)).where)
    state = State(tuple(where), 0, int(by), 0)
    want = domain.human_offer if by == Agent.HUMAN else domain.robot_offer
    got = space.statuses(state)
    assert got[0] == want
    assert got[1:] == where[1:]
