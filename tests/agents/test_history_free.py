"""A run is a pure function of its key; a stationary human answers from the state alone.

Whatever ran before in the process (other runs, an oracle build, another instance's
planner sharing the world's search space), a human's answer at (state, robot action) and
a run's log are what a fresh process gives. The oracle robot, playing the human it was
solved against, never meets a state outside its model.
"""

from __future__ import annotations

import hashlib
import json
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.base import robot_action_of
from hg_marl.agents.humans.registry import HUMANS
from hg_marl.agents.oracle import OracleRobot, layout_distribution, oracle_rate
from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.planner import Intent
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn
from hg_marl.training.runner import RunConfig, run

STATIONARY = tuple(
    n for n, s in HUMANS.items() if s.stationary and not any(p.default is None for p in s.params.values())
)
"""Every stationary registry human that needs no file (``learned`` needs a saved policy)."""
RUNS = (("planner", "cooperative"), ("hybrid", "noisy"), ("oracle", "cooperative"), ("planner", "lazy"))


def digest(robot: str, human: str, scenario: str, seed: int, duration: float) -> str:
    """A run's summary and log (wall-clock columns left out) hashed."""
    actor: Any = OracleRobot(human=human) if robot == "oracle" else make_robot(robot)
    result = run(actor, make_human(human), RunConfig(scenario=scenario, duration=duration, seed=seed))
    log = result.log.drop(columns=["planning_time"])
    text = json.dumps(result.summary, sort_keys=True) + log.to_csv(index=False)
    return hashlib.sha256(text.encode()).hexdigest()


def fresh_digest(robot: str, human: str, scenario: str, seed: int, duration: float) -> str:
    """:func:`digest` in a new interpreter (nothing cached)."""
    code = (
        "import sys; from tests.agents.test_history_free import digest; "
        f"print(digest({robot!r}, {human!r}, {scenario!r}, {seed}, {duration}))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=600)
    return out.stdout.strip().splitlines()[-1]


@pytest.mark.parametrize(
    ("scenario", "duration"), [("paper2015", 300.0), pytest.param("roboergosum", 600.0, marks=pytest.mark.slow)]
)
def test_runs_give_the_same_results_in_any_order_and_in_a_fresh_process(
    scenario: str, duration: float, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The oracle robot's model goes to a disk cache (the fresh processes inherit it): built by
    # the first run, read by the two after it, so a run with a model read back must also equal
    # a run with the model just built (and roboergosum's model is built once, not three times).
    monkeypatch.setenv("HG_MARL_CACHE", str(tmp_path))
    forward = [digest(r, h, scenario, 0, duration) for r, h in RUNS]
    assert len(list((tmp_path / "oracle").iterdir())) == 1
    backward = [digest(r, h, scenario, 0, duration) for r, h in reversed(RUNS)][::-1]
    assert forward == backward
    assert forward == [fresh_digest(r, h, scenario, 0, duration) for r, h in RUNS]


def test_the_bound_is_exactly_equal_for_all_states_of_a_canonical_key() -> None:
    # roboergosum: 3 blue and 3 green objects, placemats in 4 reach classes; 5,040 layouts
    # fall into a few dozen keys, and the planner caches one bound per key.
    space = Planner(World("roboergosum")).space
    seen: dict[object, tuple[float, ...] | None] = {}
    for state, _ in layout_distribution(space.world):
        for at in range(len(space.world.scenario.robot_locations)):
            s = state._replace(robot_at=at)
            key = space.key(s)
            assert seen.setdefault(key, space.sums(s)) == space.sums(s), s
    assert len(seen) < 5040 // 10  # the symmetry is real: many states per key


class Spy:
    """The live human, recording its answer at every turn: (state, robot action seen, distribution)."""

    def __init__(self, human: Any) -> None:
        self.human, self.seen = human, []  # type: ignore[var-annotated]
        self.name = human.name

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.human.reset(world, agent, rng)

    def act(self, turn: Turn) -> int:
        ra = robot_action_of(turn) if self.human.uses_robot_action else -1
        self.seen.append((turn.state, ra, self.human.distribution(turn.world, turn.state, ra)))
        return int(self.human.act(turn))


def fresh_answer(name: str, scenario: str, state: State, ra: int) -> list[tuple[int, float]]:
    world = World(scenario)  # a new world: a new search space, nothing cached
    human: Any = make_human(name)
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    return list(human.distribution(world, state, ra))


@pytest.mark.parametrize(
    ("scenario", "duration", "sampled"),
    [("paper2015", 1500.0, 12), ("roboergosum", 3000.0, 25)],
)
@pytest.mark.parametrize("name", STATIONARY)
def test_a_long_run_answers_as_a_fresh_instance_at_every_visited_state(
    name: str, scenario: str, duration: float, sampled: int
) -> None:
    spy = Spy(make_human(name))  # the random robot leads the human through varied states
    run(make_robot("random"), spy, RunConfig(scenario=scenario, duration=duration, seed=1))
    assert len(spy.seen) > 100
    # one fresh instance asked every visited state in the reverse order ...
    world = World(scenario)
    other: Any = make_human(name)
    other.reset(world, Agent.HUMAN, np.random.default_rng(0))
    for state, ra, dist in reversed(spy.seen):
        assert list(other.distribution(world, state, ra)) == list(dist), (state, ra)
    # ... and, for a sample, a fresh instance per state (nothing asked before)
    for state, ra, dist in spy.seen[:: max(1, len(spy.seen) // sampled)]:
        assert fresh_answer(name, scenario, state, ra) == list(dist), (state, ra)


@pytest.mark.parametrize(
    ("scenario", "humans", "duration"),
    [
        ("paper2015", STATIONARY, 3600.0),
        pytest.param(
            "roboergosum", tuple(h for h in STATIONARY if h != "noisy"), 3600.0, marks=pytest.mark.slow
        ),  # noisy's roboergosum model takes minutes (see the oracle's docstring)
    ],
)
def test_the_oracle_robot_never_leaves_its_model_against_its_own_human(
    scenario: str, humans: tuple[str, ...], duration: float
) -> None:
    for name in humans:
        result = oracle_rate(scenario, name)
        for seed in (0, 1):
            robot = OracleRobot(result)
            out = run(robot, make_human(name), RunConfig(scenario=scenario, duration=duration, seed=seed))
            assert robot.off_model == 0, (name, seed)
            assert (out.log["expert"] == "oracle").all()


def test_off_its_model_the_oracle_robot_keeps_solving_tasks() -> None:
    # Solved against the cooperative human, played with the lazy one (never takes, idles 30%):
    # states the model never reaches come up, and a robot that waited there would stop.
    robot = OracleRobot(oracle_rate("paper2015", "cooperative"))
    out = run(robot, make_human("lazy"), RunConfig(scenario="paper2015", duration=1500.0, seed=0))
    log = out.log
    off = log.index[log["expert"] != "oracle"]
    assert robot.off_model == len(off) > 0
    first = int(off[0])
    assert log["tasks_solved"].iloc[-1] >= log["tasks_solved"].iloc[first] + 10


def test_off_its_model_a_wait_that_changes_nothing_is_replaced_by_a_move() -> None:
    world = World("paper2015")
    robot = OracleRobot(oracle_rate("paper2015", "cooperative"))
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    wait = world.n_actions(Agent.ROBOT) - 1
    # a planner whose plan always waits for the human (a partner model that differs)
    robot._planner = SimpleNamespace(world=world, intent=lambda *a, **k: Intent(True, wait, -1, 10.0, 10.0))
    # a state the lazy human leads to and the cooperative one never does
    state = next(
        s
        for s in oracle_rate("paper2015", "lazy").policy
        if robot.result.action_at(world, s) is None and not world.is_clean(s)  # type: ignore[union-attr]
    )
    turn: Any = SimpleNamespace(world=world, state=state)
    k = 12  # the progress guard's K (agents/progress.py): K waits that change nothing, then a move
    moves = [robot.act(turn) for _ in range(k + 1)]
    assert moves[:k] == [wait] * k  # the planner's move while the guard counts
    assert moves[k] != wait and moves[k] in world.feasible_indices(state, Agent.ROBOT)
    assert robot.off_model == k + 1
