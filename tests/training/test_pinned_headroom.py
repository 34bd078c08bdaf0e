"""Which members a headroom report summarises, and what its files say, on hand-made matrices.

A population's report has a column per member (train, validation and held-out alike) and
takes the headroom number over the ``held_out`` members only; a list of human specs is
summarised whole. The written files are checked against matrices whose entries are
chosen by hand (no model is built except in the last test, on the one-tape crossing of
``tests/agents/data``, whose values ``tests/agents/test_headroom.py`` works out).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.headroom import HeadroomResult
from hg_marl.agents.humans.population import PopulationError
from hg_marl.core.errors import ConfigError
from hg_marl.training.headroom import heatmap_png, matrix_csv, partners, summary, write_headroom

CROSSING = str(Path(__file__).parent.parent / "agents" / "data" / "crossing.toml")
G = "preference:handover=1.0,shared=-1.0"
C = "preference:handover=-1.0,shared=1.0"

POPULATION = """name = "p"
scenario = "paper2015"

[[members]]
name = "tr"
split = "train"
spec = "preference:handover=0.5"

[[members]]
name = "ho1"
split = "held_out"
spec = "lazy"

[[members]]
name = "va"
split = "validation"
spec = "cooperative"

[[members]]
name = "ho2"
split = "held_out"
spec = "preference:shared=0.5"
"""


def test_a_population_gives_every_member_as_a_column_and_its_held_out_ones_as_the_summary(tmp_path: Path) -> None:
    path = tmp_path / "pop.toml"
    path.write_text(POPULATION)
    columns, held_out = partners(path, [])
    # every member, train first, then validation, then held out (the population's order)
    assert columns == [
        ("tr", "preference:handover=0.5"),
        ("va", "cooperative"),
        ("ho1", "lazy"),
        ("ho2", "preference:shared=0.5"),
    ]
    assert held_out == ["ho1", "ho2"]


def test_a_list_of_humans_is_summarised_whole() -> None:
    assert partners(None, ["lazy", "cooperative"]) == (
        [("lazy", "lazy"), ("cooperative", "cooperative")],
        ["lazy", "cooperative"],
    )


@pytest.mark.parametrize(
    ("population", "humans", "needle"),
    [
        (None, [], "exactly one of --population and --humans"),
        ("x.toml", ["lazy"], "exactly one of --population and --humans"),
        (None, ["lazy", "lazy"], "listed twice"),
        (None, ["no_such_human"], "--humans no_such_human"),
    ],
)
def test_bad_partner_choices_are_named(population: str | None, humans: list[str], needle: str) -> None:
    with pytest.raises(ConfigError, match=needle):
        partners(population, humans)


def test_a_bad_population_is_a_population_error(tmp_path: Path) -> None:
    path = tmp_path / "pop.toml"
    path.write_text('name = "p"\n[[members]]\nname = "a"\nsplit = "nowhere"\nspec = "lazy"\n')
    with pytest.raises(PopulationError):
        partners(path, [])


def _result(held_out: tuple[str, ...]) -> HeadroomResult:
    # cooperative row: 1/2 of a's optimum, all of b's, c has no optimum (n/a)
    return HeadroomResult(
        scenario="hand",
        assumed=("cooperative", "a", "b"),
        true=("a", "b", "c"),
        rates=np.array([[1.0, 4.0, 0.0], [2.0, 1.0, 0.0], [0.5, 4.0, 0.0]]),
        optimum=np.array([2.0, 4.0, 0.0]),
        held_out=held_out,
        n_states=7,
        seconds=0.25,
    )


def test_the_summary_is_taken_over_the_held_out_columns_of_the_cooperative_row() -> None:
    assert _result(("a", "b", "c")).headroom == pytest.approx(1 - (0.5 + 1.0) / 2)  # c (n/a) left out
    assert _result(("a",)).headroom == pytest.approx(0.5)
    assert _result(("b",)).headroom == pytest.approx(0.0)
    assert math.isnan(_result(("c",)).headroom)


def test_summary_json_fields(tmp_path: Path) -> None:
    s = summary(_result(("a", "c")))
    assert s == {
        "scenario": "hand",
        "headroom": pytest.approx(0.5),
        "held_out": ["a", "c"],
        "assumed": ["cooperative", "a", "b"],
        "true": ["a", "b", "c"],
        "optimal_rate": [2.0, 4.0, 0.0],
        "rates": [[1.0, 4.0, 0.0], [2.0, 1.0, 0.0], [0.5, 4.0, 0.0]],
        "n_states": 7,
        "seconds": 0.25,
    }
    assert summary(_result(("c",)))["headroom"] is None  # NaN is written as null, never as NaN


def test_matrix_csv_rows_are_assumed_columns_true_and_na_is_empty(tmp_path: Path) -> None:
    path = matrix_csv(_result(("a",)), tmp_path / "m.csv")
    text = path.read_text().splitlines()
    assert text[0] == "assumed \\ true,a,b,c"
    assert text[1] == "cooperative,0.500000,1.000000,"
    assert text[2] == "a,1.000000,0.250000,"
    frame = pd.read_csv(path, index_col=0)
    assert frame.loc["b", "a"] == pytest.approx(0.25) and np.isnan(frame.loc["b", "c"])


def test_heatmap_size_grows_with_the_matrix(tmp_path: Path) -> None:
    from PIL import Image

    path = heatmap_png(_result(("a",)), tmp_path / "h.png")
    # figsize (1.0 * 3 columns + 3.5, 0.5 * 3 rows + 2.2) inches at 110 dpi
    assert Image.open(path).size == (round(6.5 * 110), round(3.7 * 110))


def test_write_headroom_writes_the_three_files_into_a_new_folder(tmp_path: Path) -> None:
    out = tmp_path / "new" / "folder"
    result = write_headroom(CROSSING, [("G", G), ("C", C)], ["C"], out, progress=False)
    assert sorted(p.name for p in out.iterdir()) == ["headroom.csv", "headroom.json", "headroom.png"]
    data = json.loads((out / "headroom.json").read_text())
    assert data["held_out"] == ["C"] and data["headroom"] == pytest.approx(0.0) == result.headroom
    assert pd.read_csv(out / "headroom.csv", index_col=0).loc["G", "C"] == pytest.approx(4 / 9, abs=1e-6)


def test_write_headroom_into_an_existing_folder_replaces_its_files(tmp_path: Path) -> None:
    (tmp_path / "headroom.json").write_text("{}")  # a previous report in the folder the user names
    write_headroom(CROSSING, [("G", G), ("C", C)], ["G", "C"], tmp_path, progress=False)
    data = json.loads((tmp_path / "headroom.json").read_text())
    assert data["held_out"] == ["G", "C"] and data["headroom"] == pytest.approx(0.5)
