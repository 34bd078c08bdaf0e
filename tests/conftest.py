"""Shared fixtures: small hand-built states on the default scenario."""

from __future__ import annotations

import importlib.util
import os

import pytest
from hypothesis import settings

from hg_marl.core import World

# CI replays the same examples every run (a red build must be reproducible); locally,
# hypothesis explores new random examples each time. No example fails for being slow
# (hypothesis's default 200 ms deadline would fail tests on a loaded machine).
settings.register_profile("no_deadline", deadline=None)
settings.register_profile("ci", parent=settings.get_profile("no_deadline"), derandomize=True)
settings.load_profile("ci" if os.environ.get("CI") else "no_deadline")


EXTRAS = {"sb3": ("torch", "stable_baselines3", "sb3_contrib"), "video": ("imageio_ffmpeg",)}
"""Optional extras, by pytest marker, and the modules each needs."""


def pytest_configure(config: pytest.Config) -> None:
    """Fail the session when an extra a marked test needs is missing where it is required.

    Required in CI (``CI`` set) and when ``HG_MARL_REQUIRE_EXTRAS=1``: there a missing extra
    would make its test modules skip themselves, and a stage would pass having tested
    nothing. Elsewhere the modules skip with the reason "needs the ... extra".
    """
    if not (os.environ.get("CI") or os.environ.get("HG_MARL_REQUIRE_EXTRAS") == "1"):
        return
    if os.environ.get("HG_MARL_REQUIRE_EXTRAS") == "0":
        return
    missing = [
        f"{extra} ({name})"
        for extra, modules in EXTRAS.items()
        for name in modules
        if importlib.util.find_spec(name) is None
    ]
    if missing:
        raise pytest.UsageError(
            f"missing optional extras: {', '.join(missing)}; install them (pip install -e '.[sb3,video]') "
            "or set HG_MARL_REQUIRE_EXTRAS=0 to let their tests skip"
        )


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
