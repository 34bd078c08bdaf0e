"""The values round 93's missed bugs changed, pinned after the round (``FRESH93`` in ``mutation/planted.py``).

Each expected value is worked by hand from the module's documented rule, not read from
the code: the cooperative human's robot-action classes (duration, being a wait, being a
give), the population generator's refusal when too few candidates solve a task, the
report's figures drawn whenever some score exists, and the switching sweep's refusal of
``--seeds 0``.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import pandas as pd
import pytest

from hg_marl.core import World
from hg_marl.core.errors import ConfigError


@pytest.fixture(autouse=True)
def _close_figures() -> Any:
    yield
    plt.close("all")


def test_a_robot_give_as_long_as_a_pick_keeps_a_class_of_its_own() -> None:
    """``paper2015`` with ``give`` lengthened to 2 s (pick's and throw's length).

    The classes are keyed by (duration, is a wait, is a give): an unanswered give is no
    robot activity, so a give never shares a representative with a pick or a throw of
    the same length. By hand, the robot's 18 actions are pick x3 (0-2), throw x3 (3-5),
    give x3 (6-8), take x3 (9-11, 1.5 s), goto x5 (12-16, 3 s) and wait (17, 1 s):
    picks and throws share class 0, the gives class 6, the takes 9, the gotos 12, wait 17.
    """
    from hg_marl.agents.humans.cooperative import seen_representatives

    paper = World("paper2015")
    long_give = World("paper2015", durations=replace(paper.durations, give=2.0))
    assert seen_representatives(long_give) == [0] * 6 + [6] * 3 + [9] * 3 + [12] * 5 + [17]


class _Run:
    """A stored run as :func:`features` reads it: a log of the human's actions and a rate."""

    def __init__(self, rate: float) -> None:
        self.rate = rate

    def log(self) -> pd.DataFrame:
        return pd.DataFrame({"human_action": [0, 1], "human_action_name": ["wait", "pick(tape1)"]})


def test_too_few_candidates_solving_a_task_are_refused_by_the_candidates_message(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Three candidates, two members asked for, only candidate 0 solves a task with the planner.

    The documented refusal (the module: candidates that solve no task are dropped first;
    too few left is a ``--candidates`` error naming how many solve a task) is worked by
    hand: "only 1 of 3 candidates solve a task with planner; 2 members asked for". The
    runs are faked (one per candidate, in job order), so no episode is played.
    """
    import hg_marl.training.sweep as sweep
    from hg_marl.training.population_gen import GeneratorConfig, generate

    def fake_run_jobs(jobs: list[Any], store: Any, backend: Any, on_done: Any) -> tuple[list[_Run], Any]:
        assert len(jobs) == 3
        return [_Run(10.0), _Run(0.0), _Run(0.0)], None

    monkeypatch.setattr(sweep, "run_jobs", fake_run_jobs)
    config = GeneratorConfig(candidates=3, sizes={"train": 2}, robots=("planner",), seeds=1)
    with pytest.raises(ConfigError, match=r"--candidates: only 1 of 3 candidates solve a task with planner; 2 members"):
        generate(config, store=None, backend=object())


def test_a_study_with_one_human_without_scores_still_draws_profiles_and_intervals(tmp_path: Path) -> None:
    """Human ``k`` has no reference rate (every score n/a), human ``h`` has scores.

    The report draws ``profiles.png`` and ``intervals.png`` whenever some score exists
    (only a study without any score skips them), so all six files are written.
    """
    from hg_marl.training.report import write_outputs
    from hg_marl.training.study import Actor, Study

    study = Study(
        name="hand",
        path=Path("hand.toml"),
        robots=(Actor("A", label="A"), Actor("B", label="B")),
        humans=(Actor("h", label="h"), Actor("k", label="k")),
        scenarios=("paper2015",),
        seeds=(0, 1),
        duration=60.0,
    )
    nan = float("nan")
    scores: dict[tuple[str, str], list[float]] = {
        ("A", "h"): [0.5, 0.6],
        ("B", "h"): [0.3, 0.4],
        ("A", "k"): [nan, nan],
        ("B", "k"): [nan, nan],
    }
    frame = pd.DataFrame(
        [
            {
                "robot": r,
                "human": h,
                "scenario": "paper2015",
                "seed": i,
                "score": v,
                "oracle_rate": 100.0 if h == "h" else float("nan"),
                "reference": "oracle" if h == "h" else "none",
            }
            for (r, h), values in scores.items()
            for i, v in enumerate(values)
        ]
    )
    write_outputs(study, frame, tmp_path, {"ran": 8, "reused": 0})
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["aggregate.json", "crossplay.png", "intervals.png", "profiles.png", "report.md", "scores.csv"]


def test_a_switching_sweep_of_zero_seeds_is_refused() -> None:
    """``--seeds 0`` would run nothing and summarise empty cells: the check asks for at least one seed."""
    from hg_marl.training.switching import SwitchingConfig, check_config

    config = SwitchingConfig(
        scenario="forced_coordination",
        pairs=(("a", "b"),),
        periods=(600.0,),
        robots=("planner",),
        seeds=0,
        members=(("a", "preference"), ("b", "preference:handover=1.0,shared=-0.5")),
    )
    with pytest.raises(ConfigError, match=r"--seeds: expected an integer >= 1, got 0"):
        check_config(config)
    check_config(replace(config, seeds=1))  # the control: one seed is accepted
