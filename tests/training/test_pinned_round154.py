"""Values that round 154's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.memory_numpy import check_memory_file
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.model_format import ModelFile
from hg_marl.agents.model_sb3 import load_replay_buffer, save_replay_buffer
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.robots import HybridRobot
from hg_marl.core.errors import ModelFileError
from hg_marl.training.adaptation import AdaptationConfig, adaptation_jobs
from hg_marl.training.aggregate import br_prox
from tests.agents.test_pinned_hybrid_robot_gate import _record, _start, _turn
from tests.memory_arrays import memory_arrays, small_memory_header


def test_a_hybrid_decision_records_the_criterions_statistics() -> None:
    # A fresh habit has visited no state, so the default criterion (entropy_and_cost, which wants a
    # few visits before the habit may act) leaves the first decision to the planner as
    # "habit_untrained", and the MetaController's statistics behind it are the habit's 0 visits
    # there: the decision's record carries them, (("visits", 0.0),), not an empty tuple.
    robot = HybridRobot()
    robot.act(_turn(_start(robot)))
    decision = _record(robot)
    assert decision.reason == "habit_untrained"
    assert decision.stats == (("visits", 0.0),)


def test_a_memory_header_whose_recurrent_is_an_integer_is_refused(tmp_path: Path) -> None:
    # 'recurrent' must be JSON true or false; 1 equals True in Python but is not a boolean, and the
    # refusal names the field. Three facts, no history (obs_size 3), two actions, 4 hidden units,
    # the GRU's arrays present: the same header with recurrent: true is accepted.
    header = small_memory_header()
    arrays = memory_arrays(4, 3, 2, recurrent=True)
    assert check_memory_file(ModelFile(tmp_path / "m.json", header, arrays)).recurrent is True
    for value in (1, 0):
        bad = ModelFile(tmp_path / "m.json", {**header, "recurrent": value}, arrays)
        with pytest.raises(ModelFileError, match=f"field 'recurrent': expected true or false, got {value}"):
            check_memory_file(bad)


def test_a_refused_cost_mode_is_quoted_in_the_message() -> None:
    # The refusal shows the value given as its repr: the string 'fast' with its quotes.
    with pytest.raises(ValueError, match=r"expected 'model' or 'wall', got 'fast'$"):
        CostModel(mode="fast")


def test_a_saved_replay_buffer_keeps_its_timeouts(tmp_path: Path) -> None:
    # A buffer of 4 rows whose row 2 ended on a time limit (timeouts 1 there, 0 elsewhere): a fresh
    # buffer loaded from the file must hold that flag too, or a resumed SAC/DQN bootstraps through it
    # as through a real termination.
    def buffer(timeouts: list[float]) -> SimpleNamespace:
        return SimpleNamespace(
            observations=np.arange(8, dtype=np.float64).reshape(4, 2),
            actions=np.zeros((4, 1), dtype=np.int64),
            dones=np.array([[0.0], [0.0], [1.0], [0.0]], dtype=np.float32),
            timeouts=np.array(timeouts, dtype=np.float32).reshape(4, 1),
            buffer_size=4,
            pos=3,
            full=False,
        )

    entry = save_replay_buffer(buffer([0.0, 0.0, 1.0, 0.0]), tmp_path / "buffer.npz")
    target = buffer([0.0, 0.0, 0.0, 0.0])
    load_replay_buffer(target, tmp_path / "model.json", entry)
    assert target.timeouts.ravel().tolist() == [0.0, 0.0, 1.0, 0.0]


def test_a_solved_oracle_result_names_the_human_its_spec_builds() -> None:
    # A human given by its spec string: the result names the human the spec builds ("lazy", the
    # registry's name), not the type of the argument (str).
    assert oracle_rate("paper2015", "lazy:p_idle=0.5", cache=False).human == "lazy"


def test_the_adaptation_random_mix_is_the_papers_configuration() -> None:
    # The hybrid robot's docstring: the paper's configuration is criterion="random",
    # q_config={"features": "facts"}, share_objects=False; the adaptation sweep's "random" robot runs it.
    config = AdaptationConfig(seeds=1, switches=("lazy",), robots=("random",))
    (job,) = adaptation_jobs(config)
    assert job.robot == "hybrid"
    assert job.robot_params["criterion"] == "random"
    assert job.robot_params["share_objects"] is False


def test_br_prox_is_reported_for_the_partners_that_have_a_best_response() -> None:
    # Partner "a" has BR-Prox 0.5, 0.7, 0.9 over seeds 0-2; partner "b" has none (no exact best
    # response). Only "a" counts: one entry, its IQM over 3 runs trims int(0.75) = 0 each side, so
    # it is the mean 0.7; with reps 0 no interval.
    frame = pd.DataFrame(
        {
            "robot": ["r"] * 6,
            "human": ["a"] * 3 + ["b"] * 3,
            "scenario": ["paper2015"] * 6,
            "seed": [0, 1, 2] * 2,
            "score": [0.5, 0.7, 0.9, 0.4, 0.4, 0.4],
            "br_prox": [0.5, 0.7, 0.9, math.nan, math.nan, math.nan],
        }
    )
    (entry,) = br_prox(frame, None, reps=0)
    assert entry["robot"] == "r" and entry["split"] == "all" and entry["runs"] == 3 and entry["ci"] is None
    assert entry["iqm"] == pytest.approx(0.7)
