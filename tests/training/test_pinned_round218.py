"""Values that round 218's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.progress import PROGRESS_AFTER
from hg_marl.agents.robots import PlannerRobot
from hg_marl.core import Agent, World
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario import load_scenario
from hg_marl.core.spec import parse_spec
from hg_marl.policy import Decision
from hg_marl.training.adaptation import AdaptationConfig, adaptation_jobs
from tests.training.test_pinned_round92 import _turn
from tests.training.test_pinned_round209 import writing_is_an_output_error_naming_it

WORLD = World("paper2015")


def test_a_file_name_too_long_to_write_is_an_output_error_naming_it(tmp_path: Path) -> None:
    # A name of 300 characters is over every common file system's limit of 255 bytes: the
    # open fails with ENAMETOOLONG, a path that names the wrong thing, which the user fixes
    # (errors.WRITE_ERRNOS): one OutputError line naming the path, not a traceback.
    writing_is_an_output_error_naming_it(tmp_path / ("x" * 300), OSError)


def test_a_partner_aware_planner_robots_guard_move_names_its_partner() -> None:
    # The state stands still at the robot's turn, so after PROGRESS_AFTER planner decisions
    # the progress guard moves (round 92's setup). A partner-aware robot names its current
    # belief in every record: the posterior's most probable type, a non-empty type name,
    # the same one its planner decisions named just before (no human move came in between).
    robot = PlannerRobot(partner_aware=True)
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    state = WORLD.initial_state(np.random.default_rng(0))
    named = []
    for _ in range(PROGRESS_AFTER):
        robot.act(_turn(state))
        assert isinstance(robot.last_decision, Decision)
        named.append(robot.last_decision.partner)
    robot.act(_turn(state))
    record = robot.last_decision
    assert isinstance(record, Decision)
    assert record.expert == "guard"
    expected = robot.partnering.posterior.most_probable()
    assert expected != ""
    assert record.partner == expected == named[-1]


def test_an_unknown_scenarios_message_lists_every_accepted_name() -> None:
    # The names load_scenario accepts besides a path: the four built-in scenarios and
    # "generated" (the scenario module's docstring), all of them in the refusal's message.
    with pytest.raises(ScenarioError) as raised:
        load_scenario("no_such_scenario")
    assert str(raised.value) == (
        "unknown scenario 'no_such_scenario': expected one of paper2015, roboergosum, forced_coordination, "
        "asymmetric_advantages, generated or the path of an existing .toml file"
    )


def test_a_comma_inside_parentheses_does_not_split_a_spec() -> None:
    # The splitter nests on brackets, braces and parentheses alike ("[{(" open, "]})" close):
    # "k=(1,2)" is one parameter, and ")" closes the "(" before it, so nothing is refused.
    assert dict(parse_spec("x:k=(1,2),j=3").raw) == {"k": "(1,2)", "j": "3"}
    assert dict(parse_spec("x:k=f(a,[b,c]),j={d:(e,f)}").raw) == {"k": "f(a,[b,c])", "j": "{d:(e,f)}"}


def test_the_partner_aware_planner_of_the_adaptation_sweep_is_partner_aware() -> None:
    # The robot labelled planner_partner_aware is the planner with partner_aware=True (its
    # label says so); its jobs carry that parameter to the worker that builds it.
    config = AdaptationConfig(seeds=2, robots=("planner", "planner_partner_aware"), switches=("lazy",))
    jobs = {(job.label, job.seed): job for job in adaptation_jobs(config)}
    for seed in (0, 1):
        aware = jobs[("adapt_lazy_planner_partner_aware", seed)]
        assert (aware.robot, dict(aware.robot_params)) == ("planner", {"partner_aware": True})
        plain = jobs[("adapt_lazy_planner", seed)]
        assert (plain.robot, dict(plain.robot_params)) == ("planner", {})
