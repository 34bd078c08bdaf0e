"""Values that round 120's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.headroom import HeadroomResult
from hg_marl.agents.humans.adversarial import AdversarialHuman
from hg_marl.core import State, World
from hg_marl.training import switching
from hg_marl.training.headroom import summary
from tests.agents.test_pinned_human_adversarial_gate import named
from tests.training.test_pinned_switching import CONFIG, _stand_ins


def test_the_headroom_json_keeps_the_headroom_unrounded() -> None:
    # One held-out partner "a": the cooperative model's policy gets 1 task/h where a's optimum is
    # 3 tasks/h, a ratio of 1/3, so the headroom is 1 - 1/3 = 2/3 = 0.666..., written as computed
    # (rounded to two decimals it would read 0.67).
    result = HeadroomResult(
        scenario="hand",
        assumed=("cooperative", "a"),
        true=("a",),
        rates=np.array([[1.0], [3.0]]),
        optimum=np.array([3.0]),
        held_out=("a",),
        n_states=1,
        seconds=0.0,
    )
    assert summary(result)["headroom"] == pytest.approx(2.0 / 3.0, rel=1e-12)


def test_of_two_objects_stolen_alike_the_adversary_takes_the_first() -> None:
    # roboergosum, robot at ROBOT_LOC (0): placemat3 (2) and placemat4 (3) are both within the
    # human's reach and the robot's from where it stands, so green1 and green2 are equally "about
    # to be picked"; the candidates go in object order (as the tidying rule's do), so green1
    # (object 0) is stolen, whichever of the two mats it lies on.
    world = World("roboergosum")
    for where in ((3, 2, 0, 1, 8, 8), (2, 3, 0, 1, 8, 8)):
        assert named(world, AdversarialHuman().distribution(world, State(where, 0))) == [("pick(green1)", 1.0)]


def test_recovered_runs_counts_each_robots_own_recovered_seeds(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    # 1000 s, period 400: A [0, 400), B [400, 800), A [800, 1000]; min_phase 250 reads only the
    # change into B at 400 (the last phase lasts 200 s). B keeps 36 tasks/h (0.01 task/s).
    # A seed solving at 500, 600, 700 and 800 s keeps within one task of B's pace from the change
    # on: D peaks at 0.01 * (t - 400) - tasks before t = 1 at each solve, <= 1: recovered in 0 s.
    # A seed solving nothing: D reaches 4 at 800 while the 125 s tail allows tau <= 675 (D >= 3
    # after 700 is needed): no recovery. "other" recovers on seed 0 only: 1 recovered run; the
    # planner on both: 2.
    pace = [500.0, 600.0, 700.0, 800.0]
    _stand_ins(monkeypatch, {("planner", 0): pace, ("planner", 1): pace, ("other", 0): pace, ("other", 1): []})
    config = dataclasses.replace(CONFIG, duration=1000.0, min_phase=250.0)
    cells = {c["robot"]: c for c in switching.run_switching(config, tmp_path)["cells"]}
    assert cells["planner"]["recovered_runs"] == 2
    assert cells["other"]["recovered_runs"] == 1
    assert cells["other"]["recovery"]["mean"] == pytest.approx(0.0)
