"""The AEC environment's promises (hg_marl/envs/table_cleaning.py), pinned for the mutation gate.

Each expected value is read from the module's spec sheet and worked by hand: a seeded reset
draws its table from that seed and unseeded resets draw on; the spaces are the sheet's (0/1
int8 facts and masks, 18 robot actions on paper2015); an episode is truncated after 500
cycles by default and may last one cycle (``max_cycles`` must be positive), and a task
completed in the last allowed cycle terminates it instead; the observation holds the ``F``
facts plus ``H`` history entries (both agents' action kinds and failures for each of the
``k`` cycles, ``2 k (N_KINDS + 1)``, and the partner's cycles since progress, one-hot over
``DEFAULT_CAP + 1``); an episode starts with every info counter and reward at zero and no
action; a closed cycle updates both agents' infos with its length, the effort and the idle
time (the durations of paper2015, summed by hand); an action array of one element is its
index, any other is no index; an unknown agent is refused with the agents named; the
render modes are compared by value, not identity; the picture's caption shows each agent's
last action.
"""

from __future__ import annotations

import inspect
from typing import Any

import numpy as np
import pytest
from gymnasium import spaces

from hg_marl.agents.views import RobotView
from hg_marl.core import Kind, State
from hg_marl.envs import table_cleaning
from hg_marl.envs.history import DEFAULT_CAP
from hg_marl.envs.render import HUMAN_MESSAGE
from hg_marl.envs.table_cleaning import InvalidActionError, raw_env
from hg_marl.training.video import write_video


def _index(env: raw_env, agent: str, name: str) -> int:
    return env.action_names(agent).index(name)


def test_the_spaces_are_the_spec_sheets() -> None:
    """paper2015: 24 facts; 18 robot actions (the spec sheet) and 31 human ones (3 objects x 4
    kinds, 3 x 6 places, wait); facts and masks are 0/1 entries of type int8."""
    env = raw_env()
    for agent, n in (("robot", 18), ("human", 31)):
        assert env.action_space(agent) == spaces.Discrete(n)
        assert env.observation_space(agent) == spaces.Dict(
            {"observation": spaces.Box(0, 1, (24,), np.int8), "action_mask": spaces.Box(0, 1, (n,), np.int8)}
        )


def test_frames_are_shown_at_the_rate_videos_are_written_and_views_declare() -> None:
    fps = inspect.signature(write_video).parameters["fps"].default
    assert raw_env.metadata["render_fps"] == fps == RobotView.metadata["render_fps"] == 2


def test_a_seeded_reset_draws_the_table_from_that_seed_and_later_resets_go_on_from_it() -> None:
    """``reset(seed)`` starts the environment's generator anew; a reset without a seed draws on."""
    env = raw_env()
    for seed in range(8):
        env.reset(seed=seed)
        assert env.world_state == env.world.initial_state(np.random.default_rng(seed))
    env.reset(seed=5)
    rng = np.random.default_rng(5)
    assert env.world_state == env.world.initial_state(rng)
    drawn = []
    for _ in range(8):
        env.reset()
        drawn.append(env.world_state)
    assert drawn == [env.world.initial_state(rng) for _ in range(8)]


def test_an_episode_is_truncated_after_500_cycles_by_default() -> None:
    env = raw_env()
    env.reset(seed=0)
    robot_wait, human_wait = _index(env, "robot", "wait"), _index(env, "human", "wait")
    for _ in range(600):  # bounded: a run that is never truncated fails here instead of hanging
        env.step(robot_wait)
        env.step(human_wait)
        if any(env.truncations.values()):
            break
    assert env.truncations == {"robot": True, "human": True} and env.cycles == 500


def test_a_task_completed_in_the_last_allowed_cycle_terminates_the_episode_instead_of_truncating_it() -> None:
    env = raw_env(max_cycles=1)
    env.reset(seed=0, options={"state": State((6, 6, 6), 0)})  # paper2015: every tape in the bin (spot 6)
    env.step(_index(env, "robot", "wait"))  # the robot waits on a clean table: the task is completed
    env.step(_index(env, "human", "wait"))  # the first and last cycle closes
    assert env.terminations == {"robot": True, "human": True}
    assert env.truncations == {"robot": False, "human": False}


def test_an_episode_of_one_cycle_is_allowed_and_truncated_after_it() -> None:
    env = raw_env(max_cycles=1)
    env.reset(seed=0)
    env.step(_index(env, "robot", "wait"))
    assert not any(env.truncations.values())
    env.step(_index(env, "human", "wait"))
    assert env.truncations == {"robot": True, "human": True}
    assert not any(env.terminations.values())


@pytest.mark.parametrize("k", [0, 1, 3])
def test_the_observation_space_holds_the_facts_and_k_cycles_of_history(k: int) -> None:
    env = raw_env(history=k)
    env.reset(seed=0)
    history = 0 if k == 0 else 2 * k * (len(Kind) + 1) + DEFAULT_CAP + 1
    for agent in ("robot", "human"):
        space = env.observation_space(agent)
        assert isinstance(space, spaces.Dict)
        assert space["observation"].shape == (env.world.n_facts + history,)
        assert space.contains(env.observe(agent))


def test_an_unknown_agent_is_refused_with_the_agents_named() -> None:
    env = raw_env()
    env.reset(seed=0)
    for ask in (env.action_names, env.turn):
        with pytest.raises(KeyError, match=r"unknown agent 'dog'; agents are \['robot', 'human'\]"):
            ask("dog")


ZERO_INFO = {
    "clock": 0.0,
    "cycle": 0,
    "tasks_solved": 0,
    "action": "",
    "failed": False,
    "events": "",
    "effort": 0.0,
    "idle": 0.0,
}
"""An episode's infos before any move (the spec sheet: ``action`` is "" before the first move)."""


def test_every_episode_starts_with_its_infos_at_zero() -> None:
    env = raw_env()
    env.reset(seed=0)
    assert env.infos == {"robot": ZERO_INFO, "human": ZERO_INFO}
    assert env.rewards == {"robot": 0.0, "human": 0.0}
    assert env.turn("robot").clock == 0.0 and env.clock == 0.0
    for _ in range(3):  # a few cycles of moves, then a new episode on the same object
        env.step(_index(env, "robot", "goto(human)"))
        env.step(_index(env, "human", "wait"))
    assert env.clock > 0.0 and env.infos["robot"]["effort"] > 0.0
    env.reset(seed=1)
    assert env.infos == {"robot": ZERO_INFO, "human": ZERO_INFO}
    assert env.rewards == {"robot": 0.0, "human": 0.0}
    assert env.turn("human").clock == 0.0 and env.clock == 0.0


def test_a_closed_cycle_updates_both_agents_infos() -> None:
    """paper2015's durations: goto 3 s, wait 1 s. The cycle lasts the longer, 3 s; the robot moved
    all of it (3 s of effort, no idle time), the human waited all of it (3 s idle, no effort)."""
    env = raw_env()
    env.reset(seed=0)
    env.step(_index(env, "robot", "goto(human)"))
    env.step(_index(env, "human", "wait"))
    robot, human = env.infos["robot"], env.infos["human"]
    for info in (robot, human):
        assert (info["clock"], info["cycle"], info["tasks_solved"]) == (3.0, 1, 0)
    assert (robot["effort"], robot["idle"]) == (3.0, 0.0)
    assert (human["effort"], human["idle"]) == (0.0, 3.0)


def test_a_one_element_action_array_is_read_as_its_index() -> None:
    env = raw_env()
    env.reset(seed=0)
    env.step(np.array([_index(env, "robot", "goto(human)")]))  # as vectorised libraries hand it over
    env.step(np.array([[_index(env, "human", "wait")]]))
    assert (env.infos["robot"]["action"], env.infos["human"]["action"]) == ("goto(human)", "wait")
    assert env.cycles == 1


def test_an_action_array_of_other_than_one_element_is_refused_as_no_index() -> None:
    env = raw_env()
    env.reset(seed=0)
    with pytest.raises(InvalidActionError, match="is not an integer"):
        env.step(np.array([], dtype=np.int64))
    with pytest.raises(InvalidActionError, match="is not an integer"):
        env.step(np.array([1, 2]))


def test_a_window_asked_for_at_run_time_gets_the_pointer_to_videos() -> None:
    mode = "".join(["hu", "man"])  # as read from a command line or a file: not the literal's object
    with pytest.raises(ValueError) as refused:
        raw_env(render_mode=mode)
    assert str(refused.value) == HUMAN_MESSAGE


def test_a_render_mode_read_at_run_time_renders_text() -> None:
    mode = "".join(["an", "si"])  # as read from a command line or a file: not the literal's object
    env = raw_env(render_mode=mode)
    env.reset(seed=0)
    assert isinstance(env.render(), str)


def test_the_picture_is_captioned_with_each_agents_last_action(monkeypatch: pytest.MonkeyPatch) -> None:
    captions: list[tuple[Any, ...]] = []

    def caption(world: Any, clock: float, tasks: int, last: tuple[int, int]) -> str:
        captions.append((clock, tasks, last))
        return ""

    monkeypatch.setattr(table_cleaning, "caption_of", caption)
    env = raw_env(render_mode="rgb_array")
    env.reset(seed=0)
    env.render()
    goto, wait = _index(env, "robot", "goto(human)"), _index(env, "human", "wait")
    env.step(goto)
    env.step(wait)
    env.render()
    assert captions == [(0.0, 0, (-1, -1)), (env.clock, 0, (goto, wait))]
