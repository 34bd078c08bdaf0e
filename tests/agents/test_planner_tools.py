"""Plan views (Gantt text and PNG), plan structure (streams, links) and the ``plan`` command."""

from __future__ import annotations

import numpy as np
import typer
from typer.testing import CliRunner

from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.gantt import gantt_png, gantt_text
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
    assert "robot |" in text and "human |" in text and "completes at" in text
    assert "link handover" in text
    out = gantt_png(world, plan, tmp_path / "plan.png")
    assert out.stat().st_size > 1000


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
    assert "robot |" in result.output and "human_effort" in result.output and "planning time" in result.output
    assert png.exists()
    result = runner.invoke(app, ["plan", "--scenario", "roboergosum", "--budget", "2"])
    assert result.exit_code == 1 and "budget" in result.output
