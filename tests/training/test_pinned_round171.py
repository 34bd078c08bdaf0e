"""Values that round 171's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hg_marl.agents.robots.canonical import CanonicalView
from hg_marl.core import Agent, State, World
from hg_marl.core.errors import ConfigError
from hg_marl.core.registry import Entry, Registry
from hg_marl.training.limits import check_count
from hg_marl.training.study import load_study
from tests.fuzz.test_bounds import study
from tests.training.test_pinned_round45 import _Toy


def test_a_count_written_as_a_whole_float_is_handed_back_as_an_int(tmp_path: Path) -> None:
    # check_int's rule: a float with no fraction (3.0) is the integer 3, so the count handed
    # back is the int 3, and a study's ``seeds = 3.0`` runs the seeds 0, 1 and 2
    count = check_count(3.0, "--seeds", 7)
    assert type(count) is int and count == 3
    assert load_study(study(tmp_path, "seeds = 3.0")).seeds == (0, 1, 2)


def test_a_listing_with_parameters_separates_the_entries_by_semicolons() -> None:
    # each entry reads as a call, toy(mode='1', level=1, rate=0.5); the parameters inside a call
    # are separated by commas, so the entries are separated by "; " (the same class registered
    # a second time as "copy" lists the same parameters)
    registry = Registry("thing", ConfigError, [_Toy, Entry("copy", _Toy)], list_params=True)
    call = "(mode='1', level=1, rate=0.5)"
    assert registry.listing() == f"toy{call}; copy{call}"


def test_the_canonical_view_maps_every_action_of_a_world_with_over_128_actions() -> None:
    # generated:objects=26 has 26 interchangeable objects (one bin), five robot actions per
    # object and three others: 133 actions, the last ones past 127. Objects 0 and 1 swapped
    # (places 1 and 0) are relabelled; ``wait`` names no object, so it stands for itself both
    # ways, and the map to canonical is the inverse permutation of the map back (its argsort).
    world = World("generated:objects=26,seed=0")
    n = world.n_actions(Agent.ROBOT)
    assert n == 133
    wait = int(world.table.wait[Agent.ROBOT])
    state = State(where=(1, 0, *range(2, 26)), robot_at=0, offer_by=-1, offer_obj=-1)
    _, to_original, to_canonical = CanonicalView(world, Agent.ROBOT).view(state, world.facts(state))
    assert to_original is not None and to_canonical is not None
    assert int(to_original[wait]) == wait and int(to_canonical[wait]) == wait
    np.testing.assert_array_equal(to_canonical, np.argsort(to_original))
    np.testing.assert_array_equal(to_original[to_canonical], np.arange(n))
