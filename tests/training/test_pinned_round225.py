"""Values that round 225's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hg_marl.core import ScenarioError, load_scenario
from hg_marl.core.errors import ConfigError
from hg_marl.training.play.server_limits import ServerLimits
from tests.core.test_scenario_validation import paper_text, write

# --- hg_marl/core/scenario_file.py ---


def test_a_scenario_file_without_handover_locations_is_refused_as_missing_it(tmp_path: Path) -> None:
    # handover_locations has no default (unlike robot_start, which falls back to the first
    # location): paper2015 without its `handover_locations = ["human_side"]` line is refused,
    # naming the field; with it, the handover location is human_side, the fourth of
    # robot_locations = ["bin_side", "table_left", "table_right", "human_side"], index 3.
    text = paper_text()
    line = 'handover_locations = ["human_side"]\n'
    assert text.count(line) == 1
    assert load_scenario(write(tmp_path, text)).handover_locations == frozenset({3})
    with pytest.raises(ScenarioError, match=re.escape("field 'handover_locations': missing")):
        load_scenario(write(tmp_path, text.replace(line, ""), "no_handover.toml"))


# --- training/play/server_limits.py ---


def test_a_single_connection_is_a_valid_server_limit() -> None:
    # max_connections runs from 1 to 10,000: one connection at a time is accepted, and uvicorn,
    # which counts the asking connection too, is given a concurrency limit of 1 + 1 = 2; zero
    # is refused, naming the bound of 1.
    limits = ServerLimits(max_connections=1)
    assert limits.max_connections == 1
    assert limits.uvicorn_options()["limit_concurrency"] == 2
    with pytest.raises(ConfigError, match=r"^max_connections: expected an integer >= 1, got 0$"):
        ServerLimits(max_connections=0)
