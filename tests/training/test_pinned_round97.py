"""Values that round 97's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses

from hg_marl.agents.models.layouts import canonical_layout_count, canonical_layouts
from hg_marl.core import World


def test_the_canonical_layout_count_counts_every_robot_start() -> None:
    # paper2015 with the robot starting at location 0 or 1. Worked by hand: its 3 objects are
    # interchangeable (one bin class); the first layout group puts 2 of them on 2 of the spots
    # (0, 1, 2), C(3, 2) = 3 deals, the second puts the last one on one of the spots (4, 5), 2
    # deals: 3 * 2 = 6 deals per start, 12 for the two starts, as many as the layouts enumerated.
    world = World(dataclasses.replace(World("paper2015").scenario, robot_start=(0, 1)))
    assert canonical_layout_count(world) == 12
    assert len(canonical_layouts(world)) == 12
