"""Behaviour of the AEC environment: turns, clock, rewards, modes, infos, bad input."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import hg_marl
from hg_marl import AgentMismatchError, InvalidActionError, ScenarioError
from hg_marl.core import Action, Agent, Kind, State

# paper2015 codes: spots 0-5 (mat_shared 3, human mats 4-5), bin 6; robot locations bin_side 0,
# table_left 1, table_right 2, human_side 3.


def names(env, agent: str) -> dict[str, int]:
    return {n: i for i, n in enumerate(env.unwrapped.action_names(agent))}


def play(env, script: list[tuple[str, str]]) -> None:
    """Step the env with (robot action name, human action name) pairs."""
    r, h = names(env, "robot"), names(env, "human")
    for robot, human in script:
        assert env.agent_selection == "robot"
        env.step(r[robot])
        if env.agents and not env.terminations["human"]:
            env.step(h[human])


def nearly_done() -> State:
    # tape1, tape2 in the bin, tape3 in the robot's hand at bin_side
    return State((6, 6, 7), 0)


def test_episodic_success_terminates_at_cycle_end() -> None:
    env = hg_marl.env()
    env.reset(seed=0, options={"state": nearly_done()})
    play(env, [("throw(tape3)", "wait")])
    assert not any(env.terminations.values())
    env.step(names(env, "robot")["wait"])
    assert env.rewards == {"robot": 1.0, "human": 1.0}
    assert not env.terminations["human"], "the human still finishes the cycle"
    env.step(names(env, "human")["wait"])
    assert all(env.terminations.values())
    _, reward, term, _, info = env.last()
    assert reward == 1.0 and term and info["tasks_solved"] == 1


def test_continuing_redraws_table() -> None:
    env = hg_marl.env(continuing=True)
    env.reset(seed=0, options={"state": nearly_done()})
    play(env, [("throw(tape3)", "wait"), ("wait", "wait")])
    assert not any(env.terminations.values())
    assert env.unwrapped.tasks_solved == 1
    assert not env.unwrapped.world.is_clean(env.unwrapped.world_state), "a new layout was drawn"
    assert env.infos["robot"]["tasks_solved"] == 1


def test_clock_is_max_of_parallel_actions_plus_charged_time() -> None:
    env = hg_marl.env()
    env.reset(seed=0)
    d = env.unwrapped.world.durations
    play(env, [("goto(human)", "wait")])
    assert env.unwrapped.clock == pytest.approx(max(d.goto, d.wait))
    env.unwrapped.charge_time(0.5)
    play(env, [("pick(tape1)", "wait")])  # infeasible at human_side
    assert env.infos["robot"]["failed"] is True
    assert env.unwrapped.clock == pytest.approx(max(d.goto, d.wait) + d.wait + 0.5)
    assert env.infos["human"]["idle"] > 0 and env.infos["robot"]["effort"] == pytest.approx(d.goto)


def test_infeasible_action_has_no_effect_and_is_reported() -> None:
    env = hg_marl.env()
    env.reset(seed=0)
    before = env.unwrapped.world_state
    env.step(names(env, "robot")["throw(tape1)"])
    assert env.unwrapped.world_state == before
    assert env.infos["robot"]["failed"] is True and env.infos["robot"]["events"].startswith("robot failed")


def test_handover_through_env() -> None:
    env = hg_marl.env()
    world = env.unwrapped.world
    tape3_human = State((0, 2, world.hand[Agent.HUMAN]), 3)
    env.reset(seed=0, options={"state": tape3_human})
    play(env, [("wait", "give(tape3)"), ("take(tape3)", "wait")])
    assert env.unwrapped.world_state.where[2] == world.hand[Agent.ROBOT]


def test_time_budget_truncates() -> None:
    env = hg_marl.env(max_cycles=None, time_budget=10.0, continuing=True)
    env.reset(seed=0)
    for agent in env.agent_iter():
        _, _, term, trunc, _ = env.last()
        env.step(None if term or trunc else names(env, agent)["wait"])
    assert env.unwrapped.clock >= 10.0 and env.unwrapped.cycles == 10


@pytest.mark.parametrize("action", [18, -1, 10**9, 2.5, "wait", None, np.int64(99)])
def test_out_of_range_action_raises_clearly(action) -> None:
    env = hg_marl.env()
    env.reset(seed=0)
    with pytest.raises(InvalidActionError, match="robot"):
        env.step(action)


def test_numpy_integer_actions_accepted() -> None:
    env = hg_marl.env()
    env.reset(seed=0)
    env.step(np.int64(17))
    env.step(np.array(30))
    assert env.unwrapped.cycles == 1


def test_parallel_wrong_agent_raises_clearly() -> None:
    env = hg_marl.parallel_env()
    env.reset(seed=0)
    with pytest.raises(AgentMismatchError, match=r"missing \['human'\]"):
        env.step({"robot": 17})
    with pytest.raises(AgentMismatchError, match=r"unexpected \['dog'\]"):
        env.step({"robot": 17, "human": 30, "dog": 0})


def test_unknown_scenario_and_bad_arguments() -> None:
    with pytest.raises(ScenarioError, match="unknown scenario"):
        hg_marl.env(scenario="kitchen")
    with pytest.raises(ValueError, match="render_mode"):
        hg_marl.env(render_mode="human")
    with pytest.raises(ValueError, match="max_cycles"):
        hg_marl.env(max_cycles=0)


def test_step_before_reset_is_refused() -> None:
    env = hg_marl.env()
    with pytest.raises(Exception, match="reset"):
        env.step(0)


def test_observation_matches_world() -> None:
    env = hg_marl.env()
    env.reset(seed=3)
    obs = env.observe("human")
    world, state = env.unwrapped.world, env.unwrapped.world_state
    assert np.array_equal(obs["action_mask"], world.mask(state, Agent.HUMAN))
    assert obs["observation"].shape == (len(env.unwrapped.fact_names),)
    assert env.observation_space("robot").contains(env.observe("robot"))
    place = world.index(Agent.HUMAN, Action(Kind.PLACE, 0, 3))
    assert env.unwrapped.action_names("human")[place] == "place(tape1,mat_shared)"


def test_renders() -> None:
    text = hg_marl.env(render_mode="ansi")
    text.reset(seed=0)
    assert "trashbin" in text.render()
    image = hg_marl.env(render_mode="rgb_array", scenario="roboergosum")
    image.reset(seed=0)
    frame = image.render()
    assert frame.dtype == np.uint8 and frame.ndim == 3 and frame.shape[2] == 3
    assert len(np.unique(frame.reshape(-1, 3), axis=0)) > 5, "the picture is not blank"


def test_import_does_not_load_torch_or_pygame() -> None:
    code = (
        "import sys, hg_marl; hg_marl.env().reset(seed=0); "
        "print('torch' in sys.modules, 'pygame' in sys.modules, 'matplotlib' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["False", "False", "False"]
