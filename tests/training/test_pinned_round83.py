"""The values round 83's missed planted bugs changed, pinned after the round.

Round 83 planted 16 bugs in sixteen gated modules, written blind; 9 were caught. Each
value below is stated from the rule the module documents (or a simpler reference written
here, or a property), not read from the code under test:

- the hybrid robot's decision time is the habit's cost plus, when consulted, the
  planner's: a progress-guard or partner-stalled move consulted only the habit (1 ms);
- a planner robot whose search failed records the planner's failure;
- a population's ``behaviour`` and ``spread`` values are finite numbers, and TOML's ``true``
  is not a number;
- under the ``wall`` cost model a planner call is charged its measured wall time;
- a scenario file that is not valid TOML is named ``path:line`` once, the parser's
  ``(at line L, column C)`` taken out of the message;
- a spec's canonical text does not depend on the order in which a JSON object value's
  keys were written;
- ``convert --scenario`` overrides the scenario the old metadata beside the zip names.
"""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.planner import PlannerConfig
from hg_marl.agents.progress import PROGRESS_AFTER
from hg_marl.agents.robots import HybridRobot, PlannerRobot
from hg_marl.agents.robots.base import Robot, plan_proposal
from hg_marl.core import WAIT, Agent, State, World
from hg_marl.core.errors import PopulationError, ScenarioError
from hg_marl.core.scenario import load_scenario
from hg_marl.core.spec import AgentSpec, format_spec
from hg_marl.policy import Decision, Turn
from hg_marl.training.baselines import convert

WORLD = World("paper2015")
ROBOT_WAIT = WORLD.index(Agent.ROBOT, WAIT)
HUMAN_WAIT = WORLD.index(Agent.HUMAN, WAIT)
HABIT_COST = 1e-3
"""The default cost model's seconds per habit decision (``CostModel.habit``'s documented 1 ms)."""


def _turn(state: State, last: tuple[int, int] = (-1, -1)) -> Turn:
    obs = {"observation": WORLD.facts(state), "action_mask": WORLD.mask(state, Agent.ROBOT)}
    return Turn(WORLD, state, Agent.ROBOT, obs, reward=0.0, last_actions=last)


def _record(robot: Robot) -> Decision:
    assert robot.last_decision is not None
    return robot.last_decision


def test_a_hybrid_progress_guard_move_is_charged_the_habits_cost() -> None:
    # The state stands still: after PROGRESS_AFTER habit decisions the guard moves. The habit
    # was asked (it is always), the planner was not: the decision costs the habit's 1 ms.
    robot = HybridRobot(criterion="habit")
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    state = WORLD.initial_state(np.random.default_rng(0))
    for _ in range(PROGRESS_AFTER):
        robot.act(_turn(state))
        assert _record(robot).decision_time == pytest.approx(HABIT_COST)
    robot.act(_turn(state))
    record = _record(robot)
    assert (record.expert, record.reason) == ("guard", "no_progress")
    assert not record.planner_consulted
    assert record.decision_time == pytest.approx(HABIT_COST)


def test_a_hybrid_move_for_a_stalled_partner_is_charged_the_habits_cost() -> None:
    # paper2015: tape1 on the human's mat (spot 4), the others in the bin (6), the robot at the
    # human's side (location 3): the plan needs the human, who only waits, so the robot soon
    # takes the habit's best feasible move instead; only the habit was asked for it.
    stalled = State((4, 6, 6), 3)
    robot = HybridRobot(criterion="planner")
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    robot.act(_turn(stalled))
    for _ in range(8):
        robot.act(_turn(stalled, last=(ROBOT_WAIT, HUMAN_WAIT)))
        if _record(robot).reason == "partner_stalled":
            break
    record = _record(robot)
    assert (record.expert, record.reason) == ("habit", "partner_stalled")
    assert not record.planner_consulted
    assert record.decision_time == pytest.approx(HABIT_COST)


def test_a_planner_robot_whose_search_failed_records_no_success() -> None:
    # A node budget of 1 cannot prove a plan from the start of paper2015 (a budget failure):
    # the record says the planner was consulted and did not succeed.
    robot = PlannerRobot(planner_config=PlannerConfig(node_budget=1))
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    robot.act(_turn(WORLD.initial_state(np.random.default_rng(0))))
    record = _record(robot)
    assert record.planner_consulted
    assert record.reason.startswith("budget")
    assert record.planner_success is False
    assert record.expected_human_action == -1  # a failed plan expects nothing of the human


_POPULATION = """\
name = "p"
scenario = "paper2015"

[spread.train]
selected = {selected}
random = 1.0

[[members]]
name = "m0"
split = "train"
spec = "preference"
behaviour = {{ give = {give} }}
"""


@pytest.mark.parametrize(("selected", "give", "field"), [("true", "0.5", "spread.train"), ("2.0", "true", "behaviour")])
def test_a_population_value_of_true_is_not_a_number(tmp_path: Path, selected: str, give: str, field: str) -> None:
    # The docstring: spread values and measured behaviour features are numbers; TOML's true is
    # a boolean, refused like a text. The control: the same file with numbers loads.
    path = tmp_path / "p.toml"
    path.write_text(_POPULATION.format(selected="2.0", give="0.5"), encoding="utf-8")
    population = load_population(path)
    assert population.spread == {"train": {"selected": 2.0, "random": 1.0}}
    assert population.members()[0].behaviour == {"give": 0.5}
    path.write_text(_POPULATION.format(selected=selected, give=give), encoding="utf-8")
    with pytest.raises(PopulationError, match=field):
        load_population(path)


def test_a_planner_call_under_the_wall_cost_model_is_charged_its_wall_time() -> None:
    # CostModel(mode="wall") charges the measured wall time: a result of 0.25 s (any nodes)
    # costs 0.25 s, success or not; the "model" mode charges 50 ms + 0.5 ms per node instead.
    for success in (True, False):
        result = SimpleNamespace(
            success=success,
            robot_action=ROBOT_WAIT,
            human_action=HUMAN_WAIT,
            nodes=10,
            wall_time=0.25,
            action_distribution=lambda n, agent: np.full(n, 1.0 / n),
        )
        n = WORLD.n_actions(Agent.ROBOT)
        assert plan_proposal(result, n, Agent.ROBOT, CostModel(mode="wall")).cost == pytest.approx(0.25)
        assert plan_proposal(result, n, Agent.ROBOT, CostModel()).cost == pytest.approx(0.05 + 0.0005 * 10)


def test_a_scenario_file_that_is_not_toml_names_its_line_once(tmp_path: Path) -> None:
    # The docstring: a malformed file is refused naming path:line; the line is said once, in
    # that form, not again as the parser's "(at line 2, column ...)" at the end of the message.
    path = tmp_path / "bad.toml"
    path.write_text('name = "bad"\nobjects = = 2\n', encoding="utf-8")  # line 2: a value is missing
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    message = str(info.value)
    assert message.startswith(f"scenario file {path}:2: not valid TOML: ")
    assert "not valid TOML" in message
    assert "at line" not in message and "column" not in message


def test_a_specs_canonical_text_does_not_depend_on_its_objects_key_order() -> None:
    # Canonical text: the same parameters give the same text, whatever order they were written
    # in, inside a JSON object value too (a study's content key must not change with it).
    a = format_spec("hybrid", {"q_config": {"features": "facts", "alpha": 0.1}, "criterion": "vpi"})
    b = format_spec("hybrid", {"criterion": "vpi", "q_config": {"alpha": 0.1, "features": "facts"}})
    assert a == b
    assert a == 'hybrid:criterion=vpi,q_config={"alpha":0.1,"features":"facts"}'
    one = AgentSpec.parse('hybrid:q_config={"features": "facts", "alpha": 0.1}')
    two = AgentSpec.parse('hybrid:q_config={"alpha": 0.1, "features": "facts"}')
    assert str(one) == str(two)


def test_convert_scenario_option_overrides_the_old_metadatas_scenario(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The docstring: the options "override or supply" what the old metadata says. The old
    # model.json names paper2015; --scenario roboergosum converts for roboergosum's world.
    saved: list[dict[str, Any]] = []

    class Loader:
        @staticmethod
        def load(path: Path, device: str) -> str:
            return "model"

    def fake_save(model: Any, target: Path, fields: dict[str, Any], observation: str) -> Path:
        saved.append(fields)
        return target

    monkeypatch.setattr(convert, "algo_class", lambda name: Loader)
    monkeypatch.setattr(convert, "save_sb3", fake_save)
    zip_path = tmp_path / "model.zip"
    zip_path.write_bytes(b"PK stand-in")
    old = {"format": "hg_marl.sb3", "algo": "PPO", "seat": "robot", "scenario": "paper2015"}
    (tmp_path / "model.json").write_text(json.dumps(old), encoding="utf-8")
    convert.convert_zip(zip_path, trust=True, scenario="roboergosum", out=tmp_path / "new.json")
    convert.convert_zip(zip_path, trust=True, out=tmp_path / "old.json")  # no option: the metadata's
    other = World("roboergosum")
    assert [f["scenario"] for f in saved] == ["roboergosum", "paper2015"]
    assert saved[0]["fact_names"] == list(other.fact_names)
    assert saved[0]["action_names"] == list(other.action_names[Agent.ROBOT])
