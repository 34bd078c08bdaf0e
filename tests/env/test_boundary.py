"""The environment's constructor and API refuse bad values with the value named (HgMarlError)."""

from __future__ import annotations

import math

import pytest

from hg_marl.core import Durations
from hg_marl.core.errors import ConfigError, HgMarlError
from hg_marl.envs.table_cleaning import raw_env


@pytest.mark.parametrize(
    ("kwargs", "named"),
    [
        ({"time_budget": math.nan}, "time_budget"),
        ({"time_budget": math.inf}, "time_budget"),
        ({"time_budget": 0}, "time_budget"),
        ({"continuing": "no"}, "continuing"),
        ({"continuing": 1}, "continuing"),
        ({"max_cycles": 1.5}, "max_cycles"),
        ({"max_cycles": 0}, "max_cycles"),
        ({"durations": {"pick": math.nan}}, "durations.pick"),
        ({"durations": {"jump": 1.0}}, "durations.jump"),
        ({"durations": 3}, "durations"),
    ],
)
def test_constructor_refuses(kwargs: dict, named: str) -> None:
    with pytest.raises(ConfigError, match=named.replace(".", r"\.")):
        raw_env(**kwargs)


def test_durations_mapping_is_accepted_and_typed() -> None:
    env = raw_env(durations={"pick": 1})
    assert env.world.durations.pick == 1.0 and env.world.durations.throw == Durations().throw


def test_charge_time_and_observe() -> None:
    env = raw_env()
    env.reset(seed=0)
    for bad in (math.nan, math.inf, -1.0, "1"):
        with pytest.raises(ConfigError, match=r"charge_time"):
            env.charge_time(bad)  # type: ignore[arg-type]
    with pytest.raises(ConfigError, match="unknown agent 'alice'; the agents are robot, human"):
        env.observe("alice")


def test_durations_dataclass_refuses_non_finite() -> None:
    with pytest.raises(HgMarlError, match=r"durations\.wait"):
        Durations(wait=math.nan)
