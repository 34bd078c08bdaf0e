"""Seeded random scenario geometry for scaling tests (``generated:objects=6,seed=3``)."""

from __future__ import annotations

import numpy as np

from hg_marl.core.errors import ScenarioError, check_int, check_probability
from hg_marl.core.scenario_model import (
    Bin,
    LayoutGroup,
    Reach,
    Scenario,
    Spot,
    check_sizes,
)


def generate_scenario(
    objects: int = 4,
    spots: int | None = None,
    locations: int = 2,
    bins: int = 1,
    human_only: float = 0.3,
    seed: int = 0,
) -> Scenario:
    """A seeded random geometry for scaling tests.

    Args:
        objects: number of objects N.
        spots: number of spots M (default ``N + 2``); must be at least N.
        locations: robot locations; location 0 is next to the human.
        bins: bins; objects get colours so that each bin takes a share.
        human_only: probability that a spot is reachable by the human only, i.e. its
            object needs a human-to-robot handover or the human to throw it.
        seed: the generator's seed; same arguments, same scenario.
    """
    objects = check_int(objects, "generated scenario: objects", error=ScenarioError)
    spots = None if spots is None else check_int(spots, "generated scenario: spots", error=ScenarioError)
    locations = check_int(locations, "generated scenario: locations", error=ScenarioError)
    bins = check_int(bins, "generated scenario: bins", error=ScenarioError)
    seed = check_int(seed, "generated scenario: seed", minimum=0, error=ScenarioError)
    human_only = check_probability(human_only, "generated scenario: human_only", error=ScenarioError)
    n_spots = objects + 2 if spots is None else spots
    check_sizes("generated", objects, n_spots, bins, locations)
    if objects < 1 or n_spots < objects or locations < 1 or bins < 1:
        raise ScenarioError(
            f"generated scenario: need objects >= 1, spots >= objects, locations >= 1, bins >= 1; "
            f"got objects={objects}, spots={n_spots}, locations={locations}, bins={bins}"
        )
    rng = np.random.default_rng(seed)
    locs = tuple(f"loc{i}" for i in range(locations))

    def robot_subset() -> frozenset[int]:
        k = int(rng.integers(1, locations + 1))
        return frozenset(int(x) for x in rng.choice(locations, size=k, replace=False))

    spot_list = []
    for s in range(n_spots):
        if rng.random() < human_only:
            reach = Reach(frozenset(), True)
        else:
            reach = Reach(robot_subset(), bool(rng.random() < 0.3))
        spot_list.append(Spot(f"spot{s}", reach))
    colours = [f"c{b}" for b in range(bins)] if bins > 1 else [""]
    bin_list = tuple(Bin(f"bin{b}", Reach(robot_subset(), bool(rng.random() < 0.3)), colours[b]) for b in range(bins))
    return Scenario(
        name=f"generated:objects={objects},spots={n_spots},locations={locations},bins={bins},"
        f"human_only={human_only},seed={seed}",
        objects=tuple(f"obj{i}" for i in range(objects)),
        object_colours=tuple(colours[i % len(colours)] for i in range(objects)),
        bins=bin_list,
        spots=tuple(spot_list),
        robot_locations=locs,
        handover_locations=frozenset({0}),
        robot_start=(0,),
        layout=(LayoutGroup(objects, tuple(range(n_spots))),),
        description="seeded random geometry",
    )
