"""Values that round 245's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.core import Agent
from hg_marl.core.errors import PopulationError
from hg_marl.core.spec import parse_spec
from hg_marl.training.baselines.bc import load_traces
from hg_marl.training.regret import regret_at
from tests.agents.test_pinned_hybrid_robot_gate import ROBOT_WAIT, STALLED, WORLD, _record, stall_partner
from tests.training.test_pinned_baselines_bc_gate import _facts, _mask, _trace


def test_a_partner_aware_planner_robot_also_moves_for_a_stalled_partner() -> None:
    """agents/robots/planner.py: "a robot whose partner keeps not doing what is expected takes
    any feasible move for one decision, so no partner ... can hold it waiting forever"; the
    partner-aware planner (``partner_aware=True``) is such a robot too. At the stalled state of
    the gate's helper (the plan needs the human, who only waits) its last decision is a feasible
    non-wait move by "random" with reason ``partner_stalled``, as for the plain planner."""
    robot = PlannerRobot(partner_aware=True)
    move, reasons = stall_partner(robot)
    assert reasons[-1] == "partner_stalled"
    record = _record(robot)
    assert record.expert == "random"
    assert move == record.action and move != ROBOT_WAIT and WORLD.mask(STALLED, Agent.ROBOT)[move]


def test_a_population_member_without_a_split_is_refused(tmp_path: Path) -> None:
    """A member must name its split (train, validation or held_out): none is not "train".
    The message names the field ``members[0].split`` and the value found (None)."""
    path = tmp_path / "pop.toml"
    path.write_text('[[members]]\nname = "m1"\nspec = "lazy"\n', encoding="utf-8")
    with pytest.raises(PopulationError, match=r"members\[0\]\.split: expected one of .* got None"):
        load_population(path)


def test_the_regret_is_read_at_the_grids_own_fractional_times() -> None:
    """Switch at 0, oracle 3600 tasks/h (one per second), one task solved at 10.2 s. By hand:
    D(10.5) = 10.5 - 1 = 9.5; D(10.1) = 10.1 - 0 = 10.1 (the task at 10.2 is not solved yet);
    D(0.5) = 0.5. Read at whole seconds instead they would be 9, 10 and 0."""
    log = pd.DataFrame({"time": [5.0, 10.2, 12.0], "reward": [0.0, 1.0, 0.0]})
    values = regret_at(log, 0.0, 3600.0, np.array([10.5, 10.1, 0.5]))
    assert values.tolist() == pytest.approx([9.5, 10.1, 0.5])


def test_a_parameter_value_holding_an_equals_sign_keeps_it() -> None:
    """``key=value`` is split at its first ``=``: ``h:inner=a=b,k=1`` has the parameter
    ``inner`` with the text ``a=b`` (a nested spec's own parameter), and ``k`` with ``1``."""
    assert dict(parse_spec("h:inner=a=b,k=1").raw) == {"inner": "a=b", "k": "1"}


def test_a_directory_of_traces_is_read_as_its_jsonl_files(tmp_path: Path) -> None:
    """``load_traces`` takes trace files "or directories of them (every ``*.jsonl`` below)":
    a folder holding a.jsonl (1 turn) and sub/b.jsonl (1 turn) gives both turns, in sorted
    path order (a.jsonl before sub/b.jsonl): actions 1 then 2."""
    folder = tmp_path / "traces"
    (folder / "sub").mkdir(parents=True)
    _trace(folder / "a.jsonl", [(_facts(0), _mask(1, 30), 1)])
    _trace(folder / "sub" / "b.jsonl", [(_facts(2), _mask(2, 30), 2)], episode=1)
    data = load_traces([folder])
    assert data.actions.tolist() == [1, 2]
    assert data.facts.tolist() == [_facts(0), _facts(2)]
