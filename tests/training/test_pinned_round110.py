"""Values that round 110's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.humans.trace import read_trace
from hg_marl.agents.planner.plan import Step, _label_methods
from hg_marl.core import Agent, World
from hg_marl.core.spec import convert
from tests.agents.test_pinned_trace_gate import header, step, write

PAPER = World("paper2015")


def _step(agent: Agent, name: str, cycle: int) -> Step:
    index = PAPER.action_names[agent].index(name)
    return Step(agent, index, name, cycle, float(cycle), cycle + 1.0, PAPER.actions(agent)[index].obj, "")


def test_an_object_both_touch_with_no_give_or_human_place_is_robot_alone() -> None:
    # The rule (plan._label_methods): a human give -> handover_h2r, a robot give -> handover_r2h,
    # a human place -> human_places, only human steps -> human_alone, otherwise robot_alone. tape2:
    # the robot picks and throws it, the human's pick of it in cycle 0 (failed: the robot had it
    # first, as a replayed plan can hold) is a human step too, but not the only kind: robot_alone.
    robot = [_step(Agent.ROBOT, "pick(tape2)", 0), _step(Agent.ROBOT, "throw(tape2)", 1)]
    human = [_step(Agent.HUMAN, "pick(tape2)", 0)]
    out = _label_methods(PAPER, (robot, human))
    assert [s.method for s in out[0]] == ["robot_alone", "robot_alone"]
    assert [s.method for s in out[1]] == ["robot_alone"]


def test_a_population_file_without_a_scenario_names_none_not_its_file(tmp_path: Path) -> None:
    # No ``scenario`` field: the population says nothing about where its members were measured
    # (''), which `hg-marl population show` prints as "(unknown scenario)"; the file's stem is
    # the default of its name only.
    path = tmp_path / "mixed.toml"
    path.write_text('[[members]]\nname = "m1"\nsplit = "train"\nspec = "lazy"\n', encoding="utf-8")
    pop = load_population(path)
    assert (pop.name, pop.scenario) == ("mixed", "")


def test_a_list_parameter_drops_the_empty_items_of_its_bar_separated_text() -> None:
    # A spec's ``a|b`` is a list of strings; empty pieces name nothing: "a||b" and "a|b|" are
    # the two items a and b, "a|" the one item a.
    assert convert("a||b", [], "p", from_text=True) == ["a", "b"]
    assert convert("a|b|", [], "p", from_text=True) == ["a", "b"]
    assert convert("a|", (), "p", from_text=True) == ["a"]


def test_an_end_line_may_total_negative_rewards(tmp_path: Path) -> None:
    # A human seat with an effort weight is rewarded minus the weight times its seconds of work,
    # so an episode's total can be below 0; the end line's rewards need only be a finite number.
    end = {"type": "end", "clock": 0.0, "tasks_solved": 0, "rewards": -1.5}
    (episode,) = read_trace(write(tmp_path, header(), step(), end))
    assert episode.end["rewards"] == -1.5
