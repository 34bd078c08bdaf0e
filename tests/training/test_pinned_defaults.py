"""Documented defaults that results depend on, pinned to their stated values.

``hg-marl run`` takes its ``--duration`` default from :class:`RunConfig` (20 simulated
minutes), and every planner search stops at ``node_budget`` expanded nodes: a changed
default changes every run made without the option, so it must be a decision, not an edit.
"""

from __future__ import annotations

from hg_marl.agents.planner.costs import PlannerConfig
from hg_marl.training.runner import RunConfig
from tests.cli_helpers import run_main


def test_run_config_defaults() -> None:
    c = RunConfig()
    assert (c.scenario, c.duration, c.seed, c.charge_decision_time, c.max_decisions) == (
        "paper2015",
        20 * 60.0,
        0,
        True,
        None,
    )


def test_the_run_command_shows_the_same_default() -> None:
    code, out, _ = run_main(["run", "--help"])
    assert code == 0 and "1200" in out


def test_planner_node_budget_default() -> None:
    assert PlannerConfig().node_budget == 200_000
