"""The generalisation plot's defaults: the fallback title and the legend's size, read off the figure."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("matplotlib")

from hg_marl.training import plots
from hg_marl.training.baselines.heldout_curve import COLUMNS, plot_generalisation

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
