"""The generalisation curve: train vs held-out partners at each checkpoint, its CSV and its plot."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("torch")

from hg_marl.training.baselines.heldout_curve import (
    COLUMNS,
    HeldOutCurve,
    plot_generalisation,
    read_curve,
)
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig, train_from_options, train_recurrent

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _rows(path: Path) -> list[dict[str, str]]:
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def test_a_run_writes_one_row_per_checkpoint_and_partner(tmp_path: Path) -> None:
    config = RecurrentConfig(
        humans=("preference",),
        scenario="forced_coordination",
        steps=4 * 16 * 3,  # three updates of 4 tables x 16 cycles
        num_envs=4,
        n_steps=16,
        minibatches=2,
        eval_envs=2,
        eval_seconds=60.0,
        out=tmp_path,
    ).check()
    held_out = ("preference:handover=1.0,shared=-1.0,self_work=0.5", "cooperative")
    curve = HeldOutCurve(config, held_out, every=2 * 64, oracle=True)
    train_recurrent(config, on_update=curve)
    with open(curve.path) as handle:
        assert tuple(handle.readline().strip().split(",")) == COLUMNS
    rows = _rows(curve.path)
    # Updates end at 64, 128, 192 steps; checkpoints every 128: only 128 is one.
    assert [int(r["steps"]) for r in rows] == [128] * 3
    assert [(r["split"], r["partner"]) for r in rows] == [
        ("train", "preference"),
        ("held_out", held_out[0]),
        ("held_out", "cooperative"),
    ]
    for r in rows:
        rate = float(r["tasks_per_hour"])
        assert rate >= 0.0
        if r["oracle_per_hour"]:  # BR-Prox is the rate over the oracle's, capped at 1
            assert float(r["br_prox"]) == pytest.approx(min(1.0, rate / float(r["oracle_per_hour"])), abs=1e-4)
    assert rows[0]["oracle_per_hour"], "the oracle solves the stationary preference partner"


def test_read_curve_averages_each_split_per_checkpoint(tmp_path: Path) -> None:
    path = tmp_path / "curve_heldout.csv"
    path.write_text(
        ",".join(COLUMNS)
        + "\n"
        + "100,train,a,100,200,0.5\n100,held_out,b,50,100,0.5\n100,held_out,c,150,100,1\n"
        + "200,train,a,200,200,1\n200,held_out,b,0,100,0\n200,held_out,c,100,,\n"
    )
    curves = read_curve(path)
    np.testing.assert_array_equal(curves["train"]["steps"], [100, 200])
    np.testing.assert_allclose(curves["train"]["br_prox"], [0.5, 1.0])
    np.testing.assert_allclose(curves["held_out"]["tasks_per_hour"], [100.0, 50.0])  # (50+150)/2, (0+100)/2
    # c has no oracle rate at 200: the mean is over the partners that have one (b alone)
    np.testing.assert_allclose(curves["held_out"]["br_prox"], [0.75, 0.0])
    png = plot_generalisation(path, tmp_path / "generalisation.png")
    assert png == tmp_path / "generalisation.png"
    assert png.read_bytes()[:8] == PNG_MAGIC


def test_the_command_path_writes_the_curve_and_the_plot(tmp_path: Path) -> None:
    lines = train_from_options(
        ("preference",),
        "forced_coordination",
        "members",
        64,
        0,
        tmp_path,
        32,
        False,
        ("num_envs=2", "n_steps=16", "minibatches=1", "eval_envs=2", "eval_seconds=30"),
        held_out=("cooperative",),
    )
    assert any("curve_heldout.csv" in line for line in lines)
    assert {r["split"] for r in _rows(tmp_path / "curve_heldout.csv")} == {"train", "held_out"}
    assert (tmp_path / "generalisation.png").read_bytes()[:8] == PNG_MAGIC
