"""Values that round 212's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import gc
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import hg_marl
from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.training.baselines import evaluation
from hg_marl.training.io import write_json
from hg_marl.wrappers import AUDITS, audit_totals, audit_v0


def test_write_json_keeps_a_two_dimensional_arrays_rows(tmp_path: Path) -> None:
    # A 2 x 3 array is a list of its two rows, each a list of three integers (not one list of six).
    path = write_json(tmp_path / "a.json", {"grid": np.arange(6).reshape(2, 3)})
    assert json.loads(path.read_text()) == {"grid": [[0, 1, 2], [3, 4, 5]]}


def test_an_audit_that_is_gone_no_longer_counts_in_the_totals() -> None:
    """Two audits send 3 and 2 robot actions; once the first is dropped and collected, the totals are the second's."""
    AUDITS.clear()
    first, second = audit_v0(hg_marl.env()), audit_v0(hg_marl.env())
    first.sent["robot"], first.infeasible["robot"] = 3, 1
    second.sent["robot"], second.infeasible["robot"] = 2, 0
    assert audit_totals() == ({"robot": 5, "human": 0}, {"robot": 1, "human": 0})
    del first
    gc.collect()
    assert audit_totals() == ({"robot": 2, "human": 0}, {"robot": 0, "human": 0})


def test_actor_rate_plays_the_human_spec_with_its_parameters(monkeypatch: pytest.MonkeyPatch) -> None:
    # Each seed's human is built from the spec exactly as given, parameters included.
    asked: list[str] = []

    def spy(spec: str) -> Any:
        asked.append(spec)
        return make_human(spec)

    monkeypatch.setattr(evaluation, "make_human", spy)
    evaluation.actor_rate(lambda: make_robot("random"), "lazy:p_idle=0.5", "paper2015", 60.0, [0, 1])
    assert asked == ["lazy:p_idle=0.5", "lazy:p_idle=0.5"]
