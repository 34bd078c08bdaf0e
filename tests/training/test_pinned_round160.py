"""Values that round 160's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Any

import pytest

from hg_marl.agents.models.answers import AnswerTable
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import Agent, State, World
from hg_marl.training.baselines import heldout_curve
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig


def test_the_held_out_curves_tasks_per_hour_keep_three_decimals(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The CSV rounds tasks per hour to 3 decimals (module docstring's columns; BR-Prox to 4).
    # Scored at 12.34567 tasks/h: written 12.346 (worked by hand; one decimal would write 12.3).
    # No oracle (None): the BR-Prox and oracle cells are empty. The scoring and tables are stubbed.
    def rate(net: Any, env: Any, seconds: float, seed: int) -> float:
        return 12.34567

    monkeypatch.setattr(heldout_curve, "make_env", lambda config, n: object())
    monkeypatch.setattr(heldout_curve, "greedy_rate", rate)
    config = RecurrentConfig(humans=("cooperative",), out=tmp_path)
    curve = heldout_curve.HeldOutCurve(config, ("lazy",), every=100, oracle=False)
    curve(100, net=None)
    with open(tmp_path / "curve_heldout.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [(r["split"], r["partner"], r["tasks_per_hour"], r["br_prox"]) for r in rows] == [
        ("train", "cooperative", "12.346", ""),
        ("held_out", "lazy", "12.346", ""),
    ]


class _PlainHuman:
    """A stationary partner with a distribution and no ``uses_robot_action`` attribute: it always waits."""

    def distribution(self, world: World, state: State, seen: int) -> list[tuple[int, float]]:
        return [(world.table.wait[Agent.HUMAN], 1.0)]


def test_a_table_of_a_partner_without_the_attribute_does_not_read_the_robot_action_seen() -> None:
    # AnswerTable documents its human as having distribution(world, state, robot_action); only
    # partners that say so (``uses_robot_action = True``, as the cooperative human) are keyed on
    # the robot's action seen: the humans' base class says False, and a partner that says nothing
    # reads it as False too (the lazy transitions then look its answers up by the plain keys).
    world = World("paper2015")
    table = AnswerTable(world, _PlainHuman(), StatePacker(world))
    assert table.uses_robot_action is False
