"""Values that round 151's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.models.solve import solve
from hg_marl.core.atomic import atomic_write
from hg_marl.training.baselines.heldout_curve import COLUMNS, plot_generalisation
from tests.agents.test_pinned_model_solve_gate import _model


def test_the_generalisation_plot_draws_tasks_per_hour_unless_every_checkpoint_has_a_br_prox(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The held-out split has a BR-Prox at step 100 (0.8) and none at step 200 (empty cell): not
    # every checkpoint has one, so the plot falls back to tasks per hour (the docstring's rule),
    # with no 0-1.05 BR-Prox range; the same curve with a BR-Prox at both steps draws BR-Prox.
    pytest.importorskip("matplotlib")
    from hg_marl.training import plots

    caught: list[Any] = []

    def keep(fig: Any, png: Path) -> Path:
        caught.append(fig)
        return png

    monkeypatch.setattr(plots, "_save", keep)
    path = tmp_path / "curve.csv"
    train = "100,train,a,100,200,0.5\n200,train,a,200,200,1\n"
    path.write_text(",".join(COLUMNS) + "\n" + train + "100,held_out,b,80,100,0.8\n200,held_out,b,50,,\n")
    plot_generalisation(path, tmp_path / "g.png")
    ax = caught[-1].axes[0]
    assert ax.get_ylabel() == "tasks per hour"
    assert ax.get_ylim() != (0.0, 1.05)
    path.write_text(",".join(COLUMNS) + "\n" + train + "100,held_out,b,80,100,0.8\n200,held_out,b,50,100,0.5\n")
    plot_generalisation(path, tmp_path / "g.png")
    ax = caught[-1].axes[0]
    assert ax.get_ylabel() == "BR-Prox (mean over partners)"
    assert ax.get_ylim() == (0.0, 1.05)


def test_a_state_that_cannot_complete_does_not_keep_the_sweeps_from_converging() -> None:
    # The gate's hand-made model: state 0's only pair returns to 0 for ever (5 s), state 1 is the
    # completing wait. Worked by hand: state 0 cannot complete, so the sweeps hold it at 0 (its
    # pair is infinite); the first sweep gives V = (0, 0) from V = (0, 0), a change of 0 < 1e-9:
    # converged after one sweep. The reported value of state 0 is infinite.
    solution = solve(_model([0, 1, 1], [0], [1.0], [5.0], pairs=1), max_iterations=1000)
    assert solution.converged and solution.iterations == 1
    assert solution.values.tolist() == [np.inf, 0.0]


def test_an_atomic_write_takes_its_path_as_text(tmp_path: Path) -> None:
    # ``path: str | Path``: a path given as text is written as a Path would be, and the Path is returned.
    target = tmp_path / "sub" / "out.txt"
    written = atomic_write(str(target), lambda tmp: tmp.write_text("done"))
    assert isinstance(written, Path) and written == target
    assert target.read_text() == "done"
    assert sorted(p.name for p in target.parent.iterdir()) == ["out.txt"]
