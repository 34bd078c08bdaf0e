"""The headroom matrix: values worked out by hand on a one-tape crossing, the CLI's outputs and refusals.

The layout (``data/crossing.toml``): one tape on the human's ``mat``; the bin only the
robot reaches, from ``bin_side`` (its start); the human crosses the tape by a handover
(robot at ``pass``) or by placing it on ``counter``, which the robot reaches from
``bin_side``. goto 6 s, pick/throw/place 2 s, give and wait 1 s, take 1.5 s; a cycle
lasts the longer of its two actions. Partners: G hands over only
(``handover=1, shared=-1``), C uses the counter only (``handover=-1, shared=1``).

By hand (E = seconds from one success to the next, rate = 3600 / E):
- optimal with C: the completing cycle (robot wait 1 s, C picks 2 s) 2, C places 2,
  robot picks 2, throws 2: E = 8, 450 tasks/h. The robot never moves.
- optimal with G: the completing cycle 1 (G will not pick while the robot is away), goto
  pass 6 (G picks meanwhile), G gives 1, robot takes 1.5, goto bin_side 6, throws 2:
  E = 17.5, 205.714 tasks/h.
- pi_C with G: at the re-drawn table pi_C stays at bin_side (with C the tape comes to
  the counter) and G never picks: no success ever, 0.
- pi_G with C: completing cycle 2 (C picks at once), goto pass 6 (C puts the tape on
  the counter meanwhile), goto bin_side 6 (quicker than waiting for C to bring it back:
  C does not), pick 2, throw 2: E = 18, 200 tasks/h, 200 / 450 = 0.444 of C's optimum.
- the cooperative model plans the counter route (8 s beats 17.5 s), so its row is C's.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.headroom import HeadroomResult, headroom
from hg_marl.core.errors import HumanError
from tests.cli_helpers import error_lines, run_main

CROSSING = str(Path(__file__).parent / "data" / "crossing.toml")
G = "preference:handover=1.0,shared=-1.0"
C = "preference:handover=-1.0,shared=1.0"


def test_hand_worked_matrix_on_the_crossing() -> None:
    result = headroom(CROSSING, [("G", G), ("C", C)])
    assert result.assumed == ("cooperative", "G", "C") and result.true == ("G", "C")
    np.testing.assert_allclose(result.optimum, [3600 / 17.5, 3600 / 8])
    rates = dict(zip(result.assumed, result.rates.tolist(), strict=True))
    np.testing.assert_allclose(rates["G"], [3600 / 17.5, 3600 / 18])
    np.testing.assert_allclose(rates["C"], [0.0, 3600 / 8])
    np.testing.assert_allclose(rates["cooperative"], [0.0, 3600 / 8])
    np.testing.assert_allclose(result.ratio[1], [1.0, 4 / 9])
    # IQM of the cooperative row over both partners, (0 + 1) / 2, from 1
    assert result.headroom == pytest.approx(0.5)


def test_headroom_is_taken_over_the_held_out_columns_only() -> None:
    result = headroom(CROSSING, [("G", G), ("C", C)], held_out=["C"])
    assert result.headroom == pytest.approx(0.0)  # the cooperative model is C's optimal policy


def test_no_optimum_is_nan_and_the_iqm_trims_a_quarter_each_side() -> None:
    # IQM of four values: the middle two, (0.2 + 0.6) / 2 = 0.4; their plain mean is 0.45
    ratio_row = [0.0, 0.2, 0.6, 1.0]
    result = HeadroomResult(
        scenario="x",
        assumed=("cooperative",),
        true=("a", "b", "c", "d", "e"),
        rates=np.array([[*ratio_row, 3.0]]),
        optimum=np.array([1.0, 1.0, 1.0, 1.0, 0.0]),
        held_out=("a", "b", "c", "d", "e"),
        n_states=1,
        seconds=0.0,
    )
    assert math.isnan(result.ratio[0, 4])
    assert result.headroom == pytest.approx(1 - 0.4)


def test_cli_writes_csv_heatmap_and_json(tmp_path: Path) -> None:
    code, out, err = run_main(["headroom", "--scenario", CROSSING, "--humans", f"{G},{C}", "--out", str(tmp_path)])
    assert code == 0, err
    assert "adaptation headroom 0.500" in out
    frame = pd.read_csv(tmp_path / "headroom.csv", index_col=0)
    assert list(frame.columns) == [G, C] and list(frame.index) == ["cooperative", G, C]
    assert frame.loc[G, C] == pytest.approx(4 / 9, abs=1e-6)
    summary = json.loads((tmp_path / "headroom.json").read_text())
    assert summary["headroom"] == pytest.approx(0.5) and summary["held_out"] == [G, C]
    assert (tmp_path / "headroom.png").read_bytes()[:4] == b"\x89PNG"


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--humans", "switching"], "--humans switching: human 'switching' is not stationary"),
        (["--humans", "lazy", "--population", "populations/hard_layouts.toml"], "exactly one of"),
        (["--humans", "lazy,lazy"], "listed twice"),
        (["--humans", "lazy", "--max-seconds", "nan"], "--max-seconds"),
    ],
)
def test_cli_bad_input_is_one_line_exit_2(tmp_path: Path, args: list[str], needle: str) -> None:
    code, _, err = run_main(["headroom", "--scenario", CROSSING, "--out", str(tmp_path / "o"), *args])
    lines = error_lines(err)
    assert code == 2 and len(lines) == 1 and needle in lines[0], err
    assert not (tmp_path / "o").exists()


def test_a_bad_population_file_is_named_with_its_line(tmp_path: Path) -> None:
    bad = tmp_path / "pop.toml"
    bad.write_text('name = "p"\n\n[[members]]\nname = "a"\nsplit = "train"\nspec = "preference:handover=nan"\n')
    code, _, err = run_main(["headroom", "--scenario", CROSSING, "--population", str(bad), "--out", str(tmp_path)])
    lines = error_lines(err)
    assert code == 2 and len(lines) == 1 and f"{bad}:6" in lines[0], err


def test_over_its_budget_the_cli_refuses_in_one_line(tmp_path: Path) -> None:
    # the crossing's model has 4 states at least (the layout and three answers): 2 is too few
    code, _, err = run_main(
        ["headroom", "--scenario", CROSSING, "--humans", G, "--max-states", "2", "--out", str(tmp_path / "o")]
    )
    lines = error_lines(err)
    assert code == 2 and len(lines) == 1 and "max_states=2" in lines[0], err


@pytest.mark.parametrize(
    ("true", "assumed"),
    [
        ([("cooperative", "lazy")], []),  # the cooperative model's own label
        ([("g", "lazy"), ("c", "no_handover")], [("g", "no_handover")]),  # a row and a column
        ([("g", "lazy"), ("g", "no_handover")], []),  # two columns
    ],
)
def test_a_label_that_names_two_partners_is_refused(
    true: list[tuple[str, str]], assumed: list[tuple[str, str]]
) -> None:
    # one label, one partner: the second would silently be played as the first
    with pytest.raises(HumanError, match="names two partners"):
        headroom("paper2015", true, assumed=assumed)
