"""Values that round 229's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import logging
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.meta.base import PlanProposal
from hg_marl.agents.planner.domain import Domain
from hg_marl.agents.planner.models import cooperative
from hg_marl.core import Kind, World
from hg_marl.training.backends import make_backend
from hg_marl.training.baselines.bc import behaviour_clone
from tests.training.test_pinned_baselines_bc_gate import _facts, _mask, _trace


def test_a_plan_proposal_made_without_a_human_action_expects_none() -> None:
    # The field's documentation: "The human action the plan expects next, or -1". A proposal
    # built without naming one (make's keyword or the constructor) expects nothing: -1, never
    # a real human action index such as 0.
    made = PlanProposal.make(2, 5, 0.25)
    built = PlanProposal(True, 2, np.full(5, 0.2), 0.25)
    assert made.human_action == -1
    assert built.human_action == -1
    assert PlanProposal.make(2, 5, 0.25, human_action=0).human_action == 0


def test_a_handover_from_the_humans_hand_counts_the_robots_empty_trip_to_the_handover() -> None:
    # paper2015: one bin, reached by the robot from location 0 only and by no human; the handover
    # is location 3, not a place where the robot can let go of an object (the human throws nothing),
    # so the robot must first go there empty-handed. Durations: take 1.5, throw 2, give 1, goto 3.
    # An object in the human's hand, robot-to-human disposal: the robot goes to the handover (3),
    # takes (1.5), carries it to the bin (3) and throws (2): 3 + 1.5 + 3 + 2 = 9.5 s; the human
    # gives (1 s), holding the object through that give (1 s).
    world = World("paper2015")
    d = world.durations
    assert (d.take, d.throw, d.give, d.goto) == (1.5, 2.0, 1.0, 3.0)
    domain = Domain(world, cooperative())
    works = dict(domain.works(0, domain.human_hand, 0))
    assert works["handover_h2r"] == (9.5, 1.0, frozenset(), frozenset({Kind.GIVE}), 1.0)


def test_the_local_backend_made_by_name_runs_the_workers_asked_for() -> None:
    # make_backend("local", workers=2) is "a pool of workers processes": capacity 2, a pool of
    # two (no process starts before a job is submitted, so nothing runs here).
    backend = make_backend("local", workers=2)
    try:
        assert backend.capacity == 2
        pool = vars(backend)["_pool"]
        assert isinstance(pool, ProcessPoolExecutor)
        assert vars(pool)["_max_workers"] == 2
    finally:
        backend.close()


def test_the_clone_log_counts_distinct_observations_not_steps(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    # Three recorded turns, two of them on the same fact vector: 3 steps, 2 distinct observations;
    # the table (majority per fact vector) reproduces all three actions: accuracy 1.
    steps = [(_facts(0), _mask(1, 30), 1), (_facts(0), _mask(1, 30), 1), (_facts(1), _mask(30), 30)]
    trace = _trace(tmp_path / "t.jsonl", steps)
    with caplog.at_level(logging.INFO, logger="hg_marl.training.baselines.bc"):
        _, accuracy = behaviour_clone([trace], tmp_path / "out")
    assert accuracy == 1.0
    assert "behaviour cloning (table): 3 steps, 2 distinct observations, accuracy 1.000" in caplog.messages
