"""Converting a trusted SB3 zip: what comes from the old JSON, the options and the defaults, pinned for the gate.

SB3 itself is replaced by a stand-in class (``algo_class``) that records what it was asked
to load, and the safe writer (``save_sb3``) by one that records what it was given, so the
tests see exactly which algorithm, world, seat, observation and target the converter
chose. The expected values are the module's documented rules: options override the old
JSON (``model.json`` beside the zip, else a learned human's ``policy.json``), whose
``format`` must be ``hg_marl.sb3`` or ``hg_marl.policy``; the defaults are the robot seat,
``facts`` and ``paper2015``; the new header goes beside the zip unless ``out`` is given.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.training.baselines import convert


class _Recorder:
    def __init__(self) -> None:
        self.loaded: list[tuple[str, Path, str]] = []
        self.saved: list[dict[str, Any]] = []


@pytest.fixture
def rec(monkeypatch: pytest.MonkeyPatch) -> _Recorder:
    record = _Recorder()

    def fake_algo_class(name: str) -> Any:
        class Loader:
            @staticmethod
            def load(path: Path, device: str) -> str:
                record.loaded.append((name, path, device))
                if name == "Broken":
                    raise RuntimeError("bad pickle")
                return f"model of {name}"

        return Loader

    def fake_save(model: Any, target: Path, fields: dict[str, Any], observation: str) -> Path:
        record.saved.append({"model": model, "target": target, "fields": fields, "observation": observation})
        return target

    monkeypatch.setattr(convert, "algo_class", fake_algo_class)
    monkeypatch.setattr(convert, "save_sb3", fake_save)
    return record


def _zip(folder: Path, name: str = "model.zip") -> Path:
    path = folder / name
    path.write_bytes(b"PK stand-in")
    return path


def _names(scenario: str, agent: Agent) -> tuple[list[str], list[str]]:
    world = World(scenario)
    return list(world.fact_names), list(world.action_names[agent])


def test_without_trust_nothing_is_opened(tmp_path: Path, rec: _Recorder) -> None:
    with pytest.raises(ConfigError, match=r"converting runs the code inside the zip; pass --trust only"):
        convert.convert_zip(_zip(tmp_path), trust=False, algo="PPO")
    assert rec.loaded == [] and rec.saved == []


def test_a_missing_zip_is_one_line(tmp_path: Path, rec: _Recorder) -> None:
    with pytest.raises(ModelFileError, match=r"no\.zip: no such file$"):
        convert.convert_zip(tmp_path / "no.zip", trust=True, algo="PPO")
    with pytest.raises(ModelFileError, match="no such file"):
        convert.convert_zip(tmp_path, trust=True, algo="PPO")  # a folder is not the zip


def test_without_metadata_the_defaults_are_the_robot_seat_facts_and_paper2015(tmp_path: Path, rec: _Recorder) -> None:
    """Only ``--algo``: seat robot, observation facts, scenario paper2015, header beside the zip, on the CPU."""
    zip_path = _zip(tmp_path)
    assert convert.convert_zip(zip_path, trust=True, algo="PPO") == tmp_path / "model.json"
    assert rec.loaded == [("PPO", zip_path, "cpu")]
    (saved,) = rec.saved
    facts, actions = _names("paper2015", Agent.ROBOT)
    assert saved["model"] == "model of PPO" and saved["target"] == tmp_path / "model.json"
    assert saved["observation"] == "facts"
    assert saved["fields"] == {
        "seat": "robot",
        "scenario": "paper2015",
        "scenario_name": "paper2015",
        "fact_names": facts,
        "action_names": actions,
    }


def test_without_an_algorithm_anywhere_the_option_is_asked_for(tmp_path: Path, rec: _Recorder) -> None:
    with pytest.raises(ConfigError, match=r"no metadata beside it says the algorithm; pass --algo"):
        convert.convert_zip(_zip(tmp_path), trust=True)


def test_the_old_model_json_supplies_what_the_options_do_not(tmp_path: Path, rec: _Recorder) -> None:
    """``model.json`` says DQN, the human seat, flat, its training: all used; the options win over it."""
    zip_path = _zip(tmp_path)
    facts, actions = _names("paper2015", Agent.HUMAN)
    old = {
        "format": "hg_marl.sb3",
        "algo": "DQN",
        "seat": "human",
        "observation": "flat",
        "scenario": "paper2015",
        "fact_names": facts,
        "action_names": actions,
        "train": {"steps": 12},
    }
    (tmp_path / "model.json").write_text(json.dumps(old), encoding="utf-8")
    out = tmp_path / "new" / "h.json"
    assert convert.convert_zip(zip_path, trust=True, out=out) == out
    (saved,) = rec.saved
    assert rec.loaded[0][0] == "DQN" and saved["observation"] == "flat" and saved["target"] == out
    assert saved["fields"]["seat"] == "human" and saved["fields"]["action_names"] == actions
    assert saved["fields"]["train"] == {"steps": 12}
    convert.convert_zip(zip_path, trust=True, algo="A2C", observation="dict")
    assert rec.loaded[-1][0] == "A2C" and rec.saved[-1]["observation"] == "dict"
    assert rec.saved[-1]["target"] == tmp_path / "model.json"


def test_a_learned_humans_policy_json_is_read_when_there_is_no_model_json(tmp_path: Path, rec: _Recorder) -> None:
    """``weights.zip`` has no ``weights.json``: the folder's ``policy.json`` (format hg_marl.policy) speaks."""
    zip_path = _zip(tmp_path, "weights.zip")
    (tmp_path / "policy.json").write_text(
        json.dumps({"format": "hg_marl.policy", "algo": "A2C", "seat": "human"}), encoding="utf-8"
    )
    convert.convert_zip(zip_path, trust=True)
    assert rec.loaded[0][0] == "A2C" and rec.saved[0]["fields"]["seat"] == "human"
    assert rec.saved[0]["target"] == tmp_path / "weights.json"


def test_the_zips_own_json_comes_before_policy_json(tmp_path: Path, rec: _Recorder) -> None:
    zip_path = _zip(tmp_path)
    (tmp_path / "model.json").write_text(json.dumps({"format": "hg_marl.sb3", "algo": "PPO"}), encoding="utf-8")
    (tmp_path / "policy.json").write_text(json.dumps({"format": "hg_marl.policy", "algo": "DQN"}), encoding="utf-8")
    convert.convert_zip(zip_path, trust=True)
    assert rec.loaded[0][0] == "PPO"


def test_json_of_another_format_is_not_metadata_and_the_next_one_is_tried(tmp_path: Path, rec: _Recorder) -> None:
    """A ``model.json`` of another format (or a list) is skipped; ``policy.json`` then supplies the algorithm."""
    zip_path = _zip(tmp_path)
    (tmp_path / "model.json").write_text(json.dumps({"format": "other", "algo": "PPO"}), encoding="utf-8")
    (tmp_path / "policy.json").write_text(json.dumps({"format": "hg_marl.policy", "algo": "DQN"}), encoding="utf-8")
    convert.convert_zip(zip_path, trust=True)
    assert rec.loaded[-1][0] == "DQN"
    (tmp_path / "model.json").write_text("[1, 2]", encoding="utf-8")
    (tmp_path / "policy.json").write_text(json.dumps({"algo": "DQN"}), encoding="utf-8")  # no format: not ours
    with pytest.raises(ConfigError, match="pass --algo"):
        convert.convert_zip(zip_path, trust=True)


def test_metadata_that_is_not_json_is_one_line_naming_the_file(tmp_path: Path, rec: _Recorder) -> None:
    zip_path = _zip(tmp_path)
    bad = tmp_path / "model.json"
    bad.write_text("{not json", encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"model\.json: not valid JSON \("):
        convert.convert_zip(zip_path, trust=True, algo="PPO")
    bad.write_bytes(b'{"format": "\xff"}')
    with pytest.raises(ModelFileError, match=r"model\.json: not valid JSON \("):
        convert.convert_zip(zip_path, trust=True, algo="PPO")


def test_a_seat_or_observation_outside_the_known_ones_is_refused(tmp_path: Path, rec: _Recorder) -> None:
    zip_path = _zip(tmp_path)
    with pytest.raises(ConfigError, match=r"^--seat: expected robot or human, got 'both'$"):
        convert.convert_zip(zip_path, trust=True, algo="PPO", seat="both")
    with pytest.raises(ConfigError, match=r"^--observation: expected one of facts, flat, dict, got 'pixels'$"):
        convert.convert_zip(zip_path, trust=True, algo="PPO", observation="pixels")
    assert rec.loaded == []


def test_metadata_of_another_world_is_refused_unless_the_scenario_is_given(tmp_path: Path, rec: _Recorder) -> None:
    """Facts or actions in the old JSON that are not the scenario's: refused, before SB3 opens anything."""
    zip_path = _zip(tmp_path)
    facts, actions = _names("paper2015", Agent.ROBOT)
    for changed in ({"fact_names": facts[:-1]}, {"action_names": actions[:-1]}):
        (tmp_path / "model.json").write_text(
            json.dumps({"format": "hg_marl.sb3", "algo": "PPO", **changed}), encoding="utf-8"
        )
        with pytest.raises(ConfigError, match=r"its metadata's facts or actions differ from scenario 'paper2015'"):
            convert.convert_zip(zip_path, trust=True)
    assert rec.loaded == []
    (tmp_path / "model.json").write_text(
        json.dumps({"format": "hg_marl.sb3", "algo": "PPO", "fact_names": facts, "action_names": actions}),
        encoding="utf-8",
    )
    convert.convert_zip(zip_path, trust=True)
    assert rec.saved[-1]["fields"]["fact_names"] == facts and "train" not in rec.saved[-1]["fields"]


def test_the_scenario_option_names_the_world(tmp_path: Path, rec: _Recorder) -> None:
    """``--scenario`` builds that world: its facts and actions, and its spec as written."""
    zip_path = _zip(tmp_path)
    convert.convert_zip(zip_path, trust=True, algo="PPO", scenario="asymmetric_advantages")
    facts, actions = _names("asymmetric_advantages", Agent.ROBOT)
    fields = rec.saved[0]["fields"]
    assert fields["scenario"] == "asymmetric_advantages" and fields["fact_names"] == facts
    assert fields["action_names"] == actions


def test_what_sb3_cannot_load_is_one_line(tmp_path: Path, rec: _Recorder) -> None:
    with pytest.raises(ModelFileError, match=r"model\.zip: SB3 could not load it \(bad pickle\)$"):
        convert.convert_zip(_zip(tmp_path), trust=True, algo="Broken")
    assert rec.saved == []


def test_a_robot_seat_read_from_the_old_json_is_the_robot_seat(tmp_path: Path, rec: _Recorder) -> None:
    """``"seat": "robot"`` decoded from JSON (a new string, not the literal): the robot's actions."""
    zip_path = _zip(tmp_path)
    (tmp_path / "model.json").write_text(
        json.dumps({"format": "hg_marl.sb3", "algo": "PPO", "seat": "robot"}), encoding="utf-8"
    )
    convert.convert_zip(zip_path, trust=True)
    fields = rec.saved[-1]["fields"]
    assert fields["seat"] == "robot" and fields["action_names"] == _names("paper2015", Agent.ROBOT)[1]
    convert.convert_zip(zip_path, trust=True, seat="".join(["hu", "man"]))
    assert rec.saved[-1]["fields"]["seat"] == "human"


def test_the_options_after_the_zip_are_keyword_only(tmp_path: Path, rec: _Recorder) -> None:
    """``trust`` must be named: ``convert_zip(path, True)`` is a TypeError, so no caller vouches by position."""
    with pytest.raises(TypeError):
        convert.convert_zip(_zip(tmp_path), True)
    assert rec.loaded == []
