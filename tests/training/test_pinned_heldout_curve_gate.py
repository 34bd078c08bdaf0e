"""The generalisation plot's defaults: the fallback title and the legend's size, read off the figure."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from hg_marl.training import plots
from hg_marl.training.baselines.heldout_curve import COLUMNS, plot_generalisation, read_curve

ROWS = "100,train,a,100,200,0.5\n100,held_out,b,50,100,0.5\n200,train,a,200,200,1\n200,held_out,b,0,100,0\n"


def _figure(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, title: str) -> Any:
    """The figure ``plot_generalisation`` hands to the saver (caught before it is closed)."""
    path = tmp_path / "curve.csv"
    path.write_text(",".join(COLUMNS) + "\n" + ROWS)
    caught: list[Any] = []

    def keep(fig: Any, png: Path) -> Path:
        caught.append(fig)
        return png

    monkeypatch.setattr(plots, "_save", keep)
    plot_generalisation(path, tmp_path / "g.png", title=title)
    assert len(caught) == 1
    return caught[0]


def test_an_empty_title_falls_back_to_the_default_and_a_given_one_is_kept(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    ax = _figure(tmp_path, monkeypatch, "").axes[0]
    assert ax.get_title() == "greedy policy at each checkpoint"
    ax = _figure(tmp_path, monkeypatch, "my run").axes[0]
    assert ax.get_title() == "my run"


def test_the_legend_is_set_in_eight_point_type(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    legend = _figure(tmp_path, monkeypatch, "").axes[0].get_legend()
    labels = [t.get_text() for t in legend.get_texts()]
    assert labels == ["train partners", "held-out partners", "generalisation gap"]
    assert {t.get_fontsize() for t in legend.get_texts()} == {8.0}


def test_a_partner_without_br_prox_is_left_out_of_its_splits_mean(tmp_path: Path) -> None:
    # step 100: held-out b at 0.8 and c, whose oracle solves nothing (no BR-Prox): the mean is 0.8,
    # not (0.8 + 0) / 2; step 200, c alone: no partner has one, NaN; the rates average every partner
    path = tmp_path / "curve.csv"
    rows = "100,held_out,b,80,100,0.8\n100,held_out,c,30,,\n200,held_out,c,10,,\n"
    path.write_text(",".join(COLUMNS) + "\n" + rows)
    held = read_curve(path)["held_out"]
    assert held["steps"].tolist() == [100, 200]
    assert held["br_prox"][0] == pytest.approx(0.8) and np.isnan(held["br_prox"][1])
    assert held["tasks_per_hour"].tolist() == [55.0, 10.0]
