"""Plan views (Gantt text and PNG), plan structure (streams, links) and the ``plan`` command."""

from __future__ import annotations

import numpy as np
import typer
from typer.testing import CliRunner

from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.gantt import gantt_png, gantt_text, step_code
from hg_marl.core import Agent, Kind, World
from hg_marl.training.commands.plan import register


def test_streams_times_and_links() -> None:
    world = World("roboergosum")
    result = Planner(world).plan(world.initial_state(np.random.default_rng(1)))
    plan = result.plan
    assert plan is not None
    robot, human = plan.streams
    assert len(robot) == len(human) == len(plan.cycles)
    assert robot[-1].end <= plan.duration and robot[0].start == 0.0
    for k, (r, h) in enumerate(zip(robot, human, strict=True)):
        assert r.cycle == h.cycle == k and r.start == h.start
        assert r.end - r.start == world.step(plan.states[k], Agent.ROBOT, r.action).duration
    kinds = {link.kind for link in plan.links}
    assert "handover" in kinds
    for link in plan.links:
        src = plan.streams[link.source[0]][link.source[1]]
        dst = plan.streams[link.target[0]][link.target[1]]
        assert (src.start <= dst.start and src.obj == dst.obj) or link.kind == "waits_for"
        if link.kind == "handover":
            assert world.actions(src.agent)[src.action].kind is Kind.GIVE
            assert world.actions(dst.agent)[dst.action].kind is Kind.TAKE


def test_a_plan_from_the_humans_turn_times_its_streams_from_the_robot_action_under_way() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(2))
    first = Planner(world).plan(state).plan
    assert first is not None
    robot_action = first.cycles[0][0]
    step = world.step(state, Agent.ROBOT, robot_action)
    plan = Planner(world).plan(step.state, Agent.HUMAN, robot_action=robot_action).plan
    assert plan is not None
    robot, human = plan.streams
    assert len(human) == len(plan.cycles) and len(robot) == len(plan.cycles) - 1  # no robot step in cycle 0
    d_human = world.step(step.state, Agent.HUMAN, human[0].action).duration
    assert (human[0].start, human[0].end) == (0.0, d_human)
    assert robot[0].cycle == human[1].cycle == 1
    assert robot[0].start == human[1].start == max(step.duration, d_human)  # the first cycle lasts its longer action


def test_waits_for_link_when_the_robot_waits_for_the_human() -> None:
    world = World("generated:objects=1,seed=0,human_only=1.0")
    result = Planner(world).plan(world.initial_state(np.random.default_rng(0)))
    plan = result.plan
    assert plan is not None
    waits = [link for link in plan.links if link.kind == "waits_for"]
    assert waits, gantt_text(world, plan)
    assert all(link.target[0] is Agent.ROBOT for link in waits)


def test_gantt_text_and_png(tmp_path) -> None:  # type: ignore[no-untyped-def]
    world = World("paper2015")
    plan = Planner(world).plan(world.initial_state(np.random.default_rng(0))).plan
    assert plan is not None
    text = gantt_text(world, plan)
    assert "robot  |" in text and "human  " in text and "completes at" in text
    assert "link handover" in text
    out = gantt_png(world, plan, tmp_path / "plan.png")
    assert out.stat().st_size > 1000


def test_gantt_text_legend_spells_out_every_code() -> None:
    world = World("paper2015")
    plan = Planner(world).plan(world.initial_state(np.random.default_rng(0))).plan
    assert plan is not None
    text = gantt_text(world, plan)
    legend = dict(pair.split("=") for line in text.splitlines() if "=" in line for pair in line.split() if "=" in pair)
    # seed 0 (hand-checked): the robot bins tape1 and tape3 alone, the human hands tape2 over
    assert legend["Pt1"] == "pick(tape1)" and legend["Vt2"] == "give(tape2)" and legend["Kt2"] == "take(tape2)"
    assert legend["GB"] == "goto(trashbin)" and legend["GH"] == "goto(human)"
    rows = [line for line in text.splitlines() if line.startswith(("robot ", "human "))]
    drawn = {code.rstrip("-. ") for row in rows for code in row[7:].split("|")[1:]}
    assert drawn == set(legend), "every drawn step's code is complete and explained"


def test_gantt_png_labels_are_horizontal_and_fit_their_bars() -> None:
    from hg_marl.agents.planner.gantt import gantt_figure

    world = World("roboergosum")
    plan = Planner(world).plan(world.initial_state(np.random.default_rng(3))).plan
    assert plan is not None
    fig = gantt_figure(world, plan)
    renderer = fig.canvas.get_renderer()
    ax = fig.axes[0]
    bars = [p.get_window_extent(renderer) for p in ax.patches]
    labels = [t for t in ax.texts if t.get_text()]
    named = [t for t in labels if t.get_text() != "wait"]
    assert len(named) == sum(1 for stream in plan.streams for s in stream if s.name != "wait")
    for label in labels:
        assert label.get_rotation() == 0
        box = label.get_window_extent(renderer)
        assert any(b.x0 <= box.x0 and box.x1 <= b.x1 and b.y0 <= box.y0 and box.y1 <= b.y1 for b in bars), (
            label.get_text()
        )


def test_gantt_png_has_a_legend_of_every_colour_and_arrow_off_the_bars() -> None:
    from hg_marl.agents.planner.gantt import gantt_figure
    from tests.figure_checks import legend_inside_data, legend_labels, overlapping_texts

    world = World("paper2015")
    plan = Planner(world).plan(world.initial_state(np.random.default_rng(0))).plan
    assert plan is not None
    fig = gantt_figure(world, plan)
    drawn = {world.actions(a)[s.action].kind.name.lower() for a in Agent for s in plan.streams[a]}
    # seed 0 (see the text legend test): picks, throws, a handover (give/take), gotos and waits
    assert {"pick", "throw", "give", "take", "goto", "wait"} <= drawn
    assert set(legend_labels(fig)) == drawn | {f"{link.kind} link" for link in plan.links}
    assert legend_inside_data(fig) == [] and overlapping_texts(fig) == []
    waits = [p for p in fig.axes[0].patches if p.get_hatch() == "/"]
    assert len(waits) == sum(1 for a in Agent for s in plan.streams[a] if s.name == "wait")


def test_plan_command(tmp_path) -> None:  # type: ignore[no-untyped-def]
    app = typer.Typer()
    register(app)

    @app.callback()
    def main() -> None:
        """Test app."""

    runner = CliRunner()
    png = tmp_path / "p.png"
    result = runner.invoke(app, ["plan", "--scenario", "paper2015", "--seed", "2", "--png", str(png)])
    assert result.exit_code == 0, result.output
    assert "robot  |" in result.output and "human_effort" in result.output and "planning time" in result.output
    assert png.exists()
    result = runner.invoke(app, ["plan", "--scenario", "roboergosum", "--budget", "2"])
    assert result.exit_code == 1 and "budget" in result.output


def test_a_placement_is_coded_with_its_spots_number_counted_from_one() -> None:
    # the chart numbers spots 1, 2, ... (the docstring's "@2"): placing on the first spot is @1
    world = World("paper2015")
    places = [a for a in world.actions(Agent.HUMAN) if a.kind is Kind.PLACE and a.obj == 0]
    codes = {a.target: step_code(world, a) for a in places}
    assert codes and all(code.endswith(f"@{spot + 1}") for spot, code in codes.items()), codes
    assert 0 in codes and codes[0].endswith("@1")
