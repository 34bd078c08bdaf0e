"""Shared fixtures: small hand-built states on the default scenario."""

from __future__ import annotations

import os

import pytest
from hypothesis import settings

from hg_marl.core import World

# CI replays the same examples every run (a red build must be reproducible); locally,
# hypothesis explores new random examples each time.
settings.register_profile("ci", derandomize=True)
if os.environ.get("CI"):
    settings.load_profile("ci")


@pytest.fixture(scope="session")
def paper() -> World:
    """The paper2015 world (spots: mat_left 0, mat_centre 1, mat_right 2, mat_shared 3,
    human_mat_1 4, human_mat_2 5; bin place 6; robot hand 7, human hand 8; robot
    locations bin_side 0, table_left 1, table_right 2, human_side 3)."""
    return World("paper2015")


@pytest.fixture(scope="session")
def roboergosum() -> World:
    """The roboergosum world."""
    return World("roboergosum")
