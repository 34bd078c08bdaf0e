"""The values round 65's missed planted bugs changed (``mutation/planted.py``, FRESH65), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.core import World
from hg_marl.core.batch import BatchState
from hg_marl.core.errors import PopulationError
from hg_marl.envs.batched import BatchedTable
from hg_marl.training.adaptation import Switch, summarise_switch
from hg_marl.training.aggregate import stratified_bootstrap

_POPULATION = """name = "p"
scenario = "paper2015"

[spread.held_out]
selected = {selected}
random = 1.0

[[members]]
name = "m0"
split = "held_out"
spec = "preference:handover=0.8,shared=0.1"
"""


@pytest.mark.parametrize("selected", ['"high"', "nan"])
def test_a_spread_value_that_is_not_a_finite_number_is_refused(tmp_path: Path, selected: str) -> None:
    # The module docstring: a split's spread holds ``selected`` and ``random``, "the selection
    # criterion's value" (numbers), and a bad field is reported as one PopulationError line
    # naming it. A text and TOML's nan are not finite numbers; the same file with 2.31 loads.
    path = tmp_path / "p.toml"
    path.write_text(_POPULATION.format(selected=selected))
    with pytest.raises(PopulationError, match=r"spread\.held_out"):
        load_population(path)
    path.write_text(_POPULATION.format(selected="2.31"))
    assert load_population(path).spread == {"held_out": {"selected": 2.31, "random": 1.0}}


def test_a_run_that_keeps_the_oracles_pace_from_the_switch_recovers_in_0_s() -> None:
    # By hand from training/regret.py's docstring: the switch at 600 s, an oracle of 30 tasks/h
    # (one per 120 s) and a robot that solves one task every 60 s from 660 s to 1500 s. Its
    # regret D(t) = (t - 600) / 120 - N(t) is at most 0.5 (just before 660 s) and never grows
    # more than slack = 1 above D(600) = 0, so the time to recover is 0 s: a recovered run.
    times = np.arange(0.0, 1501.0, 10.0)
    reward = np.where((times > 600.0) & (times % 60.0 == 0.0), 1.0, 0.0)
    log = pd.DataFrame({"time": times, "reward": reward})
    row = summarise_switch([log], Switch(("cooperative", "lazy"), (600.0,)), 30.0, 1500.0)
    assert row["runs"] == 1
    assert row["recovered_runs"] == 1
    assert row["time_to_recover"] == {"mean": 0.0, "low": 0.0, "high": 0.0}


def test_the_bootstrap_interval_is_the_95_percent_one() -> None:
    # The docstring: a "95% percentile interval" of the statistic over the replications.
    # A statistic that answers replication r with r (whatever the resample) has replications
    # 0, 1, ..., 1999, whose 2.5th and 97.5th percentiles (numpy's linear rule: position
    # q * (n - 1)) are 0.025 * 1999 = 49.975 and 0.975 * 1999 = 1949.025.
    matrix = np.arange(6.0).reshape(3, 2)
    interval = stratified_bootstrap([matrix], lambda a: np.arange(a.shape[0], dtype=float)[:, None], 2000)
    assert interval.shape == (2, 1)
    assert interval[:, 0].tolist() == pytest.approx([49.975, 1949.025])


class _Waits:
    """A human partner that waits on every table (paper2015's human wait is index 30)."""

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.full(len(batch), 30, dtype=np.int64)


def test_a_reset_after_an_ended_episode_makes_the_next_step_a_real_cycle() -> None:
    # Gymnasium's next-step autoreset ignores the action of the step after an episode's last
    # one; reset() itself starts new episodes, so the step after a reset is a real cycle. With
    # max_cycles=1 every cycle truncates: the first step truncates, and after reset() the next
    # step plays cycle 1 again and truncates too (the robot waits 1 s).
    env = BatchedTable(_Waits(), 2, World("paper2015"), max_cycles=1)  # type: ignore[arg-type]
    env.reset(seed=0)
    wait = np.full(2, 17)
    _, _, _, truncated, _ = env.step(wait)
    assert truncated.tolist() == [True, True]
    env.reset(seed=1)
    _, _, terminated, truncated, info = env.step(wait)
    assert truncated.tolist() == [True, True]
    assert terminated.tolist() == [False, False]
    assert info["cycle"].tolist() == [1, 1]
    assert info["clock"].tolist() == pytest.approx([1.0, 1.0])
