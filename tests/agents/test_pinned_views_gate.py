"""The single-agent views' spaces, seeding, infos and rewards, pinned for the mutation gate.

Expected values from ``agents/views.py``'s docstring and the wrapped AEC env as the
reference: the views render as the AEC env does (its ``metadata``); the ``flat``
observation is a ``Box(0, 1)`` of facts plus mask; the ``observation`` option is compared
by value (a string read from a settings file works as the literal does); ``reset(seed=s)``
seeds the table and the partner from two draws over ``[0, 2**63 - 1)`` of the view's own
generator, which gymnasium seeds from ``s`` (the reference is that rule, written out); a
reset's info is the fresh env's clock and tasks (0); the partner's action name is the
world's name of its index (index 0 included); the human's ``work`` of a step is the rise of
its cumulative ``effort``, so the steps' works add up to the effort; a human step that ends
the episode has no robot action (-1, no name) and no task reward; episodes are truncated
after 500 cycles by default.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from gymnasium import spaces
from gymnasium.utils import seeding

from hg_marl.agents.views import HumanView, RobotView
from hg_marl.core import Agent, World
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.policy import Turn

N_FACTS = 24  # paper2015's boolean facts
N_ROBOT, N_HUMAN = 18, 31  # paper2015's action counts


class _Fixed:
    """A partner that always sends one action index (the last one: wait) and records its first draw."""

    def __init__(self, index: int | None = None) -> None:
        self.index = index
        self.first_draws: list[float] = []

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.first_draws.append(float(rng.random()))
        self.action = world.n_actions(agent) - 1 if self.index is None else self.index

    def act(self, turn: Turn) -> int:
        return self.action


def _runtime(text: str) -> str:
    """``text`` as a new string object, as a value read from a settings file is (not the interned literal)."""
    value: str = json.loads(json.dumps({"v": text}))["v"]
    copy = "".join(list(value))
    assert copy == text
    return copy


def test_the_views_render_as_the_aec_env_does() -> None:
    for view in (RobotView, HumanView):
        assert view.metadata["render_fps"] == raw_env.metadata["render_fps"]
        assert view.metadata["render_modes"] == raw_env.metadata["render_modes"]


def test_the_flat_observation_is_a_zero_one_box_of_facts_and_mask() -> None:
    view = RobotView(human=_Fixed(), observation="flat")
    assert view.observation_space == spaces.Box(0, 1, (N_FACTS + N_ROBOT,), np.int8)


@pytest.mark.parametrize("mode", ["facts", "flat", "dict"])
def test_an_observation_mode_read_at_run_time_works_as_the_literal(mode: str) -> None:
    literal = RobotView(human=_Fixed(), observation=mode)
    read = RobotView(human=_Fixed(), observation=_runtime(mode))
    assert read.observation_space == literal.observation_space
    first, _ = literal.reset(seed=2)
    second, _ = read.reset(seed=2)
    if mode == "dict":
        assert set(second) == set(first)
        for key in first:
            np.testing.assert_array_equal(second[key], first[key])
    else:
        np.testing.assert_array_equal(second, first)
        assert read.observation_space.contains(second)


@pytest.mark.parametrize("seed", [0, 5])
def test_a_reset_seed_seeds_the_table_and_the_partner_as_documented(seed: int) -> None:
    partner = _Fixed()
    view = RobotView(human=partner)
    view.reset(seed=seed)
    generator, _ = seeding.np_random(seed)
    env_seed, partner_seed = (int(x) for x in generator.integers(0, 2**63 - 1, size=2))
    reference = raw_env()
    reference.reset(seed=env_seed)
    assert view.env.world_state == reference.world_state
    assert partner.first_draws == [float(np.random.default_rng(partner_seed).random())]


def test_a_reset_info_is_the_fresh_envs_clock_and_tasks() -> None:
    robot_view = RobotView(human=_Fixed())
    _, info = robot_view.reset(seed=0)
    assert (info["clock"], info["tasks_solved"]) == (robot_view.env.clock, robot_view.env.tasks_solved) == (0.0, 0)
    human_view = HumanView(robot=_Fixed())
    _, info = human_view.reset(seed=0)
    assert info["tasks_solved"] == human_view.env.tasks_solved == 0


def test_reset_takes_its_seed_by_keyword_only_as_gymnasium_does() -> None:
    for view in (RobotView(human=_Fixed()), HumanView(robot=_Fixed())):
        with pytest.raises(TypeError):
            view.reset(0)


def test_the_human_property_is_the_partner_playing() -> None:
    partner = _Fixed()
    view = RobotView(human=partner)
    view.reset(seed=0)
    assert view.human is partner


def test_a_partner_action_zero_is_named() -> None:
    """The human always sends index 0 (``pick(tape1)``, feasible or not): the info names it."""
    view = RobotView(human=_Fixed(index=0))
    view.reset(seed=0)
    info = view.step(N_ROBOT - 1)[4]
    assert info["human_action"] == 0
    assert info["human_action_name"] == World("paper2015").action_names[Agent.HUMAN][0] == "pick(tape1)"


def test_the_human_steps_works_add_up_to_its_effort_and_weigh_on_the_reward() -> None:
    """The human picks and places (2 s each on paper2015) until the 3-cycle limit; the robot waits."""
    view = HumanView(robot=_Fixed(), max_cycles=3, effort_weight=0.5)
    view.reset(seed=0)
    works, rewards = [], []
    info: dict = {}
    truncated = False
    while not truncated:
        action = int(np.flatnonzero(view.action_masks())[0])
        _, reward, done, truncated, info = view.step(action)
        assert not done
        works.append(info["work"])
        rewards.append(reward)
    assert sum(works) == pytest.approx(info["effort"]) and all(w > 0 for w in works)
    assert rewards == pytest.approx([-0.5 * w for w in works])  # no task solved: only the effort's cost
    # the last step ended the episode: no robot move followed, and no task reward
    assert (info["robot_action"], info["robot_action_name"], info["task_reward"]) == (-1, "", 0.0)


@pytest.mark.parametrize("view_class", [RobotView, HumanView])
def test_an_episode_is_truncated_after_500_cycles_by_default(view_class: type) -> None:
    view = view_class("paper2015", _Fixed())
    view.reset(seed=0)
    wait = view.world.n_actions(view.seat) - 1
    flags = [view.step(wait)[3] for _ in range(500)]
    assert flags == [False] * 499 + [True]
