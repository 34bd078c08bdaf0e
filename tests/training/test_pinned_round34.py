"""Round 34 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated by hand or from the documented rule, not computed with the
code under test.
"""

from __future__ import annotations

import json
import sys
from io import StringIO
from pathlib import Path
from types import ModuleType, SimpleNamespace

import numpy as np
import pytest
from rich.console import Console
from typer.testing import CliRunner

from hg_marl.core import Agent, World
from hg_marl.core.errors import RobotError
from hg_marl.training.cli import app


def test_the_task_solved_line_gives_the_latest_tasks_time() -> None:
    """Two tasks solved, at 10.0 s and then at 25.5 s: the line says 2 so far, at t = 25.5 s."""
    from hg_marl.training.play.tui import screen

    world = World("paper2015")
    session = SimpleNamespace(
        world=world,
        state=world.initial_state(np.random.default_rng(0)),
        clock=25.5,
        cycle=7,
        tasks_solved=2,
        just_solved=1,
        solved_at=[10.0, 25.5],
        last_robot=None,
        last_human="",
        choices=lambda: [],
    )
    console = Console(file=StringIO(), width=200, color_system=None)
    console.print(screen(session))  # type: ignore[arg-type]
    assert "Task solved! 2 so far, at t = 25.5 s." in console.file.getvalue()  # type: ignore[attr-defined]


def test_play_command_opens_the_browser_unless_no_browser(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``--no-browser``: "Print the URL only"; without it the browser is opened."""
    for name in ("starlette", "uvicorn"):  # the play extra, faked: the server never starts here
        monkeypatch.setitem(sys.modules, name, ModuleType(name))
    opened: list[bool] = []

    class FakeServer:
        url = "http://127.0.0.1:1/?token=t"

        def __init__(self, session: object, port: int) -> None:
            pass

        def run(self, open_browser: bool = False) -> None:
            opened.append(open_browser)

    web = ModuleType("hg_marl.training.play.web")
    web.check_port = lambda port: None  # type: ignore[attr-defined]
    web.Server = FakeServer  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "hg_marl.training.play.web", web)

    class FakeSession:
        def __init__(self, *args: object, **kwargs: object) -> None:
            pass

        def close(self) -> None:
            pass

        def summary(self) -> dict[str, object]:
            return {"moves": 0, "tasks_solved": 0, "clock": 0.0, "trace": None}

    from hg_marl.training.play import session

    monkeypatch.setattr(session, "PlaySession", FakeSession)
    for extra, expected in (([], True), (["--no-browser"], False)):
        result = CliRunner().invoke(app, ["play", "--record", str(tmp_path / "games"), *extra])
        assert result.exit_code == 0, result.output
        assert opened.pop() is expected
        assert "0 moves, 0 tasks in 0.0 simulated s" in result.output


def test_robot_params_of_an_unknown_robot_is_a_robot_error_listing_the_robots() -> None:
    """Like ``make_robot``: an unknown name raises RobotError naming it and listing the robots."""
    from hg_marl.agents.robots import robot_params

    with pytest.raises(RobotError, match=r"unknown robot 'nope'; available: .*planner.*habit"):
        robot_params("nope")


def test_convert_command_passes_seat_and_observation_to_their_own_fields(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``--seat human --observation flat`` reach the converter as seat="human", observation="flat"."""
    from hg_marl.training.baselines import convert

    seen: dict[str, object] = {}
    header = tmp_path / "model.json"

    def fake_convert(path: Path, **kwargs: object) -> Path:
        seen.update(kwargs)
        return header

    monkeypatch.setattr(convert, "convert_zip", fake_convert)
    args = ["convert", str(tmp_path / "model.zip"), "--trust", "--seat", "human", "--observation", "flat"]
    result = CliRunner().invoke(app, [*args, "--algo", "PPO", "--scenario", "roboergosum"])
    assert result.exit_code == 0, result.output
    assert seen == {
        "trust": True,
        "out": None,
        "algo": "PPO",
        "scenario": "roboergosum",
        "seat": "human",
        "observation": "flat",
    }
    assert f"wrote {header} and {tmp_path / 'model.npz'}" in result.output


def test_the_habit_robots_decision_logs_its_weight_amplitude() -> None:
    """Weights 1.5 and -2 (the rest 0) give ``sum |w|`` = 3.5 in the first decision's record."""
    from hg_marl.agents.robots import make_robot

    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    robot = make_robot("habit")
    robot.reset(world, Agent.ROBOT, np.random.default_rng(1))
    robot.habit.weights[0, 0] = 1.5  # type: ignore[attr-defined]
    robot.habit.weights[1, 0] = -2.0  # type: ignore[attr-defined]
    observation = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
    from hg_marl.policy import Turn

    robot.act(Turn(world, state, Agent.ROBOT, observation))  # the first act: no TD step yet, weights unchanged
    decision = robot.last_decision
    assert decision is not None
    assert decision.expert == "habit"
    assert decision.weight_amplitude == pytest.approx(3.5)


def test_each_episode_of_a_trace_numbers_its_steps_from_zero(tmp_path: Path) -> None:
    """The format: a header, then the episode's turns as steps 0, 1, ...; a second episode starts at 0 again."""
    from hg_marl.agents.humans.trace import TraceWriter

    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    wait = world.n_actions(Agent.HUMAN) - 1
    turn = SimpleNamespace(
        world=world,
        agent=Agent.HUMAN,
        clock=0.0,
        tasks_solved=0,
        observation={"observation": world.facts(state)},
        mask=world.mask(state, Agent.HUMAN),
    )
    path = tmp_path / "two.jsonl"
    with TraceWriter(path) as writer:
        for steps in (2, 1):
            writer.header(world, Agent.HUMAN, seed=0)
            for _ in range(steps):
                writer.step(turn, wait)  # type: ignore[arg-type]
    lines = [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()]
    assert [(r["type"], r.get("episode"), r.get("step")) for r in lines] == [
        ("header", 0, None),
        ("step", None, 0),
        ("step", None, 1),
        ("header", 1, None),
        ("step", None, 0),
    ]


def test_the_flat_wrappers_info_masks_follow_each_step() -> None:
    """``mask="info"``: ``infos[agent]["action_mask"]`` is the agent's current mask, after a step too."""
    import hg_marl
    from hg_marl.wrappers import flatten_v0

    env = flatten_v0(hg_marl.env(), mask="info")
    env.reset(seed=0)
    inner = env.unwrapped
    first = {a: env.infos[a]["action_mask"].copy() for a in env.agents}
    changed = False
    for _ in range(6):  # a few moves, each the first feasible non-wait action
        agent = env.agent_selection
        mask = env.infos[agent]["action_mask"]
        env.step(int(np.flatnonzero(mask[:-1])[0]) if mask[:-1].any() else len(mask) - 1)
        for a in env.agents:
            now = np.asarray(inner.observe(a)["action_mask"], dtype=np.int8)  # the env's own mask
            assert env.infos[a]["action_mask"].dtype == np.int8
            np.testing.assert_array_equal(env.infos[a]["action_mask"], now)
            changed |= not np.array_equal(now, first[a])
    assert changed  # the moves did change a mask, so a stale one would show
