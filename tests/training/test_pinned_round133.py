"""Values that round 133's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Any

import pytest

from hg_marl.agents.meta.vpi import VPICriterion
from hg_marl.training.baselines import heldout_curve
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig


def test_the_held_out_curves_br_prox_keeps_four_decimals(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The CSV rounds tasks per hour to 3 decimals and BR-Prox to 4. Scored at 12.5 tasks/h
    # against an oracle of 37.5: BR-Prox = 12.5 / 37.5 = 1/3, written 0.3333 (worked by hand;
    # two decimals would write 0.33). The scoring and the tables are stubbed: no network needed.
    def rate(net: Any, env: Any, seconds: float, seed: int) -> float:
        return 12.5

    monkeypatch.setattr(heldout_curve, "make_env", lambda config, n: object())
    monkeypatch.setattr(heldout_curve, "oracle_per_hour", lambda scenario, partner: 37.5)
    monkeypatch.setattr(heldout_curve, "greedy_rate", rate)
    config = RecurrentConfig(humans=("cooperative",), out=tmp_path)
    curve = heldout_curve.HeldOutCurve(config, ("lazy",), every=100)
    curve(100, net=None)
    with open(tmp_path / "curve_heldout.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [(r["split"], r["partner"], r["oracle_per_hour"], r["br_prox"]) for r in rows] == [
        ("train", "cooperative", "37.5", "0.3333"),
        ("held_out", "lazy", "37.5", "0.3333"),
    ]


def test_vpis_running_reward_moves_two_percent_per_decision_by_default() -> None:
    # vpi.py documents rate_step's default as 0.02: R <- R + 0.02 (r - R) from R = 0. Two
    # rewards of 1 (worked by hand): 0.02, then 0.02 + 0.02 * 0.98 = 0.0396; the planning
    # threshold tau * R with the default tau 0.08 is then 0.08 * 0.0396 = 0.003168.
    criterion = VPICriterion()
    assert criterion.rate_step == 0.02
    criterion.observe(1.0)
    assert criterion.reward_rate == pytest.approx(0.02, abs=1e-12)
    criterion.observe(1.0)
    assert criterion.reward_rate == pytest.approx(0.0396, abs=1e-12)
    assert criterion.tau * criterion.reward_rate == pytest.approx(0.003168, abs=1e-12)
