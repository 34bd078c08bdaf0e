"""Round 47 of the fresh planted bugs: the values its missed bugs changed, pinned.

The expected values are stated independently of the code under test: a scenario file
that is not UTF-8 is refused naming the offset of its first bad byte, counted by hand in
the bytes the test writes; a planning robot whose partner stalls "takes any feasible move
for one decision" (agents/robots/planner.py), so the decision after it is the planner's
again; a bin with no colour "accepts objects of any colour" (``Bin.colour``), so a
coloured tape goes into paper2015's one colourless bin; a turn's ``events`` are "its own
last action's events, then its partner's" (``raw_env.turn``), here a robot's move and a
human's pick worked out by hand from paper2015.toml; and a dict ``q_config`` gives "the
fields that differ from ``default_habit``" (``LearningRobot``), the hybrid's being a
tabular habit.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.core import Agent, Event, Kind, State, World
from hg_marl.core.scenarios import __file__ as scenarios_init
from tests.agents.test_pinned_hybrid_robot_gate import HUMAN_WAIT, STALLED, WORLD, _record, _turn, stall_partner

PAPER = Path(scenarios_init).with_name("paper2015.toml").read_text()

# --- hg_marl/core/scenario.py ---


@pytest.mark.parametrize(
    ("data", "offset"),
    [
        (b'name = "x"\n\xff\n', 11),  # 'name = "x"\n' is 11 bytes: the 0xff is byte 11 (from 0)
        (b"\xfe", 0),
        (b"# caf\xc3\xa9 ok\n# \xe9t\xe9\n", 13),  # 5 + 2 (a valid e-acute) + 4 + 2 bytes before
    ],
)
def test_a_scenario_file_that_is_not_utf8_names_its_first_bad_byte(tmp_path: Path, data: bytes, offset: int) -> None:
    from hg_marl.core.scenario import ScenarioError, load_scenario

    path = tmp_path / "latin1.toml"
    path.write_bytes(data)
    with pytest.raises(ScenarioError, match=rf"not UTF-8 text \(byte {offset}\)"):
        load_scenario(str(path))


# --- agents/robots/planner.py ---


def test_a_planner_robot_plans_again_after_its_one_move_for_a_stalled_partner() -> None:
    """The move for a stalled partner is for one decision: at the next turn (the human
    waited again, in the state that move led to) the planner decides, not another draw,
    and the monitor counts one fallback."""
    from hg_marl.agents.robots.planner import PlannerRobot

    robot = PlannerRobot()
    move, reasons = stall_partner(robot)
    assert reasons[-1] == "partner_stalled" and _record(robot).expert == "random"
    assert robot.partnering.monitor.fallbacks == 1
    after = WORLD.step(WORLD.step(STALLED, Agent.ROBOT, move).state, Agent.HUMAN, HUMAN_WAIT).state
    robot.act(_turn(after, last=(move, HUMAN_WAIT)))
    record = _record(robot)
    assert record.expert == "planner" and record.planner_consulted
    assert record.reason != "partner_stalled"


# --- hg_marl/core/table.py ---


def test_a_bin_with_no_colour_accepts_an_object_of_any_colour(tmp_path: Path) -> None:
    """paper2015 with tape1 coloured red: its one bin (trashbin) has no colour, so accepts it."""
    from hg_marl.core.scenario import load_scenario
    from hg_marl.core.table import accepting_bins

    text = PAPER.replace('name = "paper2015"', 'name = "red_tape"')
    text = text.replace('name = "tape1"\n', 'name = "tape1"\ncolour = "red"\n', 1)
    assert text.count('colour = "red"') == 1
    path = tmp_path / "red_tape.toml"
    path.write_text(text)
    scenario = load_scenario(str(path))
    assert scenario.object_colours == ("red", "", "")
    assert accepting_bins(scenario) == ((0,), (0,), (0,))
    world = World(scenario)
    assert world.bins_of == ((0,), (0,), (0,))
    m = world.n_spots  # 6 spots: the trashbin is place 6, the robot's hand 7
    robot_at_bin = State((m + 1, m, m), 0)  # the robot holds the red tape at bin_side
    throw = world.table.action_index(Agent.ROBOT, Kind.THROW, 0)
    out = world.step(robot_at_bin, Agent.ROBOT, throw)
    assert out.ok and out.state.where == (m, m, m)
    clean = State((m, m, m), 0)
    assert world.is_clean(clean)
    assert world.step(clean, Agent.ROBOT, world.n_actions(Agent.ROBOT) - 1).reward == 1.0


# --- hg_marl/envs/table_cleaning.py ---


def test_a_turns_events_are_its_own_last_actions_then_its_partners() -> None:
    """paper2015: tape1 on mat_left (spot 0), tape2 on human_mat_1 (spot 4), tape3 in the
    trashbin (6), the robot at bin_side. The robot goes to tape1 (to table_left, the first
    location reaching mat_left), the human picks tape2; the robot's next turn tells its own
    move first, then the human's pick; the human's turn (same two actions) likewise its own first."""
    import hg_marl

    env = hg_marl.env(scenario="paper2015").unwrapped
    env.reset(seed=0, options={"state": State((0, 4, 6), 0)})
    table = env.world.table
    env.step(table.action_index(Agent.ROBOT, Kind.GOTO, target=0))
    env.step(table.action_index(Agent.HUMAN, Kind.PICK, 1))
    moved = Event("moved", "robot", "", "table_left")
    picked = Event("picked", "human", "tape2", "human_mat_1")
    assert env.turn("robot").events == (moved, picked)
    assert env.turn("human").events == (picked, moved)


# --- agents/robots/base.py ---


def test_a_dict_q_config_changes_only_its_fields_of_the_robots_default_habit() -> None:
    """The hybrid's default habit is tabular (``HybridRobot.default_habit``); a dict that
    sets the learning rate alone keeps it tabular, with QLearnerConfig's other defaults."""
    from hg_marl.agents.habit import QLearnerConfig
    from hg_marl.agents.robots import HybridRobot

    robot = HybridRobot(q_config={"alpha": 0.2})
    assert robot.q_config == QLearnerConfig(alpha=0.2, features="tabular")
    robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
    assert robot.habit.config.features == "tabular"
    assert HybridRobot(q_config={"features": "facts"}).q_config == QLearnerConfig(features="facts")
