"""Values that round 135's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.core.scenario_generated import generate_scenario


def test_a_generated_spots_robot_reach_is_k_distinct_locations_k_uniform() -> None:
    # A robot-reachable spot's locations are "k drawn at random, k uniform in 1..locations", drawn
    # without replacement: with 3 locations each size 1, 2, 3 comes up a third of the time. Over
    # 300 spots (human_only=0: every spot robot-reachable) that is 100 each, binomial sd 8.2:
    # 70-130 is 3.6 sd either side. Drawn with replacement, size 3 needs 3 distinct draws of 3
    # (6/27) and comes up about 300 x 1/3 x 2/9 = 22 times.
    sizes = {1: 0, 2: 0, 3: 0}
    for seed in range(3):
        scenario = generate_scenario(objects=30, spots=100, locations=3, human_only=0.0, seed=seed)
        for spot in scenario.spots:
            sizes[len(spot.reach.robot_from)] += 1
    assert sum(sizes.values()) == 300
    assert all(70 <= n <= 130 for n in sizes.values()), sizes
