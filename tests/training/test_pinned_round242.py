"""Values that round 242's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
import logging
from pathlib import Path

import pandas as pd
import pytest

from hg_marl.agents.compiled_robot import compile_robot
from hg_marl.agents.model_format import resolve_header
from hg_marl.agents.vector_envs import seat_robot
from hg_marl.core import World
from hg_marl.core.errors import ModelFileError
from hg_marl.training.adaptation import AdaptationConfig, adaptation_jobs
from hg_marl.training.aggregate import br_prox
from hg_marl.training.store import Store


def test_a_folder_holding_only_an_sb3_zip_gets_the_convert_advice(tmp_path: Path) -> None:
    # A folder with neither model.json nor policy.json but a model.zip (SB3's own save): the
    # module's rule is the one-line convert advice naming that zip, not "no model.json or
    # policy.json in this folder".
    (tmp_path / "model.zip").write_bytes(b"PK\x05\x06" + b"\0" * 18)
    with pytest.raises(ModelFileError) as caught:
        resolve_header(tmp_path)
    message = str(caught.value)
    assert message.startswith(f"{tmp_path / 'model.zip'}: an SB3 .zip, which runs code when loaded; refused.")
    assert f"hg-marl convert --trust {tmp_path / 'model.zip'}" in message
    assert "no model.json" not in message


def test_a_cached_value_edited_by_hand_is_reported_as_tampered(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    # A sealed cached value whose value is changed (118 -> 236) and not sealed again parses,
    # names its key and has its sha256, but the hash no longer matches: the store's word for
    # that is "tampered" (the module docstring: "the seal detects damage and edits"), distinct
    # from "corrupt" (unreadable, or not describing this key).
    store = Store(tmp_path)
    fields = {"human": {"name": "cooperative", "params": {}}}
    assert store.cached("oracle", fields, lambda: 118.0) == 118.0
    (path,) = (tmp_path / "cached" / "oracle").glob("*.json")
    record = json.loads(path.read_text())
    record["value"] = 236.0
    path.write_text(json.dumps(record))
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        assert store.cached("oracle", fields, lambda: 118.0) == 118.0
    (warning,) = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert f"is tampered ({path.name} does not match its sha256)" in warning


def test_the_compiled_robots_line_advises_compiled_false() -> None:
    # human_vector_env's docstring: compiled=False trains against the live robot itself, so the
    # compiled planner's description advises exactly that.
    robot = compile_robot(World("paper2015"), cache=None)
    assert seat_robot(robot) == (
        "the compiled planner robot (its plans and the progress guard only; "
        "runs and studies play the live robot: compiled=False to train against it)"
    )


def test_the_adaptation_habit_robot_is_the_papers_linear_habit() -> None:
    # The paper's habit is linear in the boolean facts, q_config={"features": "facts"} (the habit
    # robot's own default is tabular): the adaptation sweep's "habit" robot runs the paper's.
    config = AdaptationConfig(seeds=1, switches=("lazy",), robots=("habit",))
    (job,) = adaptation_jobs(config)
    assert job.robot == "habit"
    assert dict(job.robot_params) == {"q_config": {"features": "facts"}}


def test_a_br_prox_rows_runs_count_every_partner_and_seed() -> None:
    # Partners "a" and "b" both have a best response, 2 seeds each: the one entry (robot r, split
    # "all") is over a 2 seeds x 2 partners matrix, 4 runs. Its IQM trims int(0.25 * 4) = 1 run
    # each side of the sorted 0.2, 0.4, 0.6, 0.8: the mean of 0.4 and 0.6, 0.5.
    frame = pd.DataFrame(
        {
            "robot": ["r"] * 4,
            "human": ["a", "a", "b", "b"],
            "scenario": ["paper2015"] * 4,
            "seed": [0, 1, 0, 1],
            "score": [0.2, 0.4, 0.6, 0.8],
            "br_prox": [0.2, 0.4, 0.6, 0.8],
        }
    )
    (entry,) = br_prox(frame, None, reps=0)
    assert entry["split"] == "all" and entry["runs"] == 4
    assert entry["iqm"] == pytest.approx(0.5)
