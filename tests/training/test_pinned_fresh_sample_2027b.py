"""Values a third mutation sample of fourteen older gated modules found unpinned (seed 2027, 16 each).

``python mutation/run.py --modules runner,switching,... --sample 16 --seed 2027``: 188 of
224 caught. Each test below answers a survivor that changes what a user sees, with the
expected value stated from the documented rule:

- a refused run length names its cycles as the duration divided by the shortest action;
- the population generator draws each weight over its whole documented range (``handover``
  negative too) and a colour bonus uniform in (0, 1), not one value;
- the generator's local search ends where no single swap raises the spread (checked by
  trying every swap);
- an action other than a take of the offered object lets the partner's offer lapse before
  it fails (a take of another object), where a failed take of the offered object is a
  reply that fails first.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from hg_marl.core import Action, Agent, Kind, State, World
from hg_marl.core.errors import ConfigError
from hg_marl.training.population_gen import RANGES, local_search, rbf_kernel, sample_candidates, spread
from hg_marl.training.runner import check_cycles

# --- training/runner.py ---


def test_a_refused_duration_names_its_cycles_at_the_shortest_action() -> None:
    with pytest.raises(ConfigError, match=r"--duration 1e\+09: up to 5e\+09 cycles at the shortest action duration"):
        check_cycles(1e9, 0.2)  # 1e9 s / 0.2 s


# --- training/population_gen.py ---


def test_sampled_weights_cover_their_documented_ranges() -> None:
    candidates = sample_candidates("paper2015", 400, seed=3)
    for key, (lo, hi) in RANGES.items():
        values = np.array([c[key] for c in candidates])
        assert lo <= values.min() < lo + 0.1 * (hi - lo), key  # 400 uniform draws reach each end
        assert hi - 0.1 * (hi - lo) < values.max() <= hi, key
    assert min(c["handover"] for c in candidates) < 0.0


def test_the_colour_bonus_is_uniform_between_zero_and_one() -> None:
    candidates = sample_candidates("roboergosum", 400, seed=5)
    bonuses = np.array([c["colour_bonus"] for c in candidates if "colour_bonus" in c])
    assert len(bonuses) > 100  # one candidate in two has a colour
    assert bonuses.min() < 0.1 and bonuses.max() > 0.9
    assert 0.4 < bonuses.mean() < 0.6


def test_local_search_ends_where_no_single_swap_raises_the_spread() -> None:
    rng = np.random.default_rng(0)
    for trial in range(5):
        kernel = rbf_kernel(rng.normal(size=(14, 3)))
        pool = list(range(14))
        chosen = local_search(kernel, 4, pool)
        value = spread(kernel, chosen)
        for out_item, in_item in itertools.product(chosen, [i for i in pool if i not in chosen]):
            swapped = [in_item if i == out_item else i for i in chosen]
            assert spread(kernel, swapped) <= value + 1e-9, (trial, out_item, in_item)


# --- hg_marl/core/world.py ---


def test_a_take_of_another_object_lets_the_offer_lapse_before_it_fails() -> None:
    world = World("paper2015")
    robot_hand, human_side = 7, 3  # paper2015's places and the robot's locations, as in tests/core/test_rules.py
    state = State((robot_hand, 2, 8), human_side, int(Agent.HUMAN), 2)  # the human offers tape3
    take_other = world.index(Agent.ROBOT, Action(Kind.TAKE, 0))  # tape1: not the object offered
    out = world.step(state, Agent.ROBOT, take_other)
    assert not out.ok
    assert [e.kind for e in out.events] == ["let_lapse", "failed"]
    take_offered = world.index(Agent.ROBOT, Action(Kind.TAKE, 2))  # its hand is full: a reply that fails
    out = world.step(state, Agent.ROBOT, take_offered)
    assert [e.kind for e in out.events] == ["failed", "let_lapse"]
