"""Values that round 205's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.meta.vpi import VPICriterion
from hg_marl.training import backends
from hg_marl.training.baselines.heldout_curve import COLUMNS, read_curve
from hg_marl.training.store import Job


def test_a_curve_without_held_out_partners_has_an_empty_held_out_split(tmp_path: Path) -> None:
    # A run with no held-out partners writes train rows only (checkpoints 100 and 200). Each
    # split's steps are those of its own rows: the train split has [100, 200] with the means of
    # its one partner (40 and 80 tasks/h); the held-out split has no rows, so no steps and no
    # values (not the train split's steps with empty means).
    path = tmp_path / "curve_heldout.csv"
    path.write_text(",".join(COLUMNS) + "\n" + "100,train,a,40,80,0.5\n200,train,a,80,80,1\n")
    curves = read_curve(path)
    np.testing.assert_array_equal(curves["train"]["steps"], [100, 200])
    np.testing.assert_allclose(curves["train"]["tasks_per_hour"], [40.0, 80.0])
    assert len(curves["held_out"]["steps"]) == 0
    assert len(curves["held_out"]["tasks_per_hour"]) == 0
    assert len(curves["held_out"]["br_prox"]) == 0


def test_a_held_out_split_is_read_at_its_own_checkpoints_only(tmp_path: Path) -> None:
    # The held-out partner b was scored at checkpoint 200 only: its split's steps are [200] and
    # its mean is b's 30 tasks/h; the train split keeps both of its checkpoints.
    path = tmp_path / "curve_heldout.csv"
    path.write_text(",".join(COLUMNS) + "\n" + "100,train,a,40,,\n200,train,a,80,,\n200,held_out,b,30,,\n")
    curves = read_curve(path)
    np.testing.assert_array_equal(curves["held_out"]["steps"], [200])
    np.testing.assert_allclose(curves["held_out"]["tasks_per_hour"], [30.0])
    np.testing.assert_array_equal(curves["train"]["steps"], [100, 200])


@pytest.mark.parametrize("rate_step", [1.5, -0.1])
def test_vpis_rate_step_outside_zero_to_one_is_refused_as_not_a_probability(rate_step: float) -> None:
    # rate_step is the step of a running average, R <- R + rate_step (r - R): a probability in
    # [0, 1]. 1.5 (past the target) and -0.1 are refused, naming the parameter and the range.
    with pytest.raises(ValueError, match=r"vpi\.rate_step: expected a value in \[0, 1\]"):
        VPICriterion(rate_step=rate_step)


@pytest.mark.parametrize("rate_step", [0.0, 1.0])
def test_vpis_rate_step_may_be_either_end_of_zero_to_one(rate_step: float) -> None:
    assert VPICriterion(rate_step=rate_step).rate_step == rate_step


def executed_with_a_stand_in(
    monkeypatch: pytest.MonkeyPatch, module: Any, seat: str, job: Job
) -> tuple[Any, list[tuple[str, dict[str, Any]]]]:
    """``backends.execute(job)`` with ``module.make_<seat>`` recording what it was asked and a stand-in run.

    The stand-in builds ``"<seat> <name>"``; the run hands back what was built for ``seat`` and the seed.
    Returns execute's answer and the (name, params) asked.
    """
    import hg_marl.training.runner as runner

    asked: list[tuple[str, dict[str, Any]]] = []

    def stand_in(name: str, **params: Any) -> str:
        asked.append((name, params))
        return f"{seat} {name}"

    monkeypatch.setattr(module, f"make_{seat}", stand_in)
    monkeypatch.setattr(runner, "run", lambda robot, human, config: (robot if seat == "robot" else human, config.seed))
    return backends.execute(job), asked


def test_a_jobs_robot_is_built_with_the_jobs_robot_parameters(monkeypatch: pytest.MonkeyPatch) -> None:
    # execute builds the robot as make_robot(name, **robot_params): a stand-in make_robot
    # records what it was asked, and a stand-in run hands back the robot it was given.
    import hg_marl.agents.robots as robots

    job = Job(robot="planner", seed=3, robot_params={"horizon": 7, "greedy": True})
    built, asked = executed_with_a_stand_in(monkeypatch, robots, "robot", job)
    assert built == ("robot planner", 3)
    assert asked == [("planner", {"horizon": 7, "greedy": True})]
