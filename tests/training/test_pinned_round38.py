"""Round 38 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated by hand, from the documented rule (the ``Decision`` record's
field docs, the planner robot's docstring on a stalled partner, the environment's refusal
of an action outside its space, the population loader's documented member limit) or read
off the run itself (the node budget given and the nodes the result reports), not computed
with the code under test.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.planner.plan import PlanResult, failure
from hg_marl.core import Agent, State
from tests.agents.test_pinned_hybrid_robot_gate import ROBOT_WAIT, STALLED, WORLD, _record, _turn, stall_partner


def test_a_bool_is_refused_as_an_action() -> None:
    """An action outside the action space raises ``InvalidActionError`` (the module docstring);
    ``True`` is not an action index (the refusal's "expected an integer"), so it is refused,
    not played as index 1; the integer 1 itself is accepted."""
    from hg_marl.envs.table_cleaning import InvalidActionError, raw_env

    env = raw_env()
    env.reset(seed=0)
    with pytest.raises(InvalidActionError):
        env.step(True)
    env.step(1)  # the same index as an int is legal input
    assert env.agent_selection == "human"


def test_a_hybrid_decision_whose_plan_failed_records_no_planner_action() -> None:
    """``Decision.planner_action``: "-1: the planner did not propose or failed". A planner
    stand-in that always fails (proposing the robot's wait) is consulted: the record says
    the planner was consulted, did not succeed, and names no planner action."""
    from hg_marl.agents.robots import HybridRobot

    class FailingPlanner:
        def plan(self, state: State, to_move: Agent = Agent.ROBOT, **_: Any) -> PlanResult:
            return failure("no plan: stand-in", 7, 0.0, ROBOT_WAIT)

    robot = HybridRobot(criterion="planner")
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    state = WORLD.initial_state(np.random.default_rng(0))
    robot.planner = robot.partnering.planner = FailingPlanner()
    robot.act(_turn(state))
    record = _record(robot)
    assert record.planner_consulted and not record.planner_success
    assert record.planner_action == -1


def test_a_planner_robots_move_for_a_stalled_partner_is_recorded_as_a_random_one() -> None:
    """agents/robots/planner.py: a robot whose partner keeps not doing what is expected
    "takes any feasible move for one decision" (not the progress guard's move, whose reason
    is ``no_progress``). Tape1 on the human's mat, the others in the bin: the plan needs the
    human, who only waits; the stalled decision is a feasible non-wait move by "random"."""
    from hg_marl.agents.robots.planner import PlannerRobot

    robot = PlannerRobot()
    move, reasons = stall_partner(robot)
    assert reasons[-1] == "partner_stalled" and "no_progress" not in reasons
    record = _record(robot)
    assert record.expert == "random"
    assert move == record.action and move != ROBOT_WAIT and WORLD.mask(STALLED, Agent.ROBOT)[move]


def test_a_budget_failure_names_the_budget_then_the_nodes_expanded() -> None:
    """A planner with a node budget of 3 cannot prove a plan from paper2015's start: its reason
    reads "budget: node budget of 3 exhausted (3 nodes) ...". A search stops as soon as its
    count reaches the budget, so through ``plan`` the two numbers are always equal; the
    message's template is read with a count that differs (7, as a search that overshoots
    would report), and must name the budget given (3) first and the nodes (7) second."""
    from hg_marl.agents.planner import Planner, PlannerConfig

    planner = Planner(WORLD, config=PlannerConfig(node_budget=3))
    state = WORLD.initial_state(np.random.default_rng(0))
    result = planner.plan(state)
    assert not result.success and result.nodes == 3
    assert result.reason == "budget: node budget of 3 exhausted (3 nodes) before the optimum was proven"
    assert planner._reason(state, "budget", 7) == (
        "budget: node budget of 3 exhausted (7 nodes) before the optimum was proven"
    )


MEMBER = '[[members]]\nname = "m{i:04d}"\nsplit = "train"\nspec = "preference"\n\n'


def test_a_population_of_exactly_the_member_limit_loads_and_one_more_is_refused(tmp_path: Path) -> None:
    """The loader's documented limit: at most 1000 members (``MAX_MEMBERS``). 1000 members
    load (all 1000 in the train split); 1001 are refused naming the limit and the count."""
    from hg_marl.agents.humans.population import MAX_MEMBERS, load_population
    from hg_marl.core.errors import PopulationError

    assert MAX_MEMBERS == 1000
    head = 'name = "big"\nscenario = "paper2015"\n\n'
    exact = tmp_path / "exact.toml"
    exact.write_text(head + "".join(MEMBER.format(i=i) for i in range(1000)))
    assert len(load_population(exact).train) == 1000
    over = tmp_path / "over.toml"
    over.write_text(head + "".join(MEMBER.format(i=i) for i in range(1001)))
    with pytest.raises(PopulationError, match=r"members: at most 1000 members, got 1001"):
        load_population(over)
