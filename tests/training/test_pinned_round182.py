"""Values that round 182's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.core.errors import PopulationError, RobotError
from hg_marl.training.baselines.comparison import CompareConfig, summarise
from tests.agents.test_population import GOOD
from tests.training.test_pinned_baselines_comparison_gate import _cell


def test_a_planner_robots_partner_aware_that_is_not_a_bool_is_refused_under_its_own_name() -> None:
    # The option is called partner_aware (the registry's parameter and the study files' key), so the
    # refusal names "planner.partner_aware", the robot's name and the parameter as the user wrote it.
    with pytest.raises(RobotError) as caught:
        PlannerRobot(partner_aware="yes")
    assert str(caught.value) == "planner.partner_aware: expected true or false, got 'yes'"


def test_an_empty_member_spec_is_refused_as_a_missing_human_spec(tmp_path: Path) -> None:
    # The second member's spec is the empty text: the file names no human there at all, so the
    # refusal is the spec field's own ("expected a human spec like ..., got ''") on that member's line,
    # not whatever a human parser says of an empty name.
    path = tmp_path / "p.toml"
    path.write_text(GOOD.replace('spec = "preference:handover=0.2,accept=0.5"', 'spec = ""'))
    with pytest.raises(PopulationError) as caught:
        load_population(path)
    # GOOD's 12th line holds the second member's spec
    assert str(caught.value) == (
        f"{path}:12: members[1].spec: expected a human spec like 'preference:handover=0.8', got ''"
    )


def test_an_algorithms_row_counts_the_seeds_it_has_cells_for() -> None:
    # Three seeds configured, but ppo has cells for two of them only (seed 2 never ran or was lost):
    # its row's mean and interval come from those two, so it reports 2 seeds, not the configured 3.
    config = CompareConfig(algos=("ppo",), humans=("lazy",), seeds=3, eval_seeds=(100, 101, 102))
    cells = [_cell("ppo", "lazy", s, [(0, 0.0), (1000, 50.0)]) for s in (0, 1)]
    rows = summarise(config, cells, {"lazy": {"oracle": 100.0, "planner": None, "hybrid": None}})
    by_agent = {r["agent"]: r for r in rows}
    assert by_agent["ppo"]["seeds"] == 2
    # the references ran on the three evaluation seeds
    assert by_agent["planner"]["seeds"] == 3
