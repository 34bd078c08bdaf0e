"""BR-Prox studies: scores against each member's exact best response, the headroom beside them, population fields."""

from __future__ import annotations

import inspect
import json
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.agents.humans.preference import PreferenceHuman
from hg_marl.core.errors import StudyError
from hg_marl.training import evaluate as evaluation
from hg_marl.training.evaluate import evaluate
from hg_marl.training.store import Store
from hg_marl.training.study import Actor, load_study

CROSSING = Path(__file__).parents[1] / "agents" / "data" / "crossing.toml"
G = "preference:handover=1.0,shared=-1.0"
C = "preference:handover=-1.0,shared=1.0"


def _files(tmp_path: Path, members: str, study_extra: str = "") -> Path:
    (tmp_path / "pop.toml").write_text('name = "p"\n' + members)
    study = tmp_path / "study.toml"
    study.write_text(
        f'name = "s"\nscenarios = ["{CROSSING}"]\nseeds = 1\nduration = 300.0\nrobots = ["oracle", "planner"]\n'
        f'population = "pop.toml"\nsplits = ["held_out"]\n{study_extra}'
    )
    return study


MEMBERS = f"""
[[members]]
name = "giver"
split = "held_out"
spec = "{G}"

[[members]]
name = "counter"
split = "held_out"
spec = "{C}"

[[members]]
name = "trainee"
split = "train"
spec = "preference"
"""


def test_br_prox_is_capped_rate_over_the_members_best_response(tmp_path: Path) -> None:
    agg = evaluate(load_study(_files(tmp_path, MEMBERS)), tmp_path / "out")
    frame = pd.read_csv(tmp_path / "out" / "scores.csv")
    assert set(frame["human"]) == {"giver", "counter"}  # held_out only
    # the references are the optimal rates worked out by hand in tests/agents/test_headroom.py
    refs = frame.drop_duplicates("human").set_index("human")["oracle_rate"]
    assert refs["giver"] == pytest.approx(3600 / 17.5) and refs["counter"] == pytest.approx(3600 / 8)
    assert (frame["reference"] == "oracle").all()
    expected = (frame["rate"] / frame["oracle_rate"]).clip(upper=1.0)
    pd.testing.assert_series_equal(frame["br_prox"], expected, check_names=False)
    rows = {(r["robot"], r["split"]): r for r in agg["br_prox"]}
    assert set(rows) == {("oracle", "test"), ("planner", "test")}
    assert rows[("oracle", "test")]["runs"] == 2
    # the headroom over the held-out members: 1 - (0 + 1) / 2 (hand-worked in test_headroom.py)
    assert json.loads((tmp_path / "out" / "aggregate.json").read_text())["headroom"][str(CROSSING)] == pytest.approx(
        0.5
    )
    report = (tmp_path / "out" / "report.md").read_text()
    assert "## BR-Prox" in report and "| crossing.toml | 0.50 | test | oracle |" in report


CHANGES = {"handover": -1.0, "shared": 2.0, "keep": 2.0, "haste": 1.0, "p_idle": 0.25, "temperature": 0.5}
"""Values that change the giver's behaviour on the crossing, by its rules: it no longer hands over; it
prefers the counter; it puts the tape back on its mat instead of giving; every move scores below 0;
it idles; it draws from the softmax. (self_work, robot_side, colour_bonus and accept have nothing to
act on there: no bin the human reaches, no tape it picks on the robot's side, no colours, no offer.)"""
PARAMS = [p for p in inspect.signature(PreferenceHuman).parameters if p != "colour"]


@pytest.mark.parametrize("param", PARAMS)
def test_a_cells_reference_changes_with_every_human_parameter(tmp_path: Path, param: str, monkeypatch) -> None:
    """Each member's reference is keyed by (and solved from) all its parameters, not its family's defaults."""
    seen: list[dict] = []

    def cached(self, kind, fields, compute):  # record what the reference is keyed by, then solve
        seen.append(fields)
        return compute()

    monkeypatch.setattr(Store, "cached", cached)
    default = inspect.signature(PreferenceHuman).parameters[param].default
    changed = CHANGES.get(param, 0.5 if param == "accept" else default + 0.75)
    store = Store(tmp_path)
    base = evaluation.oracle_rate(store, Actor("preference", {"handover": 1.0, "shared": -1.0}), str(CROSSING), 10_000)
    other = evaluation.oracle_rate(
        store, Actor("preference", {"handover": 1.0, "shared": -1.0, param: changed}), str(CROSSING), 10_000
    )
    assert seen[0]["human"] != seen[1]["human"] and seen[1]["human"]["params"][param] == changed
    assert base == pytest.approx(3600 / 17.5)
    if param in CHANGES:
        assert other != pytest.approx(base)


@pytest.mark.parametrize(
    ("extra", "members", "line", "field"),
    [
        ("population = 3\n", None, 7, "population"),
        ('splits = ["heldout"]\n', None, 7, "splits"),
    ],
)
def test_bad_population_fields_are_refused_with_path_line(
    tmp_path: Path, extra: str, members: str | None, line: int, field: str
) -> None:
    study = _files(tmp_path, members or MEMBERS)
    text = study.read_text()
    key = extra.split(" =")[0]
    study.write_text("\n".join(ln for ln in text.splitlines() if not ln.startswith(key + " =")) + "\n" + extra)
    with pytest.raises(StudyError) as err:
        load_study(study)
    message = str(err.value)
    assert message.startswith(f"{study}:{line}: ") and field in message and "\n" not in message, message


def test_a_bad_member_names_the_population_file_and_line(tmp_path: Path) -> None:
    study = _files(tmp_path, MEMBERS.replace('split = "train"', 'split = "tarin"'))
    with pytest.raises(StudyError) as err:
        load_study(study)
    message = str(err.value)
    assert (
        message.startswith(f"{study}:6: population: ")
        and f"{tmp_path / 'pop.toml'}:15" in message
        and "members[2].split" in message
        and "\n" not in message
    )


def test_bundled_adaptation_study_is_valid() -> None:
    study = load_study(Path(__file__).parents[2] / "studies" / "adaptation.toml")
    assert {"forced_coordination", "asymmetric_advantages", "roboergosum"} == set(study.scenarios)
    assert study.test and set(study.test) == {h.label for h in study.humans}
    assert {"planner", "oracle", "habit", "random"} <= {r.name for r in study.robots}


def test_br_prox_is_left_empty_where_the_reference_is_the_best_robot(tmp_path: Path, monkeypatch) -> None:
    # no exact best response (as for a non-stationary partner or an oracle over its budget): the
    # score is the rate over the best robot's, and BR-Prox, which is defined against the exact
    # best response only, stays empty
    monkeypatch.setattr(evaluation, "oracle_rate", lambda *args, **kwargs: None)
    evaluate(load_study(_files(tmp_path, MEMBERS)), tmp_path / "out")
    frame = pd.read_csv(tmp_path / "out" / "scores.csv")
    assert frame["reference"].str.startswith("best robot").all()
    assert frame["score"].notna().all() and frame["br_prox"].isna().all()
