"""Values that round 128's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import inspect

from hg_marl.core import World
from hg_marl.core.scenario import BUILTIN, DEFAULT_SCENARIO
from hg_marl.envs.table_cleaning import raw_env


def test_the_default_scenario_is_paper2015_as_unnamed_worlds_take() -> None:
    # The exported default names the paper's layout (Devin et al. 2015): "paper2015", the first of the
    # built-ins and the scenario a World and the AEC env are built on when none is named (their own
    # signature defaults, read here without the loader's constant).
    assert DEFAULT_SCENARIO == "paper2015"
    assert BUILTIN[0] == DEFAULT_SCENARIO
    assert inspect.signature(World).parameters["scenario"].default == DEFAULT_SCENARIO
    assert inspect.signature(raw_env).parameters["scenario"].default == DEFAULT_SCENARIO
    assert World().scenario.name == DEFAULT_SCENARIO
