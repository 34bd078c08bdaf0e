"""Pinned against a planted bug: a human cycle with action index 0 counts in the behaviour features.

:func:`features` counts, per cycle the human played, the event of its action; a run's
log marks a robot decision without a human reply by ``human_action == -1``, and only
those rows are left out. Action index 0 is a real action (``pick(tape1)`` on
``paper2015``), so a test whose human never plays index 0 cannot tell ``>= 0`` from
``> 0``.

Worked by hand: two runs of four human cycles each, plus one row without a human reply.
Run A: ``pick(tape1)`` (index 0), ``place(tape1,mat_shared)`` (15), ``pick(tape1)`` (0),
``wait`` (30), then a robot decision with no reply (-1). Run B: ``pick(tape1)`` (0),
``throw(tape1)`` (3), ``wait`` (30), ``wait`` (30). Eight cycles: pick 3/8, throw 1/8,
place_shared 1/8, wait 3/8, the rest 0; tasks per hour the mean of 40 and 20, 30.
"""

from __future__ import annotations

import pandas as pd
import pytest

from hg_marl.training.population_gen import features

SHARED = {"mat_shared": True, "human_mat_1": False}


class LoggedRun:
    """What ``features`` reads of a stored run: its log (human action index and name per row) and its rate."""

    def __init__(self, rows: list[tuple[int, str]], rate: float) -> None:
        self.rows, self.rate = rows, rate

    def log(self) -> pd.DataFrame:
        return pd.DataFrame(self.rows, columns=["human_action", "human_action_name"])


RUN_A = LoggedRun(
    [(0, "pick(tape1)"), (15, "place(tape1,mat_shared)"), (0, "pick(tape1)"), (30, "wait"), (-1, "")], 40.0
)
RUN_B = LoggedRun([(0, "pick(tape1)"), (3, "throw(tape1)"), (30, "wait"), (30, "wait")], 20.0)


def test_cycles_where_the_human_played_action_zero_count_as_cycles_and_events() -> None:
    got = features([RUN_A, RUN_B], SHARED)
    assert got == pytest.approx(
        {
            "pick": 3 / 8,
            "throw": 1 / 8,
            "give": 0.0,
            "take": 0.0,
            "place_shared": 1 / 8,
            "place_keep": 0.0,
            "wait": 3 / 8,
            "tasks_per_hour": 30.0,
        }
    )


def test_a_run_of_action_zero_only_is_all_picks() -> None:
    """Every cycle the human picked tape1 (index 0): pick frequency 1, not 0 cycles."""
    run = LoggedRun([(0, "pick(tape1)")] * 3 + [(-1, "")], 10.0)
    got = features([run], SHARED)
    assert got["pick"] == 1.0 and got["wait"] == 0.0
