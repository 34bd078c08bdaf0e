"""The values round 79's missed planted bugs changed, pinned after the round.

Round 79 planted 16 bugs in sixteen gated modules, written blind; 15 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- ``layout_distribution`` gives every table ``World.initial_state`` can draw with its exact
  probability: the objects are dealt to the layout's spots and the robot starts at a
  uniformly drawn ``robot_start`` location, so with one object on one of two spots and two
  robot starts there are four tables, each of probability 1/2 * 1/2 = 1/4 (worked by hand),
  and the probabilities of any scenario's tables sum to 1.
"""

from __future__ import annotations

import math

import pytest

from hg_marl.agents.models.layouts import canonical_layouts, layout_distribution
from hg_marl.core import State, World
from tests.agents.test_oracle import TINY

# one object on spot a or h, two robot starts (near, far): four initial tables, each of probability 1/4
TWO_STARTS = TINY  # the oracle tests' one-object table, which has two robot starts


def test_each_table_of_a_scenario_with_two_robot_starts_has_its_share_of_the_starts() -> None:
    world = World(TWO_STARTS)
    # spots in file order: a = 0, h = 1; robot locations: near = 0, far = 1; nothing offered
    expected = {State((spot,), start, -1, -1): 0.25 for spot in (0, 1) for start in (0, 1)}
    for enumerate_layouts in (layout_distribution, canonical_layouts):
        got = dict(enumerate_layouts(world))
        assert set(got) == set(expected), enumerate_layouts.__name__
        for state, p in expected.items():
            assert got[state] == pytest.approx(p, abs=1e-12), (enumerate_layouts.__name__, state)
        # a probability distribution: the tables' probabilities sum to 1
        assert math.fsum(got.values()) == pytest.approx(1.0, abs=1e-12)
