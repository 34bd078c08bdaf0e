"""Study files that name a partner population: members become humans labelled by name, grouped by split."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

from hg_marl.core.errors import StudyError
from hg_marl.training.study import load_study

POPULATION = """\
name = "tiny"
scenario = "paper2015"

[[members]]
name = "m00"
split = "train"
spec = "preference"

[[members]]
name = "m01"
split = "validation"
spec = "preference:shared=1.0"

[[members]]
name = "m02"
split = "held_out"
spec = "preference:handover=0.2,accept=0.5"
"""


def write(tmp_path: Path, study: str) -> Path:
    (tmp_path / "pop.toml").write_text(POPULATION)
    path = tmp_path / "study.toml"
    path.write_text(study)
    return path


def test_members_are_humans_labelled_by_name_in_their_split(tmp_path: Path) -> None:
    study = load_study(write(tmp_path, 'robots = ["planner"]\nhumans = ["lazy"]\npopulation = "pop.toml"\n'))
    assert [(h.label, h.name, dict(h.params)) for h in study.humans] == [
        ("lazy", "lazy", {}),
        ("m00", "preference", {}),
        ("m01", "preference", {"shared": 1.0}),
        ("m02", "preference", {"handover": 0.2, "accept": 0.5}),
    ]
    assert [study.group(h.label) for h in study.humans] == ["", "train", "validation", "test"]


def test_splits_choose_the_members(tmp_path: Path) -> None:
    study = load_study(write(tmp_path, 'robots = ["planner"]\npopulation = "pop.toml"\nsplits = ["held_out"]\n'))
    assert [h.label for h in study.humans] == ["m02"]
    assert study.test == ("m02",) and study.train == ()


@pytest.mark.parametrize(
    ("text", "line", "message"),
    [
        ('robots = ["planner"]\npopulation = "pop.toml"\nsplits = ["test"]\n', 3, "splits: unknown split 'test'"),
        ('robots = ["planner"]\n\npopulation = "nowhere.toml"\n', 3, "no such population file"),
        ('robots = ["planner"]\nhumans = ["lazy"]\nsplits = ["train"]\n', 3, "splits: only with a population"),
        (
            'robots = ["planner"]\nhumans = [{ name = "lazy", label = "m00" }]\npopulation = "pop.toml"\n',
            3,
            "'m00' has the label of another",
        ),
    ],
)
def test_bad_population_fields_name_the_line(tmp_path: Path, text: str, line: int, message: str) -> None:
    path = write(tmp_path, text)
    with pytest.raises(StudyError) as info:
        load_study(path)
    assert str(info.value).startswith(f"{path}:{line}: ")
    assert message in str(info.value)


def test_a_population_study_scores_its_members(tmp_path: Path) -> None:
    from hg_marl.training.evaluate import evaluate

    path = write(tmp_path, 'seeds = 1\nduration = 60.0\nrobots = ["planner"]\npopulation = "pop.toml"\n')
    evaluate(load_study(path), tmp_path / "out")
    scores = pd.read_csv(tmp_path / "out" / "scores.csv")
    assert list(scores["human"]) == ["m00", "m01", "m02"]
    assert (scores["reference"] == "oracle").all() and (scores["score"] > 0).all()
